"""Fender contact against closed forms: elastic impact, Coulomb stick–slip under a harmonic load (rigid
stick), the rubber's shear spring while it sticks, sliding in two directions with friction against the
slide, friction that never adds energy at any Δt, the rigid limit of a stiff rubber, and the geometry
of tubes and fender lines (Ferreira González 2023 eq. 2.78, 3.21–3.24; Cundall & Strack 1979)."""

import math

import numpy as np
import pytest

from boatland.contact.fender import OFF, OPEN, SLIP, STICK, contact_set, stribeck
from boatland.integrate.cummins import STATUS_SLID_OFF
# The block, the plate and the closed forms are boatland.validation.contact's (`boatland validate` runs them).
from boatland.validation.contact import C_F, D_F, MU, T_PUSH, block, coulomb_case, coulomb_times, plate, pushed
from boatland.validation.contact import BLOCK_MASS as m


def test_stribeck_curve():
    assert stribeck(0.0, 0.9, 0.7, 0.2, 0.2, 1.5) == pytest.approx(0.9)
    v = 5.0
    assert stribeck(v, 0.9, 0.7, 0.2, 0.2, 1.5) == pytest.approx(0.7 + 0.2 * np.exp(-(v / 0.2) ** 1.5) + 0.2 * v)


@pytest.mark.slow
def test_mass_striking_a_linear_fender():
    """Contact lasts half the spring period π√(m/c_f) and the mass leaves with its entry speed."""
    c_f, v0, dt = 4.0e5, 1.0, 1e-3
    r = block().run(dt, 1500, x0=[0.0, 0, 0, 0, 0, 0], v0=[v0, 0, 0, 0, 0, 0], contacts=plate(c_f, 0.0))
    fn = r["fn"][:, 0]
    touching = np.nonzero(fn > 0)[0]
    duration = (touching[-1] - touching[0] + 1) * dt
    assert duration == pytest.approx(np.pi * np.sqrt(m / c_f), abs=2 * dt)
    assert r["v"][-1, 0] == pytest.approx(-v0, rel=1e-4)
    assert r["fn"].min() >= 0.0 and r["mode"][-1, 0] == OPEN  # never pulling; open again


@pytest.mark.slow
@pytest.mark.parametrize("dt", [0.01, 0.002])
def test_coulomb_stick_slip_times_within_one_step(dt):
    r = coulomb_case(dt)                      # the rigid stick (shear_stiffness inf)
    t_s, t_e = coulomb_times()
    mode = r["mode"][:, 0]
    slip_start = np.nonzero((mode[:-1] == STICK) & (mode[1:] == SLIP))[0] + 1
    slip_end = np.nonzero((mode[:-1] == SLIP) & (mode[1:] == STICK))[0] + 1
    assert r["t"][slip_start[0]] == pytest.approx(t_s, abs=dt + 1e-9)
    assert r["t"][slip_end[0]] == pytest.approx(t_e, abs=dt + 1e-9)


@pytest.mark.slow
def test_a_stiff_rubber_slips_when_the_rigid_stick_does():
    """The compliant contact's stick → slip and re-stick converge to the closed form as k_t grows
    (within a step and the rubber's own delay: the load reaches μN a few k_t-periods later)."""
    t_s, t_e = coulomb_times()
    for k_t, tol in ((3e6, 0.02), (3e8, 0.004)):
        c_t = 2 * 0.05 * math.sqrt(k_t * m)
        r = coulomb_case(0.0005, shear_stiffness=k_t, shear_damping=c_t)
        mode = r["mode"][:, 0]
        start = r["t"][np.nonzero((mode[:-1] == STICK) & (mode[1:] == SLIP))[0][0] + 1]
        end = r["t"][np.nonzero((mode[:-1] == SLIP) & (mode[1:] == STICK))[0][0] + 1]
        assert start == pytest.approx(t_s, abs=tol) and end == pytest.approx(t_e, abs=tol)


