"""RK4 Cummins integrator: order, analytic free decay, memory consistency, hemisphere decay, conv vs SS."""

import numpy as np
import pytest

from boatland.hydro.bemio import read_bemio
from boatland.irf.impulse import IRFSettings
from boatland.vessel.database import rigid_body_mass_matrix
from boatland.trial.motion import MotionArrays, compile_motion
from boatland.vessel.radiation import radiation_memory
from boatland.validation.timedomain import CTV_X0, HEMISPHERE_X0, free_decays, rms_differences

M, K_SPRING, B_LIN = 2.0e5, 8.0e5, 4.0e4     # heave oscillator: ω0 = 2 rad/s, ζ = 0.05


def oscillator():
    Mt = np.eye(6) * M
    C = np.zeros((6, 6)); C[2, 2] = K_SPRING
    return MotionArrays.without_memory(Mt, C)


def exact_decay(t, x0):
    w0 = np.sqrt(K_SPRING / M)
    z = B_LIN / (2 * np.sqrt(K_SPRING * M))
    wd = w0 * np.sqrt(1 - z * z)
    return x0 * np.exp(-z * w0 * t) * (np.cos(wd * t) + z * w0 / wd * np.sin(wd * t))


def decay_error(dt, T=10.0):
    n = int(round(T / dt))
    Bv = np.zeros(6); Bv[2] = B_LIN
    r = oscillator().run(dt, n, x0=[0, 0, 1.0, 0, 0, 0], Bv=Bv)
    t, x = r["t"], r["x"]
    assert r["status"] == 0
    return np.max(np.abs(x[:, 2] - exact_decay(t, 1.0)))


def test_rk4_is_fourth_order():
    e1, e2, e3 = decay_error(0.1), decay_error(0.05), decay_error(0.025)
    assert np.log2(e1 / e2) == pytest.approx(4.0, abs=0.15)
    assert np.log2(e2 / e3) == pytest.approx(4.0, abs=0.15)


def test_free_decay_without_memory_is_analytic():
    assert decay_error(0.01) < 1e-8


def test_runaway_is_stopped_and_reported():
    arr = oscillator()
    C = arr.C.copy(); C[2, 2] = -K_SPRING  # negative restoring: exponential growth
    bad = MotionArrays.without_memory(np.eye(6) * M, C)
    r = bad.run(0.05, 4000, x0=[0, 0, 1.0, 0, 0, 0], limit_trans=50.0)
    t, x = r["t"], r["x"]
    assert r["status"] == 2 and "runaway" in r["message"] and abs(x[-1, 2]) > 50 and t[-1] < 200


@pytest.fixture(scope="module")
def hemisphere(refdata):
    """HydroChrono's WAMIT hemisphere, mass ρV, floating with its centre on the surface
    (tests/data/refdata/README.md)."""
    db = read_bemio(refdata / "bemio_sphere" / "sphere.h5")
    m = db.rho * db.disp_vol
    r = 5.0
    inertia = 2 / 5 * m * r ** 2 * np.ones(3)  # not used in heave
    db = db.replace(M=rigid_body_mass_matrix(m, db.cog, inertia, np.zeros(3)))
    return db, radiation_memory(db, IRFSettings(t_max=30.0, dt=0.01))


def zero_up_crossings(t, z):
    k = np.nonzero((z[:-1] < 0) & (z[1:] >= 0))[0]
    return t[k] - z[k] * (t[k + 1] - t[k]) / (z[k + 1] - z[k])


@pytest.mark.slow
def test_hemisphere_decay_period_is_the_database_natural_period(hemisphere):
    """Released from +1 m heave: the zero-crossing period equals T3 from M, A(ω), C (4.365 s) within 1 %.

    The undamped estimate uses A33 at the natural frequency; the decay feels the whole A(ω), B(ω)
    (ζ ≈ 0.1 would lengthen a constant-coefficient period by 0.5 %); measured: 4.349 s (−0.4 %).
    """
    db, mem = hemisphere
    arr = compile_motion(db, mem, 0.05)
    r = arr.run(0.05, 1200, x0=[0, 0, 1.0, 0, 0, 0])
    t, x = r["t"], r["x"]
    assert r["status"] == 0
    periods = np.diff(zero_up_crossings(t, x[:, 2]))
    assert periods.size >= 3
    assert np.mean(periods[:3]) == pytest.approx(db.natural_periods()["heave"], rel=0.01)


