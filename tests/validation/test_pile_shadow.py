"""The monopile's scattered wave on the CTV: shadow and fading with distance.

References
----------
- San Nicolás Méndez (2024) (DTU thesis) §5.1, Fig. 5.4: with the ship behind the cylinder (in its shadow) the
  scattered wave field lowers the heave and pitch RAOs for medium–long waves.
- San Nicolás Méndez (2024) eq. 3.17: the scattered wave is a cylindrical wave, amplitude ∝ (kr)^(-1/2) far away.
"""

from __future__ import annotations

import numpy as np
import pytest

from boatland.freqdomain.rao import free_rao
from boatland.hydro.builtin import load_builtin
from boatland.sea.pile import pile_scattered_excitation
from boatland.waves.spectra import jonswap

A_PILE = 3.25  # 6.5 m monopile
HALF_LENGTH = 12.0


def ref_x(gap):
    """x of the reference point (heading 0, bow towards the pile on the −x side) for a bow-to-wall gap."""
    return -(A_PILE + gap + HALF_LENGTH)


@pytest.fixture(scope="module")
def ctv():
    db = load_builtin("ctv24")
    keep = [0, 9, 18, 27, 36]  # 0, 45, 90, 135, 180° relative to the vessel
    return db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep])


def test_shadow_lowers_heave_and_pitch(ctv):
    """Bow 1 m off the pile, head seas (waves travel −x: the pile is up-wave, the vessel in its
    shadow): heave and pitch RAOs drop for medium–long waves (λ ≈ 17–40 m, ka ≈ 0.5–1.2), while
    very long waves are unchanged (San Nicolás Méndez 2024 §5.1, Fig. 5.4)."""
    Xs = pile_scattered_excitation(ctv, (ref_x(1.0), 0.0), 0.0, A_PILE)
    w = ctv.omega
    R0 = np.abs(free_rao(ctv, w, [180.0])[:, 0])
    R1 = np.abs(free_rao(ctv.replace(X=ctv.X + Xs), w, [180.0])[:, 0])
    band = (w >= 1.2) & (w <= 1.9)
    for dof in (2, 4):
        drop = 1.0 - R1[band, dof].mean() / R0[band, dof].mean()
        assert drop > 0.08, (dof, drop)
        assert np.all(R1[band, dof] <= R0[band, dof] * 1.001), dof
    long = w <= 0.5
    np.testing.assert_allclose(R1[long, 2], R0[long, 2], rtol=0.01)


def test_correction_fades_like_a_cylindrical_wave(ctv):
    """Moving the vessel from 20 to 80 pile diameters (bow-to-wall gap) divides the largest |X_s|
    by √(r80/r20) ≈ 1.9 (the far field of San Nicolás Méndez 2024 eq. 3.17); long waves (ω ≤ 0.5 rad/s) change X by
    < 1 % of max |X| already at 20 D."""
    D = 2 * A_PILE
    Xn = {n: pile_scattered_excitation(ctv, (ref_x(n * D), 0.0), 0.0, A_PILE) for n in (20, 80)}
    ratio = np.sqrt(abs(ref_x(20 * D)) / abs(ref_x(80 * D)))
    Xmax = np.abs(ctv.X).max(axis=(1, 2))
    for dof in (0, 2, 4):
        got = np.abs(Xn[80][dof]).max() / np.abs(Xn[20][dof]).max()
        assert got == pytest.approx(ratio, rel=0.1), dof
        long = ctv.omega <= 0.5
        assert np.abs(Xn[20][dof][:, long]).max() < 0.01 * Xmax[dof]


def test_significant_response_changes_below_one_percent_at_20_diameters(ctv):
    """At 20 pile diameters the interference of the scattered and incident waves oscillates fast in ω
    and averages out over a sea spectrum: σ of heave and pitch in JONSWAP seas (Hs 1.5 m, Tp 7 and 9 s)
    changes < 1 % in head and following seas (issue 9 check)."""
    w = ctv.omega
    Xs = pile_scattered_excitation(ctv, (ref_x(20 * 2 * A_PILE), 0.0), 0.0, A_PILE)
    R0 = np.abs(free_rao(ctv, w, [0.0, 180.0])) ** 2
    R1 = np.abs(free_rao(ctv.replace(X=ctv.X + Xs), w, [0.0, 180.0])) ** 2
    for Tp in (7.0, 9.0):
        S = jonswap(w, 1.5, Tp)[:, None, None]
        s0 = np.sqrt(np.trapezoid(S * R0, w, axis=0))
        s1 = np.sqrt(np.trapezoid(S * R1, w, axis=0))
        rel = np.abs(s1 / s0 - 1.0)[:, [2, 4]]
        assert rel.max() < 0.01, (Tp, rel)
