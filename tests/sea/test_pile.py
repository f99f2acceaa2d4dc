"""Scattered-wave excitation of the hull near a monopile (boatland.sea.pile)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from boatland.conventions import PORT_STARBOARD_SIGN
from boatland.errors import BoatlandInputError
from boatland.hydro.builtin import load_builtin
from boatland.sea.pile import (hull_panels_global, pile_scattered_components,
                                             pile_scattered_excitation)

A_PILE = 3.25  # 6.5 m monopile
BOW_AT_PILE = (-(A_PILE + 1.0 + 12.0), 0.0)  # heading 0: bow 1 m off the pile wall


@pytest.fixture(scope="module")
def ctv():
    db = load_builtin("ctv24")
    keep = [0, 9, 18, 27, 36, 45, 54, 63]  # 0, 45, ..., 315°
    return db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep])


def test_shape_and_layout(ctv):
    Xs = pile_scattered_excitation(ctv, BOW_AT_PILE, 0.0, A_PILE)
    assert Xs.shape == ctv.X.shape and Xs.dtype == complex
    assert np.all(np.isfinite(Xs))


def test_incident_froude_krylov_matches_database(ctv):
    """Same panels, incident pressure: the open-sea Froude–Krylov force. Long waves: heave → C33
    (in phase with the crest), pitch as the BEM's X5; independent of where the vessel is and how
    it is turned (referred to the incident elevation at the reference point, database directions
    relative to the vessel)."""
    Xa = pile_scattered_excitation(ctv, (-30.0, 10.0), 25.0, A_PILE, part="incident")
    Xb = pile_scattered_excitation(ctv, (40.0, -70.0), -110.0, A_PILE, part="incident")
    np.testing.assert_allclose(Xa, Xb, atol=1e-6 * np.abs(Xa).max())
    np.testing.assert_allclose(Xa[2, :, 0], ctv.C[2, 2], rtol=1e-3)
    np.testing.assert_allclose(Xa[4, 4, :3], ctv.X[4, 4, :3], rtol=0.03)  # head seas, pitch
    assert abs(np.angle(Xa[0, 0, 5]) - math.pi / 2) < 1e-6  # surge leads the crest by 90° (β = 0)


def test_port_starboard_mirror(ctv):
    """Mirror the layout in the global xz plane: X_s,i(y0 → −y0, ψ → −ψ, β → −β) = s_i X_s,i."""
    X1 = pile_scattered_excitation(ctv, (-18.0, 6.0), 20.0, A_PILE)
    X2 = pile_scattered_excitation(ctv, (-18.0, -6.0), -20.0, A_PILE)
    mirror = [0, 7, 6, 5, 4, 3, 2, 1]  # index of −β in 0, 45, ..., 315
    np.testing.assert_allclose(X2[:, mirror], PORT_STARBOARD_SIGN[:, None, None] * X1,
                               atol=1e-9 * np.abs(X1).max())


def test_on_axis_no_transverse_force(ctv):
    """Vessel on the wave's axis through the pile (β = 0, 180°): no sway, roll or yaw."""
    Xs = pile_scattered_excitation(ctv, BOW_AT_PILE, 0.0, A_PILE)
    big = np.abs(Xs[[0, 2, 4]]).max()
    assert np.abs(Xs[[1, 3, 5]][:, [0, 4]]).max() < 1e-9 * big


def test_long_waves_small_and_short_waves_shadowed(ctv):
    """ka → 0: the pile barely scatters; heave correction < 0.1 % of C33 at the lowest ω."""
    Xs = pile_scattered_excitation(ctv, BOW_AT_PILE, 0.0, A_PILE)
    assert np.abs(Xs[2, :, 0]).max() < 1e-3 * ctv.C[2, 2]


def test_global_panels(ctv):
    c = hull_panels_global(ctv, (10.0, 5.0), 90.0)
    assert c.shape == (ctv.mesh.n_panels, 3)
    # bow (body x = 12) points to global +y
    assert c[:, 1].max() == pytest.approx(5.0 + 12.0, abs=0.3)
    assert c[:, 2].max() <= 0.0


@pytest.mark.parametrize("kwargs, match", [
    (dict(pile_radius=0.0), "diameter must be > 0"),
    (dict(pile_radius=-1.0), "diameter must be > 0"),
    (dict(pile_radius=float("nan")), "diameter must be > 0"),
    (dict(position=(-10.0, 0.0)), "inside the monopile"),
    (dict(water_depth=1.0), "deeper than the water depth"),
    (dict(water_depth=0.0), "water depth must be > 0"),
    (dict(position=(1.0,)), "two finite numbers"),
])
def test_bad_input(ctv, kwargs, match):
    args = dict(position=BOW_AT_PILE, heading_deg=0.0, pile_radius=A_PILE)
    args.update(kwargs)
    with pytest.raises(BoatlandInputError, match=match) as e:
        pile_scattered_excitation(ctv, **args)
    assert "\n" not in str(e.value)


def test_no_mesh(ctv):
    with pytest.raises(BoatlandInputError, match="no hull mesh") as e:
        pile_scattered_excitation(ctv.replace(mesh=None), BOW_AT_PILE, 0.0, A_PILE)
    assert "\n" not in str(e.value)


