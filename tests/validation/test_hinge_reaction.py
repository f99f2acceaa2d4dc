"""Time domain against frequency domain: the stuck fender's force is the reaction of the vessel held at
its fender point in the frequency domain (Grøtting 2015 §3.2.1, eq. 3.1–3.12, after Wu 2014) — for the
rigid stick (Ferreira González 2023) the hinge's, for the compliant rubber (Grøtting 2015 §3.2.2) that of
its shear spring and damper — and the compliant force tends to the rigid one as k_t grows.

Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis,
NTNU; Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of
Boatlanding Maneuvers*, Dr.-Ing. dissertation, TU Hamburg.

Frequency domain (:func:`boatland.freqdomain.hinged_rao`): the vessel pinned at the fender point in
the two tangential directions of the contact plane, the normal on the fender's linear spring–damper
(k_n, d_n), linearised about the static equilibrium under the thrust:

.. math::
    \\begin{bmatrix} Z - K_g + (k_n + i\\omega d_n) G^\\top n n^\\top G & -G^\\top T \\\\ T^\\top G & 0 \\end{bmatrix}
    \\begin{bmatrix} \\hat x \\\\ \\hat\\lambda \\end{bmatrix} = \\begin{bmatrix} X \\\\ 0 \\end{bmatrix},
    \\qquad Z = -\\omega^2 (M + A) + i\\omega B + C,

reaction on the vessel :math:`\\hat J = T\\hat\\lambda - (k_n + i\\omega d_n)\\, n n^\\top G \\hat x`;
:math:`K_g` is the stiffness of the preload (the thrust follows the vessel's x axis, Grøtting 2015 §3.4
eq. 3.62–3.63; the static contact forces turn their moments with the vessel).

Time domain (:func:`boatland.trial.simulate.simulate`): ctv24, one bow fender line (1 m wide, centred
at (12.3, 0, 1.5) m) on one vertical tube of 0.35 m, c_f 1 MN/m, d_f 40 kN s/m, μ_s = μ_k = 2 and
k_v = 0 so it never slips, 80 kN thrust at (−10.5, 0, −0.9) m (ramped over 20 s, then the waves are
ramped in over 2 T); the rubber rigid (Ferreira González 2023) or compliant (k_t 3 MN/m, 5 % of
critical damping; Grøtting 2015 §3.2.2). Regular waves H = 0.1 m (a = 0.05 m, linear): the contact
stays stuck and closed.

Measured: the first harmonic of ``fn`` (its mean, the preload, is fitted out) and of the tangential
forces ``ft`` (vertical, horizontal) over the last 10 periods, least squares c₀ + c₁t + Re{ĉ e^{iωt}},
against a·e^{i(φ − k·x₀)}·Ĵ in the contact axes (the wave's phase at the reference point's start
position). Tolerance 2 % in amplitude and 2° in phase.

Head seas (T = 5, 7, 9 s), 40 s radiation memory: rigid within 0.071 % and 0.05°, compliant within
0.093 % and 0.06° for the normal and the vertical force; the horizontal one is zero by symmetry in both.
The static preload (mean normal and vertical force) agrees within 0.05 % (0.042 %). Without K_g (the linear
hinge of Grøtting 2015 §3.2.1 alone) the vertical force is off by up to −2.85 % / 1.4°: the follower
thrust's −T θ₅ is not negligible at 80 kN.

Bow-quartering seas (150°, T = 5, 7, 9 s) with the horizontal force: rigid within 1.58 % and 0.50°,
compliant within 1.70 % and 0.51° (2026-12-03, the rebuilt ctv24; 0.98 % / 1.10 % on the database whose lid met
the hull), with three conditions the test states. (i) 120 s radiation memory:
sway, roll and yaw K(t) decay slowly, and at 40 s the truncated memory leaves B₂₂ 22 % low and B₆₆ of
the wrong sign at 0.9 rad/s. (ii) 1 MN m s/rad extra linear yaw damping in both domains: a single
contact leaves yaw about it neutral (the follower thrust passes through it), so the start-up sets the
vessel yawing slowly (0.04° over 300 s), which the linearisation about zero yaw does not see. (iii) The
fender's face turns with the vessel's yaw, so its static normal force is a follower force too
(:meth:`boatland.landing.law.ContactLaw.geometric_stiffness`; without it the compliant horizontal force
is 8 % off). A point fender on the round tube instead drifts 2.3 cm sideways in 300 s here, which tilts
its normal by 14° on a tube compressed to 9.5 cm radius — far outside the linear model, so the shipped
scenarios use fender lines.
"""

