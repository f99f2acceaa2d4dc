r"""The limits of a site's sea states from the time domain: a rare-event campaign's table (its store).

The screening predicts the onset of a slip. The incident the field counts — a slide
of tens of centimetres — is judged in the time domain: a rare-event campaign (``method = "isee"`` with an
``accept``) writes its limiting Hs per (Tp, relative direction) to its store (``/isee_limits``).
:class:`LimitsTable` reads it; a sea state's limit is then interpolated linearly in Tp and in direction
between the campaign's cases (its directions mirrored port/starboard when the vessel's database is symmetric;
two table directions more than :data:`MAX_GAP_DEG` apart are not interpolated across), and a sea state outside
the table is *not covered*: counted as not workable, and said. The table is for one spectrum (the campaign's):
a sea state with partitions is judged by its total Hs, Tp and direction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.site.limits import SeaLimits, relative_directions
from boatland.site.weather import Weather

__all__ = ["MAX_GAP_DEG", "LimitsTable", "table_limits"]

#: Two directions of a time-domain limits table further apart than this are not interpolated across [deg]: a
#: quarter of the compass (the shipped rare-event campaigns space their directions 30–45° apart).
MAX_GAP_DEG = 90.0


@dataclass(frozen=True, eq=False)
class LimitsTable:
    """The limiting Hs of a rare-event campaign per (Tp, relative direction) (module docstring).

    Attributes
    ----------
    Tp : ndarray, shape (NT,)
        Peak periods of its cases [s], increasing.
    beta_deg : ndarray, shape (Nβ,)
        Relative directions [deg] in [0, 360), increasing (mirrored ones included).
    Hs : ndarray, shape (NT, Nβ)
        Limiting Hs [m] (NaN: no case there).
    accept, access : float
        Its accepted probability per access and the access [s].
    incident : str
        Its incident definition, e.g. ``"slide > 0.2 m"``.
    name, store : str
        The campaign and its store.
    thrust, mu : float or None
        The push [N] and μ_s it ran.
    mirrored : bool
        Port/starboard mirrored directions were added.
    vessel : str
        The database its scenario names.
    """

    Tp: np.ndarray
    beta_deg: np.ndarray
    Hs: np.ndarray
    accept: float
    access: float
    incident: str
    name: str
    store: str
    thrust: float | None = None
    mu: float | None = None
    mirrored: bool = False
    vessel: str = ""

    @classmethod
    def read(cls, path, *, symmetric: bool | None = None) -> "LimitsTable":
        """Read a rare-event campaign store's ``/isee_limits``. ``symmetric``: mirror its directions port/starboard
        (None: when the database its inputs name is symmetric, :func:`~boatland.vessel.directions.
        port_starboard_symmetry`).

        Raises
        ------
        BoatlandInputError
            Not a store, no limits in it, its limits not over Tp and direction.
        """
        import json

        from boatland.campaign.report import read_store
        from boatland.errors import BoatlandInputError

        data = read_store(path)
        lim = data.get("isee_limits")
        if lim is None or lim.size == 0:
            raise BoatlandInputError(f"{path}: no limiting Hs in this store (a rare-event campaign, method = "
                                     "\"isee\" with an accept in its [isee] table, writes them)")
        fixed = json.loads(data["header"].get("inputs") or "{}")

        def column(key):
            col = f"axis: {key}"
            if col in lim.dtype.names:
                return np.asarray(lim[col], dtype=float)
            v = fixed.get(key.split(".")[-1])
            return np.full(lim.size, np.nan if v is None else float(v))
        T, b = column("sea.Tp"), np.mod(column("sea.relative_direction_deg"), 360.0)
        if not (np.all(np.isfinite(T)) and np.all(np.isfinite(b))):
            raise BoatlandInputError(f"{path}: its limits are not per peak period and relative direction (its "
                                     "campaign sweeps neither sea.Tp nor sea.relative_direction_deg, or holds "
                                     "them in another form)")
        others = [c for c in lim.dtype.names if c.startswith("axis: ") and c not in
                  ("axis: sea.Tp", "axis: sea.relative_direction_deg")
                  and np.unique(np.asarray(lim[c], dtype=float)).size > 1]
        if others:
            raise BoatlandInputError(f"{path}: its campaign sweeps {', '.join(c[6:] for c in others)} besides Tp and "
                                     "direction: one table per setting is needed (a campaign per setting, or one "
                                     "with those held fixed)")
        pairs = np.round(np.c_[T, b], 9)
        if np.unique(pairs, axis=0).shape[0] != pairs.shape[0]:
            raise BoatlandInputError(f"{path}: its limits repeat a (Tp, direction): not one table")
        uT, ub = np.unique(T), np.unique(b)
        H = np.full((uT.size, ub.size), np.nan)
        H[np.searchsorted(uT, T), np.searchsorted(ub, b)] = np.asarray(lim["limiting Hs"], dtype=float)
        if symmetric is None:
            symmetric = _symmetric_vessel(fixed.get("vessel"))
        mirrored = False
        if symmetric:
            mb = np.mod(360.0 - ub, 360.0)
            new = ~np.isin(np.round(mb, 6), np.round(ub, 6))
            if new.any():
                allb = np.concatenate([ub, mb[new]])
                allH = np.concatenate([H, H[:, new]], axis=1)
                order = np.argsort(allb)
                ub, H, mirrored = allb[order], allH[:, order], True
        name = data["plan"].get("name", "") or data["header"].get("campaign", "")
        return cls(Tp=uT, beta_deg=ub, Hs=H, accept=float(lim["accept"][0]),
                   access=float(fixed.get("access") or 1800.0), incident=lim["incident"][0].decode(), name=name,
                   store=str(path), thrust=fixed.get("thrust"), mu=fixed.get("mu_s"), mirrored=mirrored,
                   vessel=str(fixed.get("vessel") or ""))

    def at(self, Tp, beta_deg) -> np.ndarray:
        """The limiting Hs at (Tp, β) (broadcast), linear in Tp and in direction between the cases; NaN outside
        the table (Tp beyond its range, a direction not between two of its directions at most
        :data:`MAX_GAP_DEG` apart)."""
        T = np.asarray(Tp, dtype=float)
        b = np.mod(np.asarray(beta_deg, dtype=float), 360.0)
        T, b = np.broadcast_arrays(T, b)
        # direction: the bracket (j0, j1) and weight, periodic
        nb = self.beta_deg.size
        j1 = np.searchsorted(self.beta_deg, b, side="left") % nb
        j0 = (j1 - 1) % nb
        exact1 = np.isclose(np.mod(self.beta_deg[j1] - b + 180.0, 360.0) - 180.0, 0.0, atol=1e-9)
        exact0 = np.isclose(np.mod(b - self.beta_deg[j0] + 180.0, 360.0) - 180.0, 0.0, atol=1e-9)
        j1 = np.where(exact0, j0, j1)
        j0 = np.where(exact1, j1, j0)
        exact = exact0 | exact1
        gap = np.mod(self.beta_deg[j1] - self.beta_deg[j0], 360.0)
        off = np.mod(b - self.beta_deg[j0], 360.0)
        with np.errstate(invalid="ignore", divide="ignore"):
            wb = np.where(gap > 0, off / gap, 0.0)
        ok_b = exact | ((gap <= MAX_GAP_DEG) & (gap > 0))
        # period: linear inside the range
        nt = self.Tp.size
        i1 = np.clip(np.searchsorted(self.Tp, T, side="left"), 0, nt - 1)
        i0 = np.clip(i1 - 1, 0, nt - 1)
        texact = np.isclose(self.Tp[i1], T, rtol=1e-9, atol=0)
        i0 = np.where(texact, i1, i0)
        with np.errstate(invalid="ignore", divide="ignore"):
            wt = np.where(self.Tp[i1] > self.Tp[i0], (T - self.Tp[i0]) / (self.Tp[i1] - self.Tp[i0]), 0.0)
        ok_t = texact | ((T > self.Tp[0]) & (T < self.Tp[-1]))
        H = self.Hs
        h = ((1 - wt) * ((1 - wb) * H[i0, j0] + wb * H[i0, j1]) + wt * ((1 - wb) * H[i1, j0] + wb * H[i1, j1]))
        return np.where(ok_b & ok_t, h, np.nan)

    def describe(self) -> str:
        """One line: what the table is."""
        return (f"time domain ({self.name}, {self.store}): {self.incident}, {self.Tp.size} Tp "
                f"{self.Tp[0]:g}–{self.Tp[-1]:g} s × {self.beta_deg.size} directions"
                + (" (port/starboard mirrored)" if self.mirrored else ""))


def _symmetric_vessel(vessel) -> bool:
    """Whether the database ``vessel`` names (built-in name or path) is port/starboard symmetric; False when it
    cannot be read here."""
    if not vessel:
        return False
    try:
        from boatland.hydro import load_database
        from boatland.vessel.directions import port_starboard_symmetry

        return bool(port_starboard_symmetry(load_database(vessel)).symmetric)
    except Exception:  # noqa: BLE001 - unknown here: no mirroring (the table covers what it covers)
        return False


def table_limits(table: LimitsTable, weather: Weather, landings_deg) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing from a time-domain table (module docstring):
    the total sea's Hs, Tp and direction; not covered → NaN limit, not workable."""
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    beta = relative_directions(weather.from_deg, L)
    lim = table.at(weather.Tp[:, None], beta)
    with np.errstate(invalid="ignore", divide="ignore"):
        margin = lim / weather.Hs[:, None]
    covered = np.isfinite(lim)
    return SeaLimits(Hs_limit=lim, margin=margin, beta_deg=beta,
                     governing=np.full(lim.shape, table.incident, dtype=object), two_spectra=np.zeros(weather.n, bool),
                     landings_deg=L, accept=table.accept, access_duration=table.access, statistics="time domain",
                     method="importance sampling", mu=math.nan if table.mu is None else float(table.mu),
                     thrust=math.nan if table.thrust is None else float(table.thrust), source=table.describe(),
                     covered=covered)
