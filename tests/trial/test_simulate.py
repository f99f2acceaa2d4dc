"""One landing trial end to end on the Wigley CTV (scenarios/ctv24_landing.toml)."""

import numpy as np
import pytest

from boatland.trial.simulate import BlowUpError, simulate
from boatland.landing.setup import Setup


def test_calm_water_holds_the_thrust_symmetrically(landing):
    """No waves: after the ramp the two tubes share the 80 kN push, both stuck, no sway/roll/yaw."""
    sc, db = landing
    r = simulate(sc.replace({"sea": None, "simulation.duration": 120.0}), db)
    assert (r.mode[-200:] == 1).all()
    assert r.fn[-1] == pytest.approx([40e3, 40e3], rel=1e-3)
    assert np.max(np.abs(r.x[:, [1, 3, 5]])) < 1e-9


@pytest.mark.parametrize("shear", ["compliant", "rigid"])
def test_stuck_fender_does_not_drift_over_1200_s_of_waves(landing, shear):
    """Hs 0.2 m head seas, 80 kN: stuck throughout. Rigid stick: the fender points move < 1e-6 m
    (measured 5e-9 m). Compliant rubber: its anchors on the tubes never slide (zero slide and zero
    friction work in every step); the fender point only swings elastically about them, within the
    largest shear force / k_t (measured 3.9 mm; 2× allowed for the damper's share)."""
    sc, db = landing
    changes = {"sea.Hs": 0.2, "simulation.duration": 1220.0}
    if shear == "rigid":
        changes["fender.shear_stiffness"] = "rigid"
    r = simulate(sc.replace(changes), db)
    k = int(np.searchsorted(r.t, sc.thrust.ramp))
    assert (r.mode[k:] == 1).all() and not r.slip_events()
    assert not np.any(r.slide[k + 1:]) and not np.any(r.work[k + 1:])
    move = np.abs(r.tpos[k:] - r.tpos[k])
    if shear == "rigid":
        assert move.max() < 1e-6
    else:
        elastic = np.hypot(r.ft[k:, :, 0], r.ft[k:, :, 1]).max() / sc.fender.shear_stiffness
        assert 0 < move.max() <= 2 * elastic                          # elastic swing about the anchor


def test_head_seas_stay_symmetric_and_slip_is_reported(landing):
    """The default trial (Hs 1.5 m): both tubes slip together (ties released together), sway/roll/yaw
    stay at round-off, every slip event carries needed > available."""
    sc, db = landing
    r = simulate(sc.replace({"simulation.duration": 120.0}), db)
    assert np.max(np.abs(r.x[:, [1, 3, 5]])) < 1e-8
    slips = r.slip_events()
    assert slips and all(e.needed > e.available for e in slips)
    s = r.summary()
    assert s["time_to_first_slip"] == slips[0].t and s["max_slip_distance"] > 0


def test_blow_up_is_stopped_and_explained(landing):
    """A fender far too stiff for dt: the run stops at the blow-up with time, state and likely cause."""
    sc, db = landing
    bad = sc.replace({"fender.stiffness": 5e9, "simulation.duration": 30.0, "simulation.dt": 0.05,
                      "sea": None})
    with pytest.raises(BlowUpError, match=r"integration stopped at t = .* likely cause: dt = 0.05 s is large"):
        simulate(bad, db)


def test_progress_is_reported_up_to_the_last_step(landing):
    """The kernel runs in a worker thread; the callback sees a non-decreasing step count ending at n."""
    sc, db = landing
    sc = sc.replace({"simulation.duration": 60.0})
    seen = []
    r = simulate(sc, db, progress=lambda done, total: seen.append((done, total)))
    n = Setup.of(sc, db).n_steps
    assert seen and all(total == n for _, total in seen)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen) and seen[-1][0] == n
    assert r.completed and len(r.t) == n + 1


def test_landed_yaw_decays_with_the_default_memory(landing):
    """Calm water, landed, the vessel started 0.5° off in yaw: every mode decays with the default radiation
    memory (the state-space fit). The slow landed sway–yaw mode (T ≈ 37 s) is the test: the database's own
    damping there is ~2e-7 s⁻¹ (modal), so any error of the memory decides it. Measured: the peak-to-peak
    of every DOF falls from each 100 s to the next; |yaw| 1.37° in the first 100 s, 1.01° in the last."""
    sc, db = landing
    r = simulate(sc.replace({"sea": None, "simulation.duration": 900.0, "initial.rotation_deg": [0.0, 0.0, 0.5],
                             "thrust.ramp": 0.0}), db)
    w = int(round(100.0 / (r.t[1] - r.t[0])))
    for d in range(6):
        ptp = [np.ptp(r.x[k:k + w, d]) for k in range(0, len(r.t) - w, w)]
        assert np.all(np.diff(ptp) < 0), (d, ptp)
    yaw = [np.abs(r.x[k:k + w, 5]).max() for k in range(0, len(r.t) - w, w)]
    assert yaw[-1] < 0.8 * yaw[0]