def test_the_stuck_rubber_is_a_spring_damper():
    """A block that lands on the rubber moving up at v0: stuck, it rings at ω_d = ω_n√(1 − ζ²), ω_n =
    √(k_t/m), with ζ = c_t / (2√(k_t m)); the anchor never moves, and the force is −k_t e − c_t u."""
    k_t, zeta, v0, dt = 4.0e6, 0.04, 0.1, 2e-4
    c_t = 2 * zeta * math.sqrt(k_t * m)
    n = int(round(0.5 / dt))
    r = block().run(dt, n, thrust=np.full(2 * n + 1, T_PUSH), x0=[0.5 + T_PUSH / C_F, 0, 0, 0, 0, 0],
                    v0=[0, 0, v0, 0, 0, 0], contacts=plate(mu_s=0.5, shear_stiffness=k_t, shear_damping=c_t))
    assert (r["mode"][:, 0] == STICK).all() and not np.any(r["slide"]) and not np.any(r["work"])
    t, z = r["t"], r["x"][:, 2]
    peaks = np.nonzero((z[1:-1] > z[:-2]) & (z[1:-1] >= z[2:]))[0] + 1
    wn = math.sqrt(k_t / m)
    assert 2 * math.pi / np.mean(np.diff(t[peaks])) == pytest.approx(wn * math.sqrt(1 - zeta ** 2), rel=1e-3)
    decay = np.log(z[peaks[0]] / z[peaks[1]])                  # log decrement 2πζ/√(1 − ζ²)
    assert decay == pytest.approx(2 * math.pi * zeta / math.sqrt(1 - zeta ** 2), rel=0.01)
    e = r["tpos"][:, 0, 0] - r["tpos"][0, 0, 0]                  # deflection from where it landed
    assert r["ft"][:, 0, 0] == pytest.approx(-k_t * e - c_t * r["v"][:, 2], rel=1e-9, abs=1e-6)


def sliding_2d(dt, **law):
    """Pressed on the plate and dragged by a tangential force that turns (ω = 1 rad/s) and beats between
    0.2 and 1.6 μ_s N: the fender sticks, slips and slides along curved paths in both directions."""
    law.setdefault("mu_s", 0.6)
    law.setdefault("mu_k", 0.5)
    law.setdefault("k_v", 0.2)
    amp = lambda t: 0.9 * 0.6 * T_PUSH * (1 + 0.8 * np.sin(0.37 * t))  # noqa: E731
    return pushed(dt, 60.0, lambda t: (amp(t) * np.cos(t), amp(t) * np.sin(t)), plate(**law))


@pytest.mark.parametrize("shear", ["compliant", "rigid"])
@pytest.mark.parametrize("dt", [0.05, 0.025, 0.0125])
def test_friction_never_pushes(shear, dt):
    """In every slip step the friction work is ≤ 0 (the kernel's: f·ΔA for the rubber's anchor, the RK4
    quadrature of f·u for the rigid contact); and while sliding faster than 1 mm/s the friction is
    within 1° of the opposite of the sliding (the rubber's slide over the step that ended at the row, or
    the rigid contact's velocity at the row)."""
    law = {} if shear == "rigid" else {"shear_stiffness": 3e6, "shear_damping": 2 * 0.05 * math.sqrt(3e6 * m)}
    r = sliding_2d(dt, **law)
    mode, work, slide, ft = r["mode"][:, 0], r["work"][:, 0], r["slide"][:, 0], r["ft"][:, 0]
    slipping = mode == SLIP
    assert slipping.sum() > 100 and (mode == STICK).sum() > 100
    scale = 0.7 * T_PUSH * 0.1 * dt          # friction × a slide of 0.1 m/s over a step [J]
    assert work.max() <= 1e-12 * scale       # never positive (round-off only)
    assert work.sum() < -100.0
    if shear == "rigid":
        u = np.stack([r["v"][:, 2], r["v"][:, 1] * -1.0], axis=1)   # (vertical, along t_h = e_z × (−e_x) = −e_y)
        moving = slipping & (np.hypot(u[:, 0], u[:, 1]) > 1e-3)
        f, s = ft[moving], u[moving]
    else:
        moving = np.hypot(slide[:, 0], slide[:, 1]) > 1e-3 * dt
        f, s = ft[moving], slide[moving]
    cos = -(f * s).sum(axis=1) / (np.hypot(f[:, 0], f[:, 1]) * np.hypot(s[:, 0], s[:, 1]))
    assert moving.sum() > 50
    assert np.degrees(np.arccos(np.clip(cos, -1, 1))).max() < 1.0


