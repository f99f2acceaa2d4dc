"""The CTV hull (transom, hard chine or round bilge, fine entrance): lines, hydrostatics, panel meshes,
topsides."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from boatland.vessel.ctv_hull import CTVCatamaran
from boatland.vessel.wigley import mesh_volume, panel_normals_areas
from boatland.vessel.files import load_vessel

PARTS = dict(length=25.5, demihull_beam=2.7, draft=1.71, separation=5.87, deadrise_deg=26.0,
             bow_deadrise_deg=55.0, transom_draft=0.65, forefoot_station=0.55, entrance_deg=10.0)


@pytest.fixture(scope="module", params=["chine", "round"])
def hull(request):
    return CTVCatamaran(section=request.param, **PARTS)


def test_lines(hull):
    """Transom breadth and immersion, widest station, entrance half-angle, forefoot to the stem."""
    h = hull
    assert h.waterline_half_breadth(0.0) == pytest.approx(0.9 * 2.7 / 2)
    assert h.waterline_half_breadth(h.max_beam_station) == pytest.approx(2.7 / 2)
    assert h.waterline_half_breadth(1.0) == 0.0 and h.keel_depth(1.0) == 0.0
    assert h.keel_depth(0.0) == pytest.approx(0.65 * 1.71) and h.keel_depth(0.45) == pytest.approx(1.71)
    eps = 1e-7
    slope = (h.waterline_half_breadth(1.0 - eps) - h.waterline_half_breadth(1.0)) / (eps * h.length)
    assert math.degrees(math.atan(slope)) == pytest.approx(10.0, rel=1e-4)
    # sections: the keel on the centreline, the waterline breadth at the top
    for xi in (0.0, 0.2, 0.5, 0.8):
        d = h.keel_depth(xi)
        assert h.section_half_breadth(xi, 0.0) == pytest.approx(0.0, abs=1e-12)
        assert h.section_half_breadth(xi, d) == pytest.approx(h.waterline_half_breadth(xi))


def test_chine_is_a_corner_with_the_deadrise():
    h = CTVCatamaran(section="chine", **PARTS)
    xi = h.max_beam_station
    yc, hc = (float(v) for v in h.chine(xi))
    assert math.degrees(math.atan(hc / yc)) == pytest.approx(26.0)
    assert yc == pytest.approx(0.95 * 2.7 / 2)
    below = h.section_half_breadth(xi, 0.5 * hc) / (0.5 * hc)
    above = (h.section_half_breadth(xi, hc + 0.01) - yc) / 0.01
    assert below == pytest.approx(1 / math.tan(math.radians(26.0)))
    assert above < 0.2 * below                     # the side is much steeper than the bottom


def test_hydrostatics_against_scipy_quadrature(hull):
    """Volume, centre of buoyancy and waterplane of the Gauss quadrature vs scipy's adaptive one."""
    h = hull
    L, s2 = h.length, h.separation / 2

    def area(x):      # closed form (test_section_area_closed_form checks it against quad)
        return float(h.section_area(x / L + 0.5))

    def zmom(x):
        xi = x / L + 0.5
        d = float(h.keel_depth(xi))
        kink = [float(h.chine(xi)[1])] if h.section == "chine" else None
        return 2 * integrate.quad(lambda hh: (hh - d) * float(h.section_half_breadth(xi, hh)), 0.0, d,
                                  points=kink, limit=100, epsrel=1e-8)[0] if d > 0 else 0

    brk = [(b - 0.5) * L for b in (h.keel_station, h.max_beam_station, h.forefoot_station)]
    opts = dict(points=brk, limit=200, epsrel=1e-9)
    V = 2 * integrate.quad(area, -L / 2, L / 2, **opts)[0]
    hs = h.hydrostatics()
    assert hs.volume == pytest.approx(V, rel=1e-6)
    assert hs.cob[0] == pytest.approx(2 * integrate.quad(lambda x: x * area(x), -L / 2, L / 2, **opts)[0] / V, rel=1e-6)
    assert hs.cob[2] == pytest.approx(2 * integrate.quad(zmom, -L / 2, L / 2, points=brk, limit=50,
                                                         epsrel=1e-6)[0] / V, rel=1e-5)
    eta = lambda x: float(h.waterline_half_breadth(x / L + 0.5))  # noqa: E731
    awp = 2 * integrate.quad(lambda x: 2 * eta(x), -L / 2, L / 2, **opts)[0]
    assert hs.waterplane_area == pytest.approx(awp, rel=1e-8)
    assert hs.lcf == pytest.approx(2 * integrate.quad(lambda x: 2 * x * eta(x), -L / 2, L / 2, **opts)[0] / awp,
                                   rel=1e-8)
    i_t = 2 * integrate.quad(lambda x: ((s2 + eta(x)) ** 3 - (s2 - eta(x)) ** 3) / 3, -L / 2, L / 2, **opts)[0]
    assert hs.i_t == pytest.approx(i_t, rel=1e-8)
    # a transom stern: the waterplane and the buoyancy lie aft of midship
    assert hs.lcf < 0 and hs.cob[0] < 0


def test_section_area_closed_form(hull):
    for xi in (0.1, 0.35, 0.7, 0.95):
        d = float(hull.keel_depth(xi))
        num = 2 * integrate.quad(lambda hh: float(hull.section_half_breadth(xi, hh)), 0.0, d, limit=200)[0]
        assert float(hull.section_area(xi)) == pytest.approx(num, rel=1e-7)