def test_convolution_and_state_space_agree(hemisphere):
    """Free decay from surge, heave and pitch offsets, 40 s (boatland.validation.timedomain: the code of
    `boatland validate`'s state-space-vs-convolution case)."""
    db, mem = hemisphere
    runs = free_decays(db, mem, HEMISPHERE_X0, 0.05, 800)
    for d, rms in rms_differences(runs, (0, 2, 4)).items():
        assert rms < 0.01, (d, rms)


@pytest.fixture(scope="module")
def ctv24():
    from boatland.hydro.builtin import load_builtin

    db = load_builtin("ctv24")
    return db, radiation_memory(db)


def test_convolution_and_state_space_agree_on_the_ctv(ctv24):
    """Free decay of the catamaran from heave, roll, pitch and sway/surge offsets, 60 s: the state-space
    run (default fit) stays within 1 % RMS of the convolution (60 s memory) in every excited DOF.

    Measured: surge 0.08 %, sway 0.35 %, heave 0.74 %, roll 0.16 %, pitch 0.46 %. (With the old fit
    target R² = 0.999 / order ≤ 12: heave 3.7 %, pitch 5.0 %.)
    """
    db, mem = ctv24
    runs = free_decays(db, mem, CTV_X0, 0.05, 1200, memory_length=60.0)
    assert all(r["status"] == 0 for r in runs.values())
    for d, rms in rms_differences(runs, range(5)).items():  # yaw: no restoring and nothing couples into it from
        assert rms < 0.01, (d, rms)                        # rest — it stays at 0.03 rad


def test_state_space_has_no_step_limit_from_fast_poles(ctv24):
    """The memory is discretised exactly (first-order hold): at Δt = 3/|p|max — where RK4 on the fitted
    states (the method before) was unstable, |R(pΔt)| > 1 — the decay stays within 2 % RMS of the same
    state space at Δt/10 in every excited DOF (measured: surge 0.15 %, sway 0.28 %, heave 1.46 %, roll
    0.77 %, pitch 1.17 % — the body's RK4 error at 0.125 s, the convolution's being as large in heave and
    2.8 % in sway)."""
    db, mem = ctv24
    fastest = max(np.abs(np.linalg.eigvals(f.A)).max() for f in mem.state_space.pairs.values() if f.order)
    dt = 3.0 / fastest
    z = -fastest * dt
    assert abs(1 + z + z ** 2 / 2 + z ** 3 / 6 + z ** 4 / 24) > 1   # outside RK4's region
    coarse = compile_motion(db, mem, dt, method="state_space").run(dt, int(round(60 / dt)), x0=list(CTV_X0))
    fine = compile_motion(db, mem, dt / 10, method="state_space").run(dt / 10, int(round(600 / dt)),
                                                                     x0=list(CTV_X0))
    assert coarse["status"] == 0 and fine["status"] == 0
    for d in range(5):
        ref = np.interp(coarse["t"], fine["t"], fine["x"][:, d])
        rms = np.sqrt(np.mean((coarse["x"][:, d] - ref) ** 2)) / np.sqrt(np.mean(ref ** 2))
        assert rms < 0.02, (d, rms)


def test_memory_is_stage_consistent(hemisphere):
    """With the memory evaluated consistently at the stages, halving dt changes the decay by O(dt²)
    of the trapezoid, not O(dt): the two refinements shrink the difference by ≈ 4."""
    db, mem = hemisphere
    z = {}
    for dt in (0.1, 0.05, 0.025):
        arr = compile_motion(db, mem, dt)
        r = arr.run(dt, int(round(20 / dt)), x0=[0, 0, 1.0, 0, 0, 0])
        t, x = r["t"], r["x"]
        z[dt] = np.interp(np.arange(0, 20, 0.1), t, x[:, 2])
    d1 = np.max(np.abs(z[0.1] - z[0.05]))
    d2 = np.max(np.abs(z[0.05] - z[0.025]))
    assert d1 / d2 > 3.5
