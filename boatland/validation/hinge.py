"""Time domain against frequency domain: the stuck fender's force is the reaction of the vessel held at
its fender point in the frequency domain (Grøtting 2015 §3.2.1, eq. 3.1–3.12, after Wu 2014) — for the
rigid stick (Ferreira González 2023) the hinge's, for the compliant rubber (Grøtting 2015 §3.2.2) that of
its shear spring and damper.

Frequency domain (:func:`boatland.freqdomain.hinged_rao`): the vessel pinned at the fender point in the
two tangential directions of the contact plane, the normal on the fender's linear spring–damper
(k_n, d_n), linearised about the static equilibrium under the thrust:

.. math::
    \\begin{bmatrix} Z - K_g + (k_n + i\\omega d_n) G^\\top n n^\\top G & -G^\\top T \\\\ T^\\top G & 0 \\end{bmatrix}
    \\begin{bmatrix} \\hat x \\\\ \\hat\\lambda \\end{bmatrix} = \\begin{bmatrix} X \\\\ 0 \\end{bmatrix},
    \\qquad Z = -\\omega^2 (M + A) + i\\omega B + C,

reaction on the vessel :math:`\\hat J = T\\hat\\lambda - (k_n + i\\omega d_n)\\, n n^\\top G \\hat x`.

Time domain (:func:`boatland.trial.simulate.simulate`): ctv24 (pinned: the figures were measured on it),
one bow fender line (1 m wide, centred at (12.3, 0, 1.5) m) on one vertical tube of 0.35 m, c_f 1 MN/m,
d_f 40 kN s/m, μ_s = μ_k = 2 and k_v = 0 so it never slips, 80 kN thrust at (−10.5, 0, −0.9) m (ramped
over 20 s, then the waves over 2 T); regular waves H = 0.1 m. The first harmonics of the normal force
and of the tangential forces over the last 10 periods against a·e^{i(φ − k·x₀)}·Ĵ in the contact axes.
Head seas with 40 s of radiation memory; bow-quartering seas (150°) with 120 s of memory and 1 MN m s/rad
extra yaw damping in both domains (a single contact leaves yaw neutral).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.validation.case import Case, Check, Context, Outcome

__all__ = ["POINT", "FENDER_WIDTH", "STIFFNESS", "DAMPING", "THRUST", "THRUST_AT", "H", "PERIODS",
           "AMPLITUDE_TOL", "PHASE_TOL_DEG", "SHEARS", "hinge_scenario", "head_seas", "bow_quartering",
           "HingeComparison", "compare_hinge", "amplitude_phase", "CASES"]

POINT = [12.3, 0.0, 1.5]           # bow fender, body frame [m] (scenarios/ctv_landing.toml, centreline)
FENDER_WIDTH = 1.0                 # a line fender: the tube meets its face (as the shipped scenarios)
STIFFNESS, DAMPING = 1.0e6, 4.0e4  # fender normal c_f [N/m], d_f [N s/m]
THRUST, THRUST_AT = 80.0e3, [-10.5, 0.0, -0.9]
H = 0.1                            # wave height [m]
PERIODS = 10                       # fitted window [periods]
AMPLITUDE_TOL, PHASE_TOL_DEG = 0.02, 2.0
SHEARS = ("rigid", 3.0e6)
VESSEL = "ctv24"


def hinge_scenario(T, relative_direction_deg, memory, duration, yaw_damping=0.0, shear="rigid"):
    """One strut straight ahead of the vessel (its contact plane faces −x), the fender just touching it;
    ``shear`` the rubber's shear stiffness ("rigid", or N/m with the default 5 % of critical damping)."""
    from boatland.scenario.scenario import scenario_from_dict

    return scenario_from_dict({
        "name": f"hinge_T{T:g}_{relative_direction_deg:g}",
        "simulation": {"duration": duration, "seed": 1},
        "vessel": {"database": VESSEL, "damping": {"linear": [0.0] * 5 + [yaw_damping]}},
        "radiation": {"method": "convolution", "memory": memory},
        "landing": {"monopile_diameter": 6.5, "diffraction": False,   # the open-sea RAO of the FD side
                    "struts": [{"position": [-4.45, 0.0], "diameter": 0.35, "normal_deg": 180.0}]},
        "fender": {"points": [POINT], "stiffness": STIFFNESS, "damping": DAMPING, "mu_s": 2.0, "mu_k": 2.0,
                   "k_v": 0.0, "sideways": True, "shear_stiffness": shear, "width": FENDER_WIDTH},
        "thrust": {"force": THRUST, "position": THRUST_AT, "ramp": 20.0},
        "sea": {"kind": "regular", "H": H, "T": T, "relative_direction_deg": relative_direction_deg},
    })


def head_seas(T, shear="rigid"):
    """The head-seas scenario at period ``T``."""
    return hinge_scenario(T, 180.0, memory=40.0, duration=20 + 2 * T + 60 + 14 * T, shear=shear)


