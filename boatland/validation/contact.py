"""The fender contact against closed forms, on a translating block pressed on a flat plate.

- Elastic impact on the linear fender (no damping): contact lasts half the spring period π√(m/c_f) and
  the block leaves with its entry speed.
- Coulomb stick–slip under a harmonic tangential load F₀ sin ωt with the rigid stick (Ferreira González
  2023, eq. 2.78, 3.21–3.24): stuck until F₀ sin ωt = μT, then m ż' = F₀ sin ωt − μT until the sliding
  speed is zero again; the compliant rubber (Grøtting 2015 §3.2.2) tends to it as k_t grows.
- The stuck rubber is a spring–damper: it rings at ω_d = ω_n√(1 − ζ²), ω_n = √(k_t/m), with the
  logarithmic decrement 2πζ/√(1 − ζ²).
"""

from __future__ import annotations

import math

import numpy as np

from boatland.validation.case import Case, Check, Context, Outcome

__all__ = ["BLOCK_MASS", "T_PUSH", "C_F", "D_F", "MU", "F0", "W", "block", "plate", "pushed", "coulomb_case",
           "coulomb_times", "slip_times", "impact", "rubber_ring", "CASES"]

BLOCK_MASS = 1000.0
T_PUSH = 2.0e4         # thrust along x [N] (the normal force when steady)
C_F, D_F = 1.0e6, 6.0e4
MU, F0, W = 0.5, 1.5e4, 1.0


def block(C=None):
    """A translating block of mass :data:`BLOCK_MASS` (rotations frozen by 1e9 inertias), no memory."""
    from boatland.trial.motion import MotionArrays

    m = BLOCK_MASS
    Mt = np.diag([m, m, m, 1e9, 1e9, 1e9])
    return MotionArrays.without_memory(Mt, np.zeros((6, 6)) if C is None else C)


def plate(c_f=C_F, d_f=D_F, **law):
    """Fender point at the reference point; a flat plate x = 0.5 with normal −x (the block comes from −x)."""
    from boatland.contact.fender import contact_set

    law.setdefault("mu_s", 0.0)
    law.setdefault("mu_k", law["mu_s"])
    return contact_set([[0.0, 0.0, 0.0]], [[0.5, 0.0]], math.inf, [[-1.0, 0.0]], stiffness=c_f, damping=d_f, **law)


def pushed(dt, duration, F_t, contacts, x0=None):
    """Block pressed on the plate by :data:`T_PUSH` and loaded tangentially by F_t(t) = (Fy, Fz) at half steps."""
    n = int(round(duration / dt))
    t_half = np.arange(2 * n + 1) * dt / 2
    F = np.zeros((2 * n + 1, 6))
    Fy, Fz = F_t(t_half)
    F[:, 1], F[:, 2] = Fy, Fz
    x0 = [0.5 + T_PUSH / C_F, 0, 0, 0, 0, 0] if x0 is None else x0
    return block().run(dt, n, F_ext=F, thrust=np.full(2 * n + 1, T_PUSH), x0=x0, contacts=contacts)


def coulomb_case(dt, **law):
    """Pressed by T (normal force T), loaded vertically by F0 sin ωt, μ_s = μ_k = μ."""
    law.setdefault("mu_s", MU)
    return pushed(dt, 12.0, lambda t: (0 * t, F0 * np.sin(W * t)), plate(**law))


def coulomb_times():
    """Closed form: stuck until F0 sin ωt = μT, then m z'' = F0 sin ωt − μT until z' = 0 again.
    Returns (t_slip, t_stick) [s]."""
    from scipy.optimize import brentq

    m = BLOCK_MASS
    t_s = math.asin(MU * T_PUSH / F0) / W
    vel = lambda t: (F0 * (math.cos(W * t_s) - math.cos(W * t)) / W - MU * T_PUSH * (t - t_s)) / m  # noqa: E731
    return t_s, brentq(vel, t_s + 0.1, t_s + math.pi / W * 1.9)