def test_restoring_couples_heave_and_pitch(hull):
    """The waterplane's first moment couples heave and pitch (C35 = −ρ g ∫x dA ≠ 0), unlike the Wigley's."""
    hs = hull.hydrostatics()
    C = hull.restoring(1025.0, 9.81, 1025.0 * hs.volume, (hs.cob[0], 0.0, 1.29))
    assert C[2, 4] == C[4, 2] == pytest.approx(-1025 * 9.81 * hs.lcf * hs.waterplane_area)
    assert C[2, 4] > 0                          # LCF aft: bow-down pitch lifts... (x < 0 half wider)
    assert C[3, 5] == pytest.approx(0.0, abs=1e-6 * C[3, 3])   # CoG above CoB: no roll–yaw weight coupling


@pytest.mark.parametrize("size", [0.7, 0.4])
def test_panel_mesh_is_the_hull(hull, size):
    """Closed by the waterplane, the panels enclose the quadrature's volume (chords lose a little), their
    normals point out (Gauss: ∮ x n_x dS = ∇), the waterplane they close is A_wp, and no panel edge is
    longer than asked. Measured volume loss: chine 0.06 % (0.7 m) and 0.02 % (0.4 m); round bilge 2.3 % and
    0.7 % (the chords of the bilge)."""
    counts = hull.panel_counts(size)
    m = hull.mesh(counts)
    n, a, c = panel_normals_areas(m.vertices, m.faces)
    hs = hull.hydrostatics()
    tol = {("chine", 0.7): 0.001, ("chine", 0.4): 0.0005, ("round", 0.7): 0.025, ("round", 0.4): 0.008}[
        (hull.section, size)]
    assert mesh_volume(m.vertices, m.faces) == pytest.approx(hs.volume, rel=tol)
    assert np.sum(c[:, 0] * n[:, 0] * a) == pytest.approx(hs.volume, rel=tol)
    assert -np.sum(n[:, 2] * a) == pytest.approx(hs.waterplane_area, rel=1e-3)
    assert np.all(m.vertices[:, 2] <= 1e-12) and m.vertices[:, 0].min() == pytest.approx(-hull.length / 2)
    f = m.faces
    v = m.vertices
    edges = np.linalg.norm(v[f] - v[np.roll(f, -1, axis=1)], axis=2)
    assert edges.max() <= size * 1.05
    # port–starboard mirror image
    assert np.allclose(np.sort(v[:, 1]), np.sort(-v[:, 1]))


def test_half_mesh(hull):
    counts = hull.panel_counts(0.5)
    v, f = hull.half_panels(counts)
    assert np.all(v[:, 1] > 0)
    transom = np.all(np.isclose(v[f][:, :, 0], -hull.length / 2), axis=1)
    n, a, _ = panel_normals_areas(v, f)
    assert transom.sum() >= counts.n_transom and np.allclose(n[transom & (a > 0), 0], -1.0)


def test_topsides_for_the_viewers():
    h = CTVCatamaran(section="chine", **PARTS, freeboard=2.4, tunnel_height=1.4, flare_deg=5.0, stem_rake_deg=20.0,
                     deckhouse=(-9.5, 0.5, 6.5, 2.6))
    top = h.topsides()
    v = top.vertices
    assert v[:, 2].min() == pytest.approx(0.0) and v[:, 2].max() == pytest.approx(2.4 + 2.6)
    assert 2 * v[:, 1].max() == pytest.approx(h.deck_beam) == pytest.approx(8.99, abs=0.005)
    assert v[:, 0].max() == pytest.approx(h.stem_at(2.4)) and h.stem_at(0.0) == 12.75
    assert top.n_panels > 300


def test_bad_form_parameters():
    with pytest.raises(ValueError, match="entrance_deg"):
        CTVCatamaran(**{**PARTS, "entrance_deg": 3.5})
    with pytest.raises(ValueError, match="tunnel_height"):
        CTVCatamaran(**PARTS, freeboard=1.0, tunnel_height=1.5)
    with pytest.raises(ValueError, match="section"):
        CTVCatamaran(**PARTS, section="flat")


def test_shipped_ctv27_vessel_file():
    """The default vessel's particulars (scenarios/vessels/ctv27.toml): [IC]'s 26.97 m × 8.99 m × 1.71 m."""
    spec = load_vessel("scenarios/vessels/ctv27.toml")
    h = spec.hull
    assert isinstance(h, CTVCatamaran) and spec.form == "ctv"
    assert h.deck_beam == pytest.approx(8.99, abs=0.005) and h.draft == 1.71
    # deck-level stem (raked) plus a 0.4 m fender: 26.77 m, 0.2 m short of the published 26.97 m overall
    # (waterjet buckets and transom fittings aft of the transom are not modelled)
    assert h.stem_at(2.4) + 0.4 - (-h.length / 2) == pytest.approx(26.97, rel=0.01)
    assert spec.total_mass == pytest.approx(1025 * h.volume) and 125e3 < spec.total_mass < 140e3
    assert spec.cog[0] == pytest.approx(h.centre_of_buoyancy[0])
    assert spec.panels_per_wavelength() >= 5.5
