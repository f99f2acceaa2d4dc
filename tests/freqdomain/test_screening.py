"""Wu (2014) slip screening (boatland.freqdomain.screening) on the built-in CTV (ctv24,
scenarios/ctv24_landing.toml): sign conventions against the hinge reactions, static capacities, the
limiting-Hs root, monotonicity in μ and thrust (Grøtting 2015 §4.1.1), bad input."""

from __future__ import annotations

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.freqdomain import (ACCEPT_PRESETS, LandingSetup, accept_probability, incident_probability,
                                 limiting_hs, screening_grid, slip_transfer, spectral_moments)
from boatland.freqdomain.screening import landed_response
from boatland.hydro.builtin import load_builtin

TP = np.array([4.0, 6.0, 8.0, 11.0, 15.0])
BETA = np.array([90.0, 135.0, 180.0])


@pytest.fixture(scope="module")
def single(landing):
    """One contact on the centreline (as tests/validation/test_hinge_reaction.py)."""
    db, s = landing
    return db, s.replace(points=[[12.3, 0.0, 1.5]], normals=[[-1.0, 0.0, 0.0]])


def test_setup_from_the_default_scenario(landing):
    db, s = landing
    assert s.points.shape == (2, 3) and np.allclose(s.normals, [[-1, 0, 0]] * 2)  # bow on, heading 0
    assert s.mu == 0.6 and s.thrust == 80e3 and s.roll_limit_deg == 10.0


@pytest.mark.parametrize("shear", ["compliant", "rigid"])
def test_margins_are_the_slip_conditions_of_the_contact_forces(landing, shear):
    """Per contact c: H_down = J_v − μJ_n, H_up = −J_v − μJ_n, H_left = J_h − μJ_n, H_right = −J_h − μJ_n
    in its own axes (n, t_v = e_z, t_h = e_z × n) of contact_components; for n = −e_x, t_h = −e_y
    (starboard): a needed force to starboard means a slip to port (left). Grøtting 2015 eq. 3.25–3.28 /
    3.76–3.79, for each contact rather than for their sum — each direction tilted onto the friction circle by
    the static load across it (slip_directions): the side modes by the static vertical force V⁰, the
    vertical modes by the (here vanishing) static side force H⁰."""
    db, s = landing
    if shear == "rigid":
        s = s.replace(shear_stiffness=np.inf)
    w = np.array([0.6, 0.9, 1.3])
    tr = slip_transfer(db, s, omega=w, beta_deg=[150.0])
    r = landed_response(db, s, w, [150.0])
    mu = s.mu
    expected, capacity = [], []
    for c in range(2):
        Jn, Jv, Jh = np.moveaxis(r.contact_components()[:, :, c], -1, 0)
        N0, V0, H0 = r.contact_components(static=True)[c]
        assert np.isclose(N0, s.thrust / 2, rtol=1e-3) and V0 < 0 and abs(H0) < 1e-6 * N0
        sv, sh = -H0 / (mu * N0), V0 / (mu * N0)       # across the vertical modes: −t_h; across the side: e_z
        cv, ch = np.sqrt(1 - sv ** 2), np.sqrt(1 - sh ** 2)
        along = [(cv * Jv - sv * Jh, cv * V0 - sv * H0), (-cv * Jv - sv * Jh, -cv * V0 - sv * H0),
                 (ch * Jh + sh * Jv, ch * H0 + sh * V0), (-ch * Jh + sh * Jv, -ch * H0 + sh * V0)]
        expected += [d - mu * Jn for d, _ in along]
        # static capacities a_m = μN⁰ − d_mᵀJ⁰ (Grøtting 2015 eq. 3.72–3.75): the fender is above the thrust
        # line, so the static vertical force F_zc on the vessel points down and lowers the capacity against
        # upward slip; on the circle it lowers the side modes' too
        capacity += [mu * N0 - d0 for _, d0 in along]
    expected = np.stack(expected + [r.x[..., 3]], axis=-1)
    np.testing.assert_allclose(tr.H, expected, rtol=1e-12, atol=1e-9)
    assert tr.names == ("down 0", "up 0", "left 0", "right 0", "down 1", "up 1", "left 1", "right 1", "roll")
    np.testing.assert_allclose(tr.capacity[:-1], capacity)
    assert tr.capacity[2] < mu * s.thrust / 2 * (1 - 1e-3)      # the side modes lose to the vertical load
    assert tr.capacity[-1] == np.radians(s.roll_limit_deg)
    # roll is locked by the rigid stick, free on the rubber
    assert (np.abs(tr.H[..., -1]).max() < 1e-12) == (shear == "rigid")