def coulomb_velocity(t):
    """The closed-form vertical velocity of the Coulomb case [m/s] (zero while stuck; first slip only)."""
    t_s, t_e = coulomb_times()
    t = np.asarray(t, dtype=float)
    v = (F0 * (math.cos(W * t_s) - np.cos(W * t)) / W - MU * T_PUSH * (t - t_s)) / BLOCK_MASS
    return np.where((t > t_s) & (t < t_e), v, 0.0)


def slip_times(r):
    """First stick → slip and the following slip → stick times of the integrator's run ``r``."""
    from boatland.contact.fender import SLIP, STICK

    mode = r["mode"][:, 0]
    start = np.nonzero((mode[:-1] == STICK) & (mode[1:] == SLIP))[0] + 1
    end = np.nonzero((mode[:-1] == SLIP) & (mode[1:] == STICK))[0] + 1
    return float(r["t"][start[0]]), float(r["t"][end[0]])


def impact(c_f=4.0e5, v0=1.0, dt=1e-3, n=1500):
    """The block strikes the undamped fender at ``v0``: (contact duration [s], exit velocity [m/s],
    closed-form duration π√(m/c_f), the run)."""
    r = block().run(dt, n, x0=[0.0, 0, 0, 0, 0, 0], v0=[v0, 0, 0, 0, 0, 0], contacts=plate(c_f, 0.0))
    touching = np.nonzero(r["fn"][:, 0] > 0)[0]
    duration = (touching[-1] - touching[0] + 1) * dt
    return duration, float(r["v"][-1, 0]), math.pi * math.sqrt(BLOCK_MASS / c_f), r


def rubber_ring(k_t=4.0e6, zeta=0.04, v0=0.1, dt=2e-4, duration=0.5):
    """A block that lands on the rubber moving up at ``v0``: stuck, it rings. Returns (damped angular
    frequency, logarithmic decrement, their closed forms, all stuck, the run)."""
    from boatland.contact.fender import STICK

    m = BLOCK_MASS
    c_t = 2 * zeta * math.sqrt(k_t * m)
    n = int(round(duration / dt))
    r = block().run(dt, n, thrust=np.full(2 * n + 1, T_PUSH), x0=[0.5 + T_PUSH / C_F, 0, 0, 0, 0, 0],
                    v0=[0, 0, v0, 0, 0, 0], contacts=plate(mu_s=0.5, shear_stiffness=k_t, shear_damping=c_t))
    t, z = r["t"], r["x"][:, 2]
    peaks = np.nonzero((z[1:-1] > z[:-2]) & (z[1:-1] >= z[2:]))[0] + 1
    wd = 2 * math.pi / float(np.mean(np.diff(t[peaks])))
    decrement = math.log(z[peaks[0]] / z[peaks[1]])
    wn = math.sqrt(k_t / m)
    return (wd, decrement, wn * math.sqrt(1 - zeta ** 2), 2 * math.pi * zeta / math.sqrt(1 - zeta ** 2),
            bool((r["mode"][:, 0] == STICK).all()), r)