import numpy as np
import pytest

from boatland.freqdomain import first_harmonic
from boatland.hydro.builtin import load_builtin
from boatland.trial.simulate import simulate
from boatland.validation.hinge import AMPLITUDE_TOL, PERIODS, PHASE_TOL_DEG, bow_quartering, compare_hinge, head_seas

# The scenarios and the comparison are boatland.validation.hinge's: `boatland validate` runs the same code.


@pytest.fixture(scope="module")
def ctv24():
    return load_builtin("ctv24")


def compare(db, s):
    """Time-domain first harmonics and frequency-domain reactions of (fn, ft_vertical, ft_horizontal)."""
    c = compare_hinge(db, s)
    # linear stuck case: stuck and closed throughout the fitted window, the stick force is `needed`
    assert c.stuck and c.closed and c.needed_is_ft
    return c.td, c.fd, c.static_td, c.static_fd


def assert_close(td, fd, what):
    err = abs(td) / abs(fd) - 1
    dphase = np.degrees(np.angle(td / fd))
    assert abs(err) < AMPLITUDE_TOL and abs(dphase) < PHASE_TOL_DEG, \
        f"{what}: TD {abs(td):.1f} N, FD {abs(fd):.1f} N ({100 * err:+.2f} %), phase {dphase:+.2f}°"


SHEARS = ["rigid", 3.0e6]


@pytest.mark.parametrize("shear", SHEARS)
@pytest.mark.parametrize("T", [5.0, 7.0, 9.0])
def test_stick_force_is_hinge_reaction_head_seas(ctv24, T, shear):
    td, fd, static_td, static_fd = compare(ctv24, head_seas(T, shear))
    assert_close(td[0], fd[0], "normal force")
    assert_close(td[1], fd[1], "vertical stick force")
    # head seas on the centreline: no horizontal reaction in either domain
    assert abs(td[2]) < 1e-9 * abs(td[1]) and abs(fd[2]) < 1e-9 * abs(fd[1])
    # the preload the frequency domain is linearised about: normal = thrust, vertical ≈ Grøtting 2015 eq. 3.61
    np.testing.assert_allclose(static_td, static_fd, rtol=2e-3)


@pytest.mark.parametrize("shear", SHEARS)
@pytest.mark.parametrize("T", [5.0, 7.0, 9.0])
def test_stick_force_is_hinge_reaction_bow_quartering(ctv24, T, shear):
    td, fd, _, _ = compare(ctv24, bow_quartering(T, shear))
    for c, what in enumerate(("normal force", "vertical stick force", "horizontal stick force")):
        assert_close(td[c], fd[c], what)


@pytest.mark.slow
def test_a_stiff_rubber_tends_to_the_rigid_stick(ctv24):
    """Bow-quartering seas, T = 7 s: the time domain's stuck forces (first harmonics: normal, vertical,
    horizontal) with the rubber 10× and 100× as stiff in shear as the default (3 MN/m) against the rigid
    stick's. The default time step rule resolves each (dt ≤ T_shear/8: 0.024 s, 0.0076 s). Measured: 10×
    within 0.34 %, 100× within 0.05 %."""
    runs = {}
    for shear in ("rigid", 3.0e7, 3.0e8):
        s = bow_quartering(7.0, shear)
        r = simulate(s, ctv24)
        w = s.sea.waves.omega
        runs[shear] = np.array([first_harmonic(r.t, y, w, PERIODS) for y in (r.fn[:, 0], r.ft[:, 0, 0], r.ft[:, 0, 1])])
    err10 = np.abs(runs[3.0e7] / runs["rigid"] - 1)
    err100 = np.abs(runs[3.0e8] / runs["rigid"] - 1)
    assert np.all(err100 < 0.01), err100
    assert np.all(err100 < err10)