def bow_quartering(T, shear="rigid"):
    """The bow-quartering (150°) scenario at period ``T``."""
    return hinge_scenario(T, 150.0, memory=120.0, duration=300.0, yaw_damping=1.0e6, shear=shear)


@dataclass(frozen=True)
class HingeComparison:
    """Time-domain first harmonics and frequency-domain reactions of (fn, ft_vertical, ft_horizontal) [N],
    the static preload (normal, vertical) in both, and whether the linear stuck case held in the fitted
    window (stuck throughout, closed with at least half the thrust, the stick force equal to |ft|)."""

    td: np.ndarray
    fd: np.ndarray
    static_td: np.ndarray
    static_fd: np.ndarray
    stuck: bool
    closed: bool
    needed_is_ft: bool
    result: object


def compare_hinge(db, s) -> HingeComparison:
    """Run scenario ``s`` on ``db`` and compare with :func:`boatland.freqdomain.hinged_rao`."""
    from boatland.contact.fender import STICK
    from boatland.freqdomain import first_harmonic, hinged_rao
    from boatland.landing.law import normal_follows
    from boatland.landing.setup import Setup
    from boatland.trial.simulate import simulate
    from boatland.waves.dispersion import wavenumber_scalar

    setup = Setup.of(s, db)
    r = simulate(s, db, setup=setup)
    wave = s.sea.waves
    w = wave.omega
    x0, y0, psi = s.start_pose()
    # the excitation is referred to the wave at the reference point's start position (waves.excitation)
    k = wavenumber_scalar(w, db.water_depth, db.g)
    th = np.radians(wave.direction_deg)
    a = wave.H / 2 * np.exp(1j * (np.radians(wave.phase_deg) - k * (x0 * np.cos(th) + y0 * np.sin(th))))
    ct = setup.contacts()
    shear = {} if s.fender.rigid else {"shear_stiffness": ct.KT[0], "shear_damping": ct.CT[0]}
    follows = normal_follows(s.fender.width, ct.RT, THRUST / STIFFNESS)   # the fender's face turns with the yaw
    fd = hinged_rao(db, w, ct.P[0], beta_deg=wave.direction_deg - np.degrees(psi), normal=ct.N0[0],
                    stiffness=STIFFNESS, damping=DAMPING, thrust=THRUST, thrust_position=THRUST_AT,
                    additional_damping=setup.additional_damping()[0], normal_follows=follows["follows"],
                    tube_radius=follows.get("radius", np.inf), **shear)
    window = r.t >= r.t[-1] - PERIODS * 2 * np.pi / w
    td = np.array([first_harmonic(r.t, y, w, PERIODS) for y in (r.fn[:, 0], r.ft[:, 0, 0], r.ft[:, 0, 1])])
    static_td = np.array([r.fn[window, 0].mean(), r.ft[window, 0, 0].mean()])
    needed = r.needed[window, 0]
    ft = np.hypot(*r.ft[window, 0].T)
    return HingeComparison(td, a * fd.contact_components()[0, 0, 0], static_td,
                           fd.contact_components(static=True)[0, :2],
                           bool(np.all(r.mode[window, 0] == STICK)), bool(r.fn[window, 0].min() > 0.5 * THRUST),
                           bool(np.all(np.abs(needed - ft) <= 1e-6 + 1e-9 * np.abs(ft))), r)


def amplitude_phase(td, fd) -> tuple[float, float]:
    """Relative amplitude error |td|/|fd| − 1 and phase difference [deg]."""
    return float(abs(td) / abs(fd) - 1), float(np.degrees(np.angle(td / fd)))