# --------------------------------------------------------------------------- case
def run_contact(ctx: Context) -> Outcome:
    """Case contact-analytic: impact, Coulomb stick–slip (rigid and rubber) and the stuck rubber in closed form."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    checks = []
    duration, v_out, expected, r_imp = impact()
    checks.append(Check.below("elastic impact: contact duration − π√(m/c_f) [steps of 1 ms]",
                              abs(duration - expected) / 1e-3, 2.0, "{:.2f}"))
    checks.append(Check.percent("elastic impact: exit speed vs entry speed", abs(-v_out - 1.0), 1e-4, digits=4))
    t_s, t_e = coulomb_times()
    runs = {}
    for dt in (0.01, 0.002):
        r = coulomb_case(dt)
        runs[dt] = r
        s, e = slip_times(r)
        checks.append(Check.below(f"rigid stick, Δt = {dt:g} s: |slip start − {t_s:.4f} s| in steps",
                                  abs(s - t_s) / dt, 1.0 + 1e-9 / dt, "{:.2f}"))
        checks.append(Check.below(f"rigid stick, Δt = {dt:g} s: |re-stick − {t_e:.4f} s| in steps",
                                  abs(e - t_e) / dt, 1.0 + 1e-9 / dt, "{:.2f}"))
    for k_t, tol in ((3e6, 0.02), (3e8, 0.004)):
        c_t = 2 * 0.05 * math.sqrt(k_t * BLOCK_MASS)
        s, e = slip_times(coulomb_case(0.0005, shear_stiffness=k_t, shear_damping=c_t))
        checks.append(Check.below(f"rubber k_t = {k_t:.0e} N/m (5 % damping): max |Δt| of slip start and re-stick "
                                  "against the rigid closed form [s]", max(abs(s - t_s), abs(e - t_e)), tol, "{:.4f}"))
    wd, dec, wd0, dec0, stuck, r_ring = rubber_ring()
    checks.append(Check("stuck rubber: stuck throughout", "yes" if stuck else "no", "yes", stuck))
    checks.append(Check.percent("stuck rubber: damped frequency vs ω_n√(1 − ζ²)", abs(wd / wd0 - 1), 1e-3, digits=4))
    checks.append(Check.percent("stuck rubber: logarithmic decrement vs 2πζ/√(1 − ζ²)", abs(dec / dec0 - 1), 0.01, digits=3))

    fig, ax = plt.subplots(1, 3, figsize=(14, 3.8), constrained_layout=True)
    fn = r_imp["fn"][:, 0]
    ax[0].plot(r_imp["t"], fn / 1e3, label="boatland")
    ax[0].axvline(np.nonzero(fn > 0)[0][0] * 1e-3 + expected, color="k", ls=":", label="π√(m/c_f) after touching")
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("normal force [kN]")
    ax[0].set_title("elastic impact, c_f = 400 kN/m, v₀ = 1 m/s")
    tt = np.linspace(0, 12, 2000)
    ax[1].plot(tt, coulomb_velocity(tt), color="0.7", lw=3, label="closed form (first slip)")
    for dt, r in runs.items():
        ax[1].plot(r["t"], r["v"][:, 2], "--", lw=1, label=f"boatland, Δt = {dt:g} s")
    ax[1].axvline(t_s, color="k", ls=":")
    ax[1].axvline(t_e, color="k", ls=":")
    ax[1].set_xlim(0, t_e + 2)
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("sliding speed ż [m/s]")
    ax[1].set_title(f"Coulomb stick–slip, μ = {MU:g}, F₀ sin t, T = {T_PUSH / 1e3:g} kN")
    ax[2].plot(r_ring["t"], r_ring["x"][:, 2] * 1e3, label="boatland")
    tr = r_ring["t"]
    ax[2].plot(tr, 0.1 / wd0 * np.exp(-dec0 / (2 * math.pi) * wd0 * tr) * np.sin(wd0 * tr) * 1e3, ":", color="k",
               label="closed form")
    ax[2].set_xlabel("t [s]")
    ax[2].set_ylabel("z [mm]")
    ax[2].set_title("stuck rubber, k_t = 4 MN/m, ζ = 0.04")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    name = ctx.save(fig, "contact_analytic.png")
    worst_steps = max(k.error for k in checks if "in steps" in k.what)
    return Outcome(checks, f"slip times within {worst_steps:.2f} step", name)


CASES = [
    Case("contact-analytic", "Fender contact: impact, Coulomb stick–slip and the stuck rubber in closed form",
         "Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of Boatlanding "
         "Maneuvers*, Dr.-Ing. dissertation, TU Hamburg, eq. 2.78, 3.21–3.24 (stick–slip as an augmented "
         "system); Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind "
         "Turbines*, MSc thesis, NTNU, §3.2.2 (the rubber's shear spring); closed forms of a mass on a spring, "
         "and under Coulomb friction.",
         "A 1 t block (rotations frozen) on a flat plate: striking the undamped fender; pressed by 20 kN and "
         "loaded by 15 kN·sin t with μ = 0.5 (rigid stick at Δt = 0.01 and 0.002 s; rubber k_t = 3e6 and 3e8 N/m "
         "at Δt = 0.0005 s); landing on the stuck rubber at 0.1 m/s.",
         "event times against the closed form (in steps or seconds); frequency and decrement relative errors",
         "slip times within 1 step", run_contact,
         cite="closed forms; Ferreira González (2023) eq. 3.21–3.24"),
]