def test_wu_method_has_the_thrust_as_static_normal_only(single):
    """Grøtting (2015) §3.2.1: rigid hinge, N⁰ = F_b, no static vertical force: every capacity is μF_b."""
    db, s = single
    tr = slip_transfer(db, s, omega=[0.8], beta_deg=[180.0], method="wu")
    assert tr.N_static == pytest.approx([s.thrust])
    np.testing.assert_allclose(tr.capacity[:4], s.mu * s.thrust)


def test_limiting_hs_is_the_root_of_the_accept_criterion(landing):
    """At the limit P_inc per cycle = P_facc Tp / t_acc (Grøtting 2015 eq. 3.38–3.40); the vectorised bisection
    equals one cell at a time."""
    db, s = landing
    tr = slip_transfer(db, s, beta_deg=BETA)
    m, _ = spectral_moments(tr, TP)
    tab = limiting_hs(m, tr.capacity, TP, BETA, accept="best", statistics="rayleigh")
    pc, _, _ = incident_probability(tab.Hs, m, tr.capacity, TP, statistics="rayleigh")
    np.testing.assert_allclose(pc, np.broadcast_to(ACCEPT_PRESETS["best"] * TP[:, None] / 1800.0, pc.shape), rtol=1e-9)
    one = limiting_hs(m[2:3, 1:2], tr.capacity, TP[2:3], BETA[1:2], statistics="rayleigh")
    assert one.Hs[0, 0] == pytest.approx(tab.Hs[2, 1], rel=1e-12)
    # with Rice's up-crossings (the default) the limit is where P per access is the accepted risk
    rice = limiting_hs(m, tr.capacity, TP, BETA, accept="best")
    _, pa, _ = incident_probability(rice.Hs, m, tr.capacity, TP, statistics="rice")
    assert rice.statistics == "rice"
    np.testing.assert_allclose(pa, ACCEPT_PRESETS["best"], rtol=1e-9)
    # every σ is linear in Hs: the margins' m0 scale with Hs²
    _, _, p1 = incident_probability(1.0, m, tr.capacity, TP, statistics="rayleigh")
    _, _, p2 = incident_probability(2.0, m, tr.capacity, TP, statistics="rayleigh")
    assert np.allclose(np.log(p2[..., :-1]), np.log(p1[..., :-1]) / 4)


@pytest.mark.parametrize("statistics", ["rayleigh", "rice", "vanmarcke"])
def test_limiting_hs_rises_with_thrust_and_friction(landing, statistics):
    """Grøtting (2015) §4.1.1 (Figures 4.1–4.3): more bollard push or friction → larger limiting Hs, everywhere."""
    db, s = landing
    grid = lambda **kw: screening_grid(db, s, TP, BETA, statistics=statistics, **kw).Hs  # noqa: E731
    for lo, hi in ((dict(mu=0.5), dict(mu=0.6)), (dict(mu=0.6), dict(mu=0.8)),
                   (dict(thrust=60e3), dict(thrust=80e3)), (dict(thrust=80e3), dict(thrust=120e3))):
        a, b = grid(**lo), grid(**hi)
        assert np.all(b > a), (lo, hi)


def test_stricter_acceptance_lowers_the_limit(landing):
    """Grøtting (2015) §4.1.3 / Table 2.1 presets: conservative < best < non-conservative."""
    db, s = landing
    tr = slip_transfer(db, s, beta_deg=BETA)
    m, _ = spectral_moments(tr, TP)
    h = [limiting_hs(m, tr.capacity, TP, BETA, accept=k).Hs for k in ("conservative", "best", "non-conservative")]
    assert np.all(h[0] < h[1]) and np.all(h[1] < h[2])


