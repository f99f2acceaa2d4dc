"""Frequency-domain RAOs on databases that do not tabulate the whole circle (boatland.freqdomain.rao)."""

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.freqdomain import excitation_force, hinged_rao, screening_grid
from boatland.hydro.builtin import load_builtin


@pytest.fixture(scope="module")
def dbs():
    full = load_builtin("ctv24")
    keep = np.flatnonzero(full.wave_dir_deg <= 180.0)
    half = full.replace(X=full.X[:, keep], wave_dir_deg=full.wave_dir_deg[keep])
    X = half.X.copy()
    X[5, 0, :] += 0.02 * np.abs(X[3:]).max()  # a yaw moment in following seas: not symmetric
    return full, half, half.replace(X=X)


def test_hinged_rao_of_the_half_database_equals_the_twin(dbs, landing):
    full, half, _ = dbs
    _, setup = landing
    w = np.linspace(0.3, 3.0, 25)
    kw = dict(beta_deg=[200.0, 270.0, 330.0], normal=setup.normals, stiffness=setup.stiffness,
              damping=setup.damping, thrust=setup.thrust, thrust_position=setup.thrust_position)
    a, b = hinged_rao(half, w, setup.points, **kw), hinged_rao(full, w, setup.points, **kw)
    assert np.max(np.abs(a.J - b.J)) <= 1e-9 * np.max(np.abs(b.J))


@pytest.mark.slow
def test_asymmetric_half_database_refuses_directions_outside(dbs, landing):
    full, _, asym = dbs
    _, setup = landing
    with pytest.raises(BoatlandInputError, match=r"beta_deg: 270° is outside .*yaw excitation 2e-2 at 0°"):
        excitation_force(asym, 1.0, [90.0, 270.0])
    with pytest.raises(BoatlandInputError, match="225°, 270°, 315° are outside"):
        screening_grid(asym, setup, [6.0], np.arange(0.0, 360.0, 45.0))
    inside = screening_grid(asym, setup, [6.0], [0.0, 90.0, 180.0])
    assert np.all(np.isfinite(inside.Hs))
    assert np.allclose(excitation_force(asym, 1.0, 135.0), excitation_force(full, 1.0, 135.0), rtol=1e-12)