def test_finite_depth_runs(ctv):
    """Finite depth (h = 25 m) differs little from deep water for these waves at ka ≥ 0.3
    (kh > 2.3), but is not identical."""
    Xd = pile_scattered_excitation(ctv, BOW_AT_PILE, 0.0, A_PILE)
    Xh = pile_scattered_excitation(ctv, BOW_AT_PILE, 0.0, A_PILE, water_depth=25.0)
    assert not np.allclose(Xd, Xh)
    hi = ctv.omega > 1.0
    np.testing.assert_allclose(Xh[:, :, hi], Xd[:, :, hi], atol=0.02 * np.abs(Xd).max())


def test_components_equal_grid_values(ctv):
    """Per-component X_s (ω_i, θ_i) = the grid X_s where the component sits on the grid (θ = β + ψ)."""
    psi = 30.0
    pos = (-15.0, -6.0)
    Xg = pile_scattered_excitation(ctv, pos, psi, A_PILE)
    fi = np.array([3, 20, 40, 60, 3])
    bi = np.array([0, 4, 7, 2, 5])
    Xc = pile_scattered_components(ctv, pos, psi, A_PILE, ctv.omega[fi], np.radians(ctv.wave_dir_deg[bi] + psi))
    assert Xc.shape == (6, fi.size)
    np.testing.assert_allclose(Xc, Xg[:, bi, fi], atol=1e-9 * np.abs(Xg).max())


@pytest.mark.slow
def test_scattered_tables_are_keyed_by_content_and_serve_another_process(ctv, monkeypatch):
    """A table made in one process (pickled as to a campaign worker) serves another database object of the
    same content there, bit for bit, without being made again; another layout is another table."""
    import pickle

    import boatland.sea.pile as pd

    monkeypatch.setattr(pd, "_TABLES", {})
    theta = np.radians([180.0, 135.0])
    om, th = np.linspace(0.3, 2.5, 50), np.repeat(theta, 25)
    tables = pd.scattered_tables(ctv, BOW_AT_PILE, 0.0, A_PILE, theta)
    assert len(tables) == 2
    made = pd.pile_scattered_interpolated(ctv, BOW_AT_PILE, 0.0, A_PILE, om, th)

    def made_again(*args, **kwargs):
        raise AssertionError("made again")

    monkeypatch.setattr(pd, "_TABLES", {})
    pd.remember_tables(pickle.loads(pickle.dumps(tables)))
    monkeypatch.setattr(pd, "_scattered_columns", made_again)
    twin = ctv.replace(X=ctv.X.copy())                               # another object, the same content
    assert pd.pile_scattered_interpolated(twin, BOW_AT_PILE, 0.0, A_PILE, om, th).tobytes() == made.tobytes()
    assert pd.pile_table_key(twin, BOW_AT_PILE, 0.0, A_PILE, float(np.unique(theta)[0])) == tables[0].key
    with pytest.raises(AssertionError, match="made again"):
        pd.pile_scattered_interpolated(ctv, (BOW_AT_PILE[0] - 1.0, 0.0), 0.0, A_PILE, om, th)


@pytest.mark.slow
def test_the_directions_of_a_layout_are_made_together_each_as_if_made_alone(ctv, monkeypatch, tmp_path):
    """make_tables (a campaign's cases) makes every distinct table once, the directions of one layout in
    passes of at most TABLE_BATCH (the Hankel functions and the series shared); each table is the one the
    exact per-component sum gives on its grid (as the tables were made before issue 16), bit for bit. (An
    empty disk cache: the making is what is counted.)"""
    import boatland.sea.pile as pd
    from boatland.waves.dispersion import wavenumber

    monkeypatch.setenv("BOATLAND_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(pd, "_TABLES", {})
    monkeypatch.setattr(pd, "TABLE_BATCH", 2)
    passes = []
    columns = pd._scattered_columns

    def counted(db, layout, k, thetas):
        passes.append(len(thetas))
        return columns(db, layout, k, thetas)

    monkeypatch.setattr(pd, "_scattered_columns", counted)
    aside = (BOW_AT_PILE[0] - 1.0, 2.0)
    requests = [pd.TableRequest(BOW_AT_PILE, 0.0, A_PILE, np.radians([180.0, 135.0, 180.0])),
                pd.TableRequest(BOW_AT_PILE, 0.0, A_PILE, np.radians([90.0])),
                pd.TableRequest(aside, 0.0, A_PILE, np.radians([135.0]))]
    tables = pd.make_tables(ctv, requests)
    assert len(tables) == 4 and passes == [2, 1, 1]
    for table in tables:
        position, theta = (table.key[3], table.key[4]), table.key[-1]
        grid = table.grid
        exact = pile_scattered_components(ctv, position, 0.0, A_PILE, grid, np.full(grid.size, theta))
        h = pd._table_layout(ctv, position, 0.0, A_PILE, None).h
        expected = exact * np.exp(-1j * wavenumber(grid, h, ctv.g) * table.d)[None, :]
        assert table.reduced.tobytes() == expected.tobytes()
    assert pd.make_tables(ctv, requests[:1]) == tables[1:3] and passes == [2, 1, 1]     # kept: not made again