def test_default_ctv_limits_are_low_and_governed_by_upward_slip(landing):
    """The default CTV at 80 kN, μ 0.6, head seas, P_acc 0.00119 per 30 min — limiting Hs 0.15–0.21 m
    over Tp 4–15 s (measured 0.195, 0.157, 0.173, 0.196, 0.213), upward slip of one of the (symmetric)
    contacts governs: the vertical force the waves put on each contact against its capacity
    μN⁰ + F_zc = 0.6 × 40 kN + 6.5 kN. Consistent with the time domain, where the default trial (Hs 1.5 m)
    slips hundreds of times in 10 min."""
    db, s = landing
    tab = screening_grid(db, s, TP, [180.0])
    assert np.all((tab.Hs > 0.12) & (tab.Hs < 0.25)) and all(g.startswith("up ") for g in tab.governing.ravel())


def test_beam_and_quartering_seas_are_the_most_dangerous(landing):
    """Each contact judged on its own, the couple of opposite vertical forces that resists roll in
    oblique seas is seen: at Tp 7 s the limiting Hs falls from head (0.16 m) to quartering (0.09 m) to
    beam seas (0.07 m) — the ranking of Grøtting's (2015) SIMO runs. The rigid stick, which locks roll
    and takes the whole roll moment as that couple, halves the oblique limits again (0.046, 0.037 m)."""
    db, s = landing
    soft = screening_grid(db, s, [7.0], [180.0, 135.0, 90.0]).Hs[0]
    rigid = screening_grid(db, s.replace(shear_stiffness=np.inf), [7.0], [180.0, 135.0, 90.0]).Hs[0]
    assert soft[0] > soft[1] > soft[2]
    assert rigid[1] < soft[1] and rigid[2] < soft[2]
    assert rigid[0] == pytest.approx(soft[0], rel=0.05)                      # head seas: no couple


@pytest.mark.parametrize("bad", [0.0, 1.0, -0.1, 1.5, "often", float("nan")])
def test_accept_outside_0_1_is_refused(bad):
    with pytest.raises(BoatlandInputError, match="accepted probability"):
        accept_probability(bad)


def test_accept_presets_are_table_2_1():
    assert accept_probability("best") == 0.00119
    assert accept_probability("Conservative") == 0.00002
    assert accept_probability("non-conservative") == 0.02681
    assert accept_probability("0.01") == 0.01


def test_fender_point_outside_the_hull_is_refused(landing):
    db, s = landing
    aft = s.replace(points=[[0.0, 0.0, 1.5]], normals=[[-1.0, 0.0, 0.0]])
    with pytest.raises(BoatlandInputError, match=r"fender.points\[0\].*outside the bow"):
        aft.check_on_hull(db, "my.toml")
    wide = s.replace(points=[[12.3, 9.0, 1.5]], normals=[[-1.0, 0.0, 0.0]])
    with pytest.raises(BoatlandInputError, match="my.toml"):
        wide.check_on_hull(db, "my.toml")


def test_bad_setup_values_are_refused():
    with pytest.raises(BoatlandInputError, match="mu"):
        LandingSetup(points=[[12.3, 0, 1.5]], normals=[[-1, 0, 0]], mu=-0.2, thrust=8e4)
    with pytest.raises(BoatlandInputError, match="thrust"):
        LandingSetup(points=[[12.3, 0, 1.5]], normals=[[-1, 0, 0]], mu=0.6, thrust=0.0)
    db = load_builtin("ctv24")
    s = LandingSetup(points=[[12.3, 0, 1.5]], normals=[[-1, 0, 0]], mu=0.6, thrust=8e4)
    with pytest.raises(BoatlandInputError, match="statistics"):
        screening_grid(db, s, [8.0], [180.0], statistics="gumbel")


