"""Free RAOs with and without the monopile's scattered wave (San Nicolás Méndez 2024 §5.1, Figs. 5.4–5.12).

Near the turbine the vessel does not feel the open sea: :func:`rao_with_pile` adds the Froude–Krylov
force of the pile's scattered wave (:func:`boatland.sea.pile.pile_scattered_excitation`)
to the database's excitation and solves the free RAO (San Nicolás Méndez 2024 eq. 3.31) both ways. The vessel's own
scattering of the pile's wave is neglected, as in San Nicolás Méndez 2024.
"""

from __future__ import annotations

from boatland.freqdomain.rao import free_rao
from boatland.vessel.database import HydroDB
from boatland.sea.pile import pile_scattered_excitation

__all__ = ["rao_with_pile", "COMPARE_HEADINGS"]

#: Relative wave directions of San Nicolás Méndez 2024's comparison [deg] (0 = following, 180 = head seas).
COMPARE_HEADINGS = (0.0, 45.0, 90.0, 135.0, 180.0)


def rao_with_pile(db: HydroDB, omega, position, heading_deg: float, pile_radius: float,
                  water_depth: float | None = None, betas=COMPARE_HEADINGS, additional_damping=None):
    """Free RAOs (Nω, Nβ, 6) in the open sea and beside the pile.

    Parameters
    ----------
    db : HydroDB
        With a hull mesh.
    omega : array_like
        Frequencies [rad/s] within the database's band.
    position : (x, y)
        Mean position of the reference point relative to the pile axis, global frame [m].
    heading_deg : float
        Heading of the bow, global frame [deg].
    pile_radius : float
    water_depth : float, optional
        Default the database's.
    betas : sequence of float
        Relative wave directions [deg].

    Returns
    -------
    open_sea, with_pile : ndarray of complex, shape (Nω, Nβ, 6)
    """
    Xs = pile_scattered_excitation(db, position, heading_deg, pile_radius, water_depth)
    near = db.replace(X=db.X + Xs)
    kw = dict(additional_damping=additional_damping)
    return free_rao(db, omega, list(betas), **kw), free_rao(near, omega, list(betas), **kw)