def test_a_truncated_convolution_that_makes_the_landed_yaw_grow_is_refused(landing):
    """The convolution over 40 s without a taper rebuilds a negative damping at the landed sway–yaw mode
    larger than the fender's own damping there (ζ −0.59 % and −0.26 % in all: the mode grows): the run is
    refused before it starts, naming radiation.method and what to use."""
    from boatland.errors import BoatlandInputError

    sc, db = landing
    with pytest.raises(BoatlandInputError, match=r"radiation\.method: .*sway mode \(T = 3\d\.\d s\).*state_space"):
        simulate(sc.replace({"radiation.method": "convolution", "radiation.taper": "none", "simulation.duration": 30.0}),
                 db)


def test_ramps_are_the_whole_series_formulas_bit_for_bit(landing):
    """thrust_series and wave_ramp evaluate the half-cosine only where it applies: the same bits as the
    formulas over the whole series."""
    from boatland.trial.simulate import thrust_series, wave_ramp, wave_start

    sc, db = landing
    dt, n = 0.05, 4000
    t = np.arange(2 * n + 1) * dt / 2
    for changes in ({}, {"thrust.ramp": 7.3, "simulation.start_ramp": 11.1}, {"thrust.ramp": 0.0},
                    {"simulation.start_ramp": 0.0}):
        s = sc.replace(changes)
        T, ramp = s.thrust.force, s.thrust.ramp
        expected = T * (np.ones_like(t) if ramp <= 0 else np.where(t < ramp, 0.5 * (1 - np.cos(np.pi * t / ramp)), 1.0))
        assert thrust_series(s, dt, n).tobytes() == expected.tobytes()
        tw, R = t - wave_start(s), s.simulation.start_ramp
        expected = (tw >= 0).astype(float) if R <= 0 else \
            np.where(tw <= 0, 0.0, np.where(tw < R, 0.5 * (1 - np.cos(np.pi * np.clip(tw, 0, R) / R)), 1.0))
        assert wave_ramp(s, dt, n).tobytes() == expected.tobytes()


@pytest.mark.slow
def test_a_trial_from_shipped_kernel_arrays_and_pile_tables_is_the_same_trial(landing, monkeypatch):
    """What a campaign makes once and ships (kernel arrays, the pile's ω tables; pickled as to a worker)
    gives the trial simulate makes by itself, bit for bit — and nothing is made again."""
    import pickle

    import boatland.sea.pile as pd
    import boatland.trial.simulate as sim

    sc, db = landing
    s = sc.replace({"simulation.duration": 150.0, "sea.Hs": 0.8, "sea.relative_direction_deg": 150.0})
    own = simulate(s, db)
    setup = Setup.of(s, db)
    arrays = pickle.loads(pickle.dumps(sim.motion_arrays(setup, setup.memory())))
    tables = pickle.loads(pickle.dumps(sim.pile_tables(setup)))
    assert len(tables) == 1                                           # long-crested: one direction

    def made_again(*args, **kwargs):
        raise AssertionError("made again")

    monkeypatch.setattr(pd, "_TABLES", {})
    pd.remember_tables(tables)
    monkeypatch.setattr(pd, "pile_scattered_components", made_again)
    monkeypatch.setattr(Setup, "memory", made_again)
    monkeypatch.setattr(sim, "compile_motion", made_again)
    shipped = simulate(s, db, arrays=arrays)
    for name in ("x", "v", "F_exc", "mode", "fn", "ft", "tpos"):
        assert getattr(shipped, name).tobytes() == getattr(own, name).tobytes(), name
    assert own.slip_events() and len(shipped.events) == len(own.events)


def test_the_same_seed_gives_the_same_sea_whatever_the_duration(landing):
    """The sea is fixed by the seed, the spectrum and the component settings (``sea.repeat_period``,
    default 600 s), not by the duration: a 60-s run is the first minute of the 600-s run — the same
    components, the same elevation at the bow and the same excitation and motions to round-off."""
    from boatland.waves.synthesis import elevation_series

    sc, db = landing
    short, long_ = sc.replace({"simulation.duration": 60.0}), sc.replace({"simulation.duration": 600.0})
    waves = Setup.of(sc, db).waves
    a, b = waves.realise(sc.simulation.seed, 60.0), waves.realise(sc.simulation.seed, 600.0)
    assert a.size == b.size > 256 and all(np.array_equal(p, q) for p, q in zip(a, b))
    dt = Setup.of(sc, db).dt
    n = int(round(60.0 / dt)) + 1
    eta60 = elevation_series(a, 10.0, 0.0, 0.0, dt, n)
    eta600 = elevation_series(b, 10.0, 0.0, 0.0, dt, int(round(600.0 / dt)) + 1)[:n]
    assert np.abs(eta60 - eta600).max() <= 1e-9 * np.abs(eta600).max()
    r60, r600 = simulate(short, db), simulate(long_, db)
    m = len(r60.t)
    assert np.array_equal(r60.t, r600.t[:m])
    scale = np.abs(r600.F_exc[:m]).max(axis=0)
    assert np.all(np.abs(r60.F_exc - r600.F_exc[:m]).max(axis=0) <= 1e-9 * scale)
    dx = np.abs(r60.x - r600.x[:m]).max(axis=0)            # translations [m] and rotations [rad] apart
    assert dx[:3].max() <= 1e-9 * np.abs(r600.x[:m, :3]).max(), dx
    assert dx[3:].max() <= 1e-9 * np.abs(r600.x[:m, 3:]).max(), dx
    # a longer record than repeat_period needs more components: another sea, as the help says
    assert waves.realise(sc.simulation.seed, 1800.0).size > b.size