# --------------------------------------------------------------------------- case
def run_hinge(ctx: Context) -> Outcome:
    """Case hinge-reaction: stuck contact forces of ctv24 in regular waves against :func:`compare_hinge`'s FD side."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from boatland.hydro.builtin import load_builtin

    db = load_builtin(VESSEL)
    periods = (7.0,) if ctx.quick else (5.0, 7.0, 9.0)
    rows = []          # (seas, shear, T, component, amplitude error, phase error, td, fd)
    checks = []
    linear_ok = True
    static_err = 0.0
    for seas, make, comps in (("head", head_seas, (0, 1)), ("bow-quartering 150°", bow_quartering, (0, 1, 2))):
        for shear in SHEARS:
            for T in periods:
                ctx.progress(f"  hinge: {seas} seas, {'rigid stick' if shear == 'rigid' else 'rubber'}, T = {T:g} s")
                c = compare_hinge(db, make(T, shear))
                linear_ok &= c.stuck and c.closed and c.needed_is_ft
                if make is head_seas:
                    static_err = max(static_err, float(np.max(np.abs(c.static_td / c.static_fd - 1))))
                for comp in comps:
                    e, p = amplitude_phase(c.td[comp], c.fd[comp])
                    rows.append((seas, shear, T, comp, e, p, c.td[comp], c.fd[comp]))
    names = ("normal force", "vertical stick force", "horizontal stick force")
    checks.append(Check("the linear stuck case held in every fitted window (stuck, closed, stick force = |f_t|)",
                        "yes" if linear_ok else "no", "yes", linear_ok))
    checks.append(Check.percent("head seas: static preload (mean normal and vertical force) the frequency domain "
                                "is linearised about", static_err, 2e-3, digits=3))
    for seas in ("head", "bow-quartering 150°"):
        for shear in SHEARS:
            sel = [r for r in rows if r[0] == seas and r[1] == shear]
            ea = max(abs(r[4]) for r in sel)
            ep = max(abs(r[5]) for r in sel)
            label = "rigid stick" if shear == "rigid" else f"rubber k_t = {shear / 1e6:g} MN/m"
            checks.append(Check.percent(f"{seas} seas, {label}: amplitude, worst of {len(sel)} "
                                        "(period × force component)", ea, AMPLITUDE_TOL, digits=3))
            checks.append(Check.below(f"{seas} seas, {label}: phase [deg]", ep, PHASE_TOL_DEG, "{:.2f}", "°"))
    fig, ax = plt.subplots(1, 2, figsize=(11, 3.8), constrained_layout=True)
    shift = {("head", "rigid"): -0.15, ("head", 3.0e6): -0.05, ("bow-quartering 150°", "rigid"): 0.05,
             ("bow-quartering 150°", 3.0e6): 0.15}
    marker = {0: "o", 1: "s", 2: "^"}
    for seas, shear, T, comp, e, p, _, _ in rows:
        kw = dict(marker=marker[comp], color="C0" if seas == "head" else "C3",
                  fillstyle="full" if shear == "rigid" else "none", ls="none")
        ax[0].plot(T + shift[(seas, shear)], 100 * e, **kw)
        ax[1].plot(T + shift[(seas, shear)], p, **kw)
    for comp in (0, 1, 2):
        ax[0].plot([], [], marker=marker[comp], color="0.4", ls="none", label=names[comp])
    ax[0].plot([], [], "s", color="C0", label="head seas")
    ax[0].plot([], [], "s", color="C3", label="bow-quartering 150°")
    ax[0].plot([], [], "s", color="0.4", fillstyle="none", label="open: rubber k_t 3 MN/m; filled: rigid stick")
    for a, tol, unit in ((ax[0], 100 * AMPLITUDE_TOL, "amplitude: |TD| / |FD| − 1 [%]"),
                         (ax[1], PHASE_TOL_DEG, "phase: arg(TD / FD) [deg]")):
        a.axhspan(-tol, tol, color="0.92", zorder=0, label="tolerance")
        a.axhline(0, color="0.5", lw=0.8)
        a.set_ylim(-1.6 * tol, 1.6 * tol)
        a.set_xticks(periods)
        a.set_xlim(min(periods) - 0.8, max(periods) + 0.8)
        a.set_xlabel("wave period T [s]")
        a.set_ylabel(unit)
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=7, ncol=2, loc="lower left")
    fig.suptitle(f"Stuck fender force, time domain (TD) vs frequency-domain hinge reaction (FD); ctv24, H = {H:g} m")
    name = ctx.save(fig, "hinge_reaction.png")
    worst_a = max(abs(r[4]) for r in rows)
    worst_p = max(abs(r[5]) for r in rows)
    return Outcome(checks, f"max {100 * worst_a:.2f} %, {worst_p:.2f}°", name,
                   settings=f"T = {', '.join(f'{T:g}' for T in periods)} s" + (" (--quick: T = 7 s only)" if ctx.quick else ""))


CASES = [
    Case("hinge-reaction", "Time domain vs frequency domain: the stuck fender's force is the hinge reaction",
         "Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc "
         "thesis, NTNU, §3.2.1 eq. 3.1–3.12 (the fender-hinged vessel, after Wu, M. (2014), \"Numerical "
         "analysis of docking operation between service vessels and offshore wind turbines\", *Ocean "
         "Engineering* 91) and §3.2.2 (the rubber's shear spring); the rigid stick of Ferreira González (2023), "
         "TU Hamburg Dr.-Ing. dissertation, §3.4.",
         "ctv24 (pinned), one fender line on one tube, 80 kN thrust, μ = 2 so it never slips, regular waves "
         "H = 0.1 m: first harmonics of the normal and tangential contact forces over the last 10 periods "
         "against the frequency-domain reaction of the vessel hinged at its fender point (rigid stick, and "
         "the rubber k_t = 3 MN/m), head seas and bow-quartering seas.",
         "relative amplitude error and phase difference of each force component, worst over periods",
         "< 2 %, < 2°", run_hinge, quick="T = 7 s only (full: 5, 7, 9 s)",
         cite="Grøtting (2015) §3.2.1–3.2.2, after Wu (2014)"),
]
