"""IRFs: analytic pair, settings, checks that refuse bad input with what to change."""

import numpy as np
import pytest

from boatland.irf.impulse import IRFError, IRFSettings, compute_irf, significant_pairs


def diag_db(w, b33):
    A = np.zeros((6, 6, w.size)); B = np.zeros((6, 6, w.size))
    B[2, 2] = b33
    A[2, 2] = 1.0
    return A, B


@pytest.mark.slow
def test_gaussian_damping_gives_closed_form_kernel():
    """B = b0 ω² exp(−ω²/2s²) (zero at ω = 0, like radiation damping) ↔
    K = (2/π) b0 s³ √(π/2) (1 − s²t²) exp(−s²t²/2) — to 1e-4 of K(0)."""
    s_, b0 = 1.5, 2.0
    w = np.linspace(0.01, 12.0, 1200)
    A, B = diag_db(w, b0 * w ** 2 * np.exp(-w ** 2 / (2 * s_ ** 2)))
    irf = compute_irf(w, A, B, A_inf=np.eye(6), settings=IRFSettings(t_max=10, dt=0.01, tail="none"))
    st2 = (s_ * irf.t) ** 2
    exact = (2 / np.pi) * b0 * s_ ** 3 * np.sqrt(np.pi / 2) * (1 - st2) * np.exp(-st2 / 2)
    assert np.max(np.abs(irf.K[2, 2] - exact)) / exact[0] < 1e-4
    assert irf.err_B[2, 2] < 1e-4
    assert irf.significant[2, 2] and not irf.significant[0, 0]


def test_ogilvie_recovers_a_inf_of_a_consistent_pair():
    """A(ω) made from K by eq. 3.41a with a known A∞: Ogilvie's relation returns that A∞."""
    w = np.linspace(0.05, 30, 600)
    b = w ** 2 * np.exp(-w)          # smooth, B(0) = 0, decays
    from boatland.irf.quadrature import cos_transform, sin_transform
    t = np.linspace(0, 60, 1201)
    K = (2 / np.pi) * cos_transform(np.concatenate([[0], w]), np.concatenate([[0], b]), t)
    A_inf = 3.0
    A33 = A_inf - sin_transform(t, K, w) / w
    A, B = diag_db(w, b)
    A[2, 2] = A33
    irf = compute_irf(w, A, B, A_inf=None, settings=IRFSettings(t_max=60, dt=0.05, tail="none"))
    assert irf.A_inf_source == "ogilvie"
    assert abs(irf.A_inf[2, 2] - A_inf) < 1e-3
    assert any("Ogilvie" in n for n in irf.notes)


def test_significance_in_commensurable_units():
    B = np.zeros((6, 6, 3))
    B[1, 1] = 1e5; B[3, 3] = 4e5; B[1, 3] = B[3, 1] = 1e5; B[5, 5] = 1e-9
    sig = significant_pairs(B, 1e-3, length_scale=2.0)
    assert sig[1, 1] and sig[3, 3] and sig[1, 3] and not sig[5, 5] and not sig[0, 0]


@pytest.mark.parametrize("change, message", [
    (dict(n=6), "only 6 frequencies"),
    (dict(nan=True), "NaN"),
    (dict(zero=True), "radiation damping is zero"),
    (dict(wmax=1.0), r"B\[heave\] at the top of the band .* extend the BEM band"),
    (dict(t_max=1.0), r"K\[heave\] has not decayed by T_K = 1 s .* increase t_max"),
    (dict(dt=0.5), r"dt = 0.5 s is too coarse .* use dt ≤"),
])
def test_bad_input_says_what_to_change(change, message):
    n = change.get("n", 200)
    w = np.linspace(0.05, change.get("wmax", 6.0), n)
    b = w ** 2 * np.exp(-2 * w) * 1e4
    if change.get("zero"):
        b = 0 * w
    if change.get("nan"):
        b[3] = np.nan
    A, B = diag_db(w, b)
    settings = IRFSettings(t_max=change.get("t_max", 30.0), dt=change.get("dt", 0.05), tail="linear")
    with pytest.raises(IRFError, match=message):
        compute_irf(w, A, B, np.eye(6), settings)


def test_asymptotic_tail_accepts_a_short_band_with_a_note():
    w = np.linspace(0.05, 1.5, 100)
    A, B = diag_db(w, w ** 2 * np.exp(-1.5 * w) * 1e4)
    irf = compute_irf(w, A, B, np.eye(6), IRFSettings(t_max=40, dt=0.05, tail="asymptotic"))
    assert any("extrapolated by the asymptotic tail" in n for n in irf.notes)
    assert irf.omega_max_used == pytest.approx(4.5)


def test_auto_tail_is_linear_for_a_decayed_band_and_asymptotic_otherwise():
    w = np.linspace(0.05, 6, 200)
    A, B = diag_db(w, w ** 2 * np.exp(-2 * w) * 1e4)
    assert "tail 'auto' → 'linear'" in compute_irf(w, A, B, np.eye(6), IRFSettings(t_max=30)).notes
    short = w < 1.5
    A, B = diag_db(w[short], (w ** 2 * np.exp(-1.5 * w) * 1e4)[short])
    irf = compute_irf(w[short], A, B, np.eye(6), IRFSettings(t_max=40, dt=0.05))
    assert "tail 'auto' → 'asymptotic'" in irf.notes
    assert any("a wider BEM band avoids that" in n for n in irf.notes)


def test_clip_and_cut_log_negative_damping():
    w = np.linspace(0.05, 6, 200)
    b = w ** 2 * np.exp(-2 * w) * 1e4
    b[-10:] = -0.001 * b.max()
    A, B = diag_db(w, b)
    clipped = compute_irf(w, A, B, np.eye(6), IRFSettings(t_max=30))
    assert any("clipped negative damping B[heave]" in n for n in clipped.notes)
    cut = compute_irf(w, A, B, np.eye(6), IRFSettings(t_max=30, clean="cut"))
    assert any("band cut at" in n for n in cut.notes)


def test_settings_are_validated():
    with pytest.raises(IRFError, match="tail must be one of"):
        IRFSettings(tail="exp")