def test_stribeck_speed_and_decision_use_the_friction_directions():
    """sideways = false: no horizontal friction, and the sliding speed of μ(v) is the vertical one only."""
    r = pushed(0.01, 5.0, lambda t: (8e3 + 0 * t, 1.5e4 * np.sin(3 * t)),
               plate(mu_s=0.6, mu_k=0.5, k_v=0.2, sideways=False))
    sl = r["mode"][:, 0] == SLIP
    assert sl.sum() > 20 and not np.any(r["ft"][:, 0, 1])
    uz = np.abs(r["v"][sl, 2])
    mu = np.array([stribeck(u, 0.6, 0.5, 0.2, 0.2, 1.5) for u in uz])
    assert r["available"][sl, 0] == pytest.approx(mu * r["fn"][sl, 0], rel=1e-12)
    assert np.abs(r["v"][sl, 1]).max() > 10 * uz.max()       # it slides sideways much faster than vertically


def test_stuck_block_does_not_drift():
    """Held by friction under a load below μN for many cycles: the anchor keeps the point in place."""
    dt = 0.02
    r = pushed(dt, 1200.0, lambda t: (0 * t, 0.8e4 * np.sin(t)), plate(mu_s=MU))
    assert np.all(r["mode"][:, 0] == STICK)
    assert np.max(np.abs(r["tpos"][:, 0, 0] - r["tpos"][0, 0, 0])) < 1e-6


def tube(width, **kw):
    """A tube of radius 0.2 m at (0.7, 0) meeting a fender line of the given width along y at the
    reference point, from z = −1 to 1 m."""
    return contact_set([[0.0, 0.0, 0.0]], [[0.7, 0.0]], 0.2, [[-1.0, 0.0]], half_width=width / 2, bottom=-1.0,
                       top=1.0, stiffness=C_F, damping=D_F, mu_s=0.3, mu_k=0.3, sideways=True, **kw)


def test_the_normal_follows_the_tube():
    """A point fender 0.1 m to the side of a 0.2 m tube's axis touches it off its front: the normal force
    acts from the tube's axis through the point, δ = ρ − distance."""
    x, y = 0.7 - 0.2 * math.cos(math.pi / 6) + 0.01, 0.1
    dt = 1e-7
    r = block().run(dt, 1, x0=[x, y, 0, 0, 0, 0], contacts=tube(0.0))
    d = np.array([x - 0.7, y])
    fn = r["fn"][0, 0]
    assert fn == pytest.approx(C_F * (0.2 - np.linalg.norm(d)), rel=1e-9)
    acc = (r["v"][1, :2] - r["v"][0, :2]) / dt
    assert acc == pytest.approx(fn * d / np.linalg.norm(d) / m, rel=1e-4)


@pytest.mark.parametrize("width", [0.0, 1.0])
def test_a_sideways_push_beyond_the_fender_ends_in_sliding_off(width):
    """Pushed sideways (10 kN ≫ μN = 6 kN) the fender slides along the tube; once the tube is a tube radius
    past the fender's end no contact is possible: the contact is off the landing and the trial ends there
    (not an endless slide)."""
    dt, n = 0.002, 5000
    F = np.zeros((2 * n + 1, 6))
    F[:, 1] = 1.0e4
    x0 = [0.7 - 0.2 + T_PUSH / C_F, 0, 0, 0, 0, 0]
    r = block().run(dt, n, F_ext=F, thrust=np.full(2 * n + 1, T_PUSH), x0=x0, contacts=tube(width))
    assert r["status"] == STATUS_SLID_OFF
    assert r["mode"][-1, 0] == OFF and SLIP in r["mode"][:, 0]
    assert r["x"][-1, 1] >= width / 2 + 0.2 - 1e-9            # the tube one radius past the fender's end
    assert r["x"][-1, 1] < width / 2 + 0.2 + 0.05


def test_sliding_past_the_tube_end_is_off_the_landing():
    """Pushed up past the tube's top (z = 1 m): off the landing."""
    dt, n = 0.002, 4000
    F = np.zeros((2 * n + 1, 6))
    F[:, 2] = 1.0e4
    r = block().run(dt, n, F_ext=F, thrust=np.full(2 * n + 1, T_PUSH), x0=[0.5 + T_PUSH / C_F, 0, 0, 0, 0, 0],
                    contacts=tube(1.0))
    assert r["status"] == STATUS_SLID_OFF and r["mode"][-1, 0] == OFF
    assert r["x"][-1, 2] == pytest.approx(1.0, abs=0.01)