@pytest.mark.slow
def test_sea_response_adds_the_wave_systems(landing):
    """Grøtting 2015 eq. 3.41–3.45: a swell and a wind sea from different directions add their spectral
    integrals; one long-crested part is the screening grid's cell scaled by Hs²; a very narrow cos-2s
    spreading tends to the long-crested sea. Every response — each contact's four margins and roll (free
    on the rubber fender) — to rtol 1e-10."""
    from boatland.freqdomain import sea_response
    from boatland.sea.spectra import SpectrumPart

    db, s = landing
    swell = SpectrumPart(Hs=0.15, Tp=12.0, gamma=5.0, direction_deg=150.0)
    wind = SpectrumPart(Hs=0.12, Tp=5.0, direction_deg=200.0)
    both = sea_response(db, s, [swell, wind])
    one = [sea_response(db, s, [p]) for p in (swell, wind)]
    assert both.m.shape == (9, 3) and both.sigma[-1] > 0                   # roll is not locked
    np.testing.assert_allclose(both.m, one[0].m + one[1].m, rtol=1e-10)
    assert both.cycle_period == 12.0 and 1 > both.p_access > max(o.p_access for o in one)
    tr = slip_transfer(db, s, beta_deg=[150.0])
    m, _ = spectral_moments(tr, [12.0], sea=swell)
    np.testing.assert_allclose(one[0].m, 0.15 ** 2 * m[0, 0], rtol=1e-10)
    narrow = sea_response(db, s, [SpectrumPart(Hs=0.15, Tp=12.0, gamma=5.0, direction_deg=150.0, spreading=2000.0)],
                          spreading_step_deg=0.5)
    np.testing.assert_allclose(narrow.sigma, one[0].sigma, rtol=0.01)


@pytest.mark.slow
def test_pile_wave_on_the_columns_the_directions_read_gives_the_same_excitation(landing):
    """The screening adds the pile's scattered wave only to the columns of the table that the interpolation
    at its directions reads (issue 16: 3 of 72 directions of the ctv24 mesh instead of all): the excitation
    there is the whole table's to the bit — on a tabulated direction, between two and across 360°."""
    from boatland.freqdomain.rao import excitation_force

    db, s = landing
    db = db.replace()                           # a database of its own: no table made for it yet
    assert s.pile is not None and db.n_dir == 72
    betas = ([180.0], [37.3], [357.5, 2.5, 90.0])
    parts = [s.near_pile(db, beta) for beta in betas]          # made before the whole table: their columns only
    full = s.near_pile(db)
    w = np.linspace(0.3, 3.0, 40)
    for beta, part in zip(betas, parts):
        changed = np.flatnonzero(np.any(part.X != db.X, axis=(0, 2)))
        assert 1 <= changed.size <= 2 * len(beta)                     # only the brackets' columns
        assert np.array_equal(excitation_force(part, w, beta), excitation_force(full, w, beta))
    # once a table of more columns exists it serves fewer (the values are the same to the bit, above)
    assert s.near_pile(db, [200.0]) is full and s.near_pile(db, [11.0, 300.0]) is full


def test_slip_directions_follow_the_friction_circle():
    """boatland.freqdomain.screening.slip_directions: without a tangential static load the four modes are
    ±e_z and ±s (Grøtting 2015 eq. 3.13–3.24); with a side load F_p across a mode its direction is the
    circle's tangent where |J_t| = μN at that side load — so the mode's capacity is the exact distance to the
    circle along it, and the margin is zero at the design point."""
    from boatland.freqdomain.screening import slip_directions

    n = np.array([1.0, 0.0, 0.0])                  # the contact's normal, landing → vessel
    mu, N = 0.8, 100e3
    plain = slip_directions(n)
    assert np.array_equal(slip_directions(n, N * n, mu), plain)     # normal load only: exactly Grøtting's
    s = plain[3]
    F_p = 30e3
    J0 = N * n + F_p * s                           # pushed on (n: landing → vessel), 30 kN sideways
    d = slip_directions(n, J0, mu)
    assert np.allclose(np.linalg.norm(d, axis=1), 1.0) and np.allclose(d @ n, 0.0)
    assert np.array_equal(d[2:], plain[2:])        # the side modes: no vertical load across them
    for m in (0, 1):                               # up and down: tilted towards the side load
        v = np.sqrt((mu * N) ** 2 - F_p ** 2)
        point = v * plain[m] + F_p * s             # where the circle is reached at that side load
        assert np.linalg.norm(point) == pytest.approx(mu * N)
        assert d[m] @ point == pytest.approx(mu * N)               # the tangent touches the circle there
        assert mu * N - d[m] @ J0 < mu * N - plain[m] @ J0         # less capacity than the square's
