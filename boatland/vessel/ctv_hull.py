r"""Parametric CTV catamaran hull: transom stern, hard-chine or round-bilge sections, fine entrance,
flared topsides and a deck — the wetted part for the BEM, the part above water for the viewers.

Each demihull (centreline at :math:`y = \pm s/2`, symmetric about it) is described by its lines in
the body frame of :mod:`boatland.conventions` with the origin at *midship* — halfway between the
transom (:math:`x = -L/2`) and the waterline stem (:math:`x = +L/2`) — on the centreline between the
demihulls, in the calm waterline. With :math:`\xi = x/L + 1/2 \in [0, 1]` (transom to stem):

Waterline half-breadth (a transom of breadth :math:`t_b b`, the widest station at :math:`\xi_m`, a
fine entrance of half-angle :math:`\alpha_e`):

.. math::
    \eta_w(\xi) = \frac{b}{2}\begin{cases}
        t_b + (1 - t_b)\,\bigl[1 - (1 - \xi/\xi_m)^2\bigr], & \xi \le \xi_m \\
        1 - u^{n}, \quad u = \frac{\xi - \xi_m}{1 - \xi_m}, & \xi > \xi_m \end{cases}
    \qquad n = \frac{2 (1 - \xi_m) L \tan\alpha_e}{b},

so that :math:`-d\eta_w/dx = \tan\alpha_e` at the stem.

Keel line (the local draught :math:`d(\xi)`; an immersed transom of depth :math:`t_d T`, the full
draught :math:`T` from :math:`\xi_k`, a forefoot rising to the waterline stem from :math:`\xi_f`):

.. math::
    d(\xi) = T\begin{cases}
        t_d + (1 - t_d)\,\bigl[1 - (1 - \xi/\xi_k)^2\bigr], & \xi \le \xi_k \\
        1, & \xi_k < \xi \le \xi_f \\
        1 - v^{2}, \quad v = \frac{\xi - \xi_f}{1 - \xi_f}, & \xi > \xi_f. \end{cases}

Sections, with :math:`h \in [0, d]` the height above the local keel and :math:`y(h)` the half-breadth
about the demihull's own centreline:

- **hard chine**: a straight bottom of deadrise :math:`\beta` from the keel to the chine at
  :math:`(y_c, h_c)`, :math:`y_c = c\,\eta_w`, :math:`h_c = y_c \tan\beta` (capped at :math:`0.8\,d`, then
  :math:`y_c = h_c/\tan\beta`), and a straight side from the chine to the waterline. The deadrise is
  :math:`\beta_m` aft of :math:`\xi_m` and grows as :math:`\beta_m + (\beta_b - \beta_m)u^2` towards the
  stem (a V entrance). Section area of one demihull
  :math:`a = y_c h_c + (d - h_c)(y_c + \eta_w)`.
- **round bilge**: a superellipse quadrant :math:`y = \eta_w\,[1 - (1 - h/d)^p]^{1/p}` (p = 2 an
  ellipse, larger p a flatter bottom and a tighter bilge); :math:`a = 2\eta_w d\,\Gamma(1+1/p)^2/\Gamma(1+2/p)`.

Above the waterline the sides flare outwards by :math:`\varphi`, :math:`y = y_w + z\tan\varphi`, and
the stem rakes forwards, :math:`x_{stem}(z) = L/2 + z\tan\rho`: at height :math:`z` the waterline
shape is stretched over :math:`[-L/2,\, x_{stem}(z)]`. The outer topsides rise to the deck at
:math:`z = f` (freeboard), the inner ones to the wet deck of the tunnel at :math:`z = h_t`; the deck
spans both hulls and the cross structure, whose front carries the bow fender. A deckhouse box sits
on the deck. The topsides, deck and deckhouse are drawn by the viewers only
(:meth:`CTVCatamaran.topsides`); the BEM sees the wetted surface (:meth:`CTVCatamaran.mesh`), the
transom included.

Hydrostatics (:class:`Hydrostatics`) are integrated from these closed-form sections by Gauss–Legendre
quadrature (exact to round-off for the piecewise-linear chine sections across the girth; 10⁻⁹ along
the length), and are the reference the panel meshes and Capytaine are checked against.

The shape follows the description of current wind-farm catamarans: narrow demihulls with a fine
(often near-vertical "axe") entrance, a transom stern carrying waterjets or propellers, hard-chine
aluminium hulls, a high tunnel and a flared, high bow carrying the fender (Damen FCS 2610/2710
"Twin Axe", offshorewind.biz 2015 "The class of 26"; Incat Crowther's 27 m CTV, WorkBoat 2021;
Grøtting 2015 §1.2). Hull lines of a real vessel are not public: the form parameters are stated in
the vessel file.

Panels
------
The catamaran is port–starboard symmetric only (a transom stern has no fore–aft symmetry), so the BEM
meshes a *half*: the whole port demihull, both its sides and its immersed transom, and Capytaine is
told about the xOz plane. Stations are clustered towards the stem and the transom, waterlines towards
the free surface; the chine is a line of the mesh. Faces are quadrilaterals ``[a, b, c, d]``
counter-clockwise seen from the water (normal out of the hull); a triangle repeats its last vertex.

References
----------
- Wigley, W. C. S. (1934) and Journée, J. M. J. (1992), for the companion form of
  :mod:`boatland.vessel.wigley`.
- Savitsky, D. (1964). Hydrodynamic design of planing hulls. *Marine Technology* 1(1): deadrise and
  chine geometry of hard-chine hulls.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, fields
from typing import NamedTuple

import numpy as np

from boatland.vessel.wigley import clustered, merge_vertices, mirror_panels
from boatland.vessel.database import HullMesh

__all__ = ["CTVCatamaran", "CTVPanelCounts", "Hydrostatics", "SECTIONS"]

#: Section shapes of :class:`CTVCatamaran`.
SECTIONS = ("chine", "round")
#: Largest chine height as a fraction of the local draught.
CHINE_CAP = 0.8
#: Weight of the sine part of the station clustering (both ends).
END_CLUSTERING = 0.5
#: Largest station spacing relative to the uniform one for :func:`_both_ends`.
MAX_END_SPACING = (1.0 - END_CLUSTERING) + END_CLUSTERING * np.pi / 2
_GL_X = 400   # Gauss–Legendre nodes per length piece
_GL_H = 64    # per girth piece of a round-bilge section


class CTVPanelCounts(NamedTuple):
    """Panel counts of the half mesh (the port demihull).

    Attributes
    ----------
    n_length : int
        Panels from the transom to the stem.
    n_bottom, n_side : int
        Panels from the keel to the chine, and from the chine to the waterline (round bilge: n_bottom
        keel to waterline, n_side = 0).
    n_transom : int
        Panels across the transom (half of them each side of the demihull's centreline).
    n_lid : int
        Lid panels across the demihull's waterplane.
    """

    n_length: int
    n_bottom: int
    n_side: int
    n_transom: int
    n_lid: int

    @property
    def n_girth(self) -> int:
        return self.n_bottom + self.n_side


class Hydrostatics(NamedTuple):
    """Hydrostatic particulars of both demihulls at the design waterline (body frame).

    Attributes
    ----------
    volume : float
        Displaced volume ∇ [m³].
    cob : ndarray, shape (3,)
        Centre of buoyancy [m].
    waterplane_area : float
        A_wp [m²].
    lcf : float
        Longitudinal centre of flotation x_F = ∫x dA / A_wp [m].
    i_t, i_l : float
        Second moments of the waterplane about the x and y axes through the origin [m⁴].
    block_coefficient : float
        C_b = ∇ / (2 L b T).
    midship_coefficient : float
        Section area at the widest station over b T.
    """

    volume: float
    cob: np.ndarray
    waterplane_area: float
    lcf: float
    i_t: float
    i_l: float
    block_coefficient: float
    midship_coefficient: float


def _both_ends(n: int, alpha: float = END_CLUSTERING) -> np.ndarray:
    r"""``n + 1`` points on [0, 1], denser at both ends: :math:`(1-\alpha)t + \alpha(1-\cos\pi t)/2`."""
    t = np.linspace(0.0, 1.0, n + 1)
    u = (1.0 - alpha) * t + alpha * 0.5 * (1.0 - np.cos(np.pi * t))
    u[0], u[-1] = 0.0, 1.0
    return u


@functools.lru_cache(maxsize=8)
def _legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


def _gauss(a: float, b: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights of order n on [a, b]."""
    x, w = _legendre(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


@dataclass(frozen=True)
class CTVCatamaran:
    """Two identical CTV demihulls side by side (module docstring for the equations).

    Parameters
    ----------
    length : float
        Waterline length L of a demihull, transom to stem [m].
    demihull_beam : float
        Largest waterline beam b of a demihull [m].
    draft : float
        Draught T at the keel [m].
    separation : float
        Distance s between the demihull centrelines [m]; more than ``demihull_beam``.
    section : {"chine", "round"}
        Hard-chine or round-bilge sections.
    deadrise_deg, bow_deadrise_deg : float
        Deadrise β_m amidships and aft, and β_b at the stem [deg] (chine sections).
    chine_beam : float
        Chine half-breadth over the waterline half-breadth, c ∈ (0.5, 1] (chine sections).
    bilge_exponent : float
        Superellipse exponent p of round-bilge sections (≥ 1.5).
    transom_beam, transom_draft : float
        Waterline breadth and keel depth at the transom as fractions t_b of b and t_d of T.
    max_beam_station, keel_station, forefoot_station : float
        ξ_m, ξ_k, ξ_f: where the waterline is widest, where the keel reaches the full draught, where
        the forefoot starts to rise (fractions of L from the transom).
    entrance_deg : float
        Half-angle of entrance α_e of the waterline at the stem [deg].
    freeboard : float
        Deck height f above the waterline [m].
    tunnel_height : float
        Wet-deck (tunnel roof) height h_t above the waterline [m], below the deck.
    flare_deg : float
        Outward flare φ of the topsides [deg].
    stem_rake_deg : float
        Forward rake ρ of the stem above the waterline [deg].
    deckhouse : tuple of 4 floats
        (x_aft, x_fwd, width, height) of the deckhouse box on the deck [m]; width 0 for none.
    """

    length: float
    demihull_beam: float
    draft: float
    separation: float
    section: str = "chine"
    deadrise_deg: float = 22.0
    bow_deadrise_deg: float = 50.0
    chine_beam: float = 0.95
    bilge_exponent: float = 2.5
    transom_beam: float = 0.9
    transom_draft: float = 0.75
    max_beam_station: float = 0.35
    keel_station: float = 0.3
    forefoot_station: float = 0.65
    entrance_deg: float = 12.0
    freeboard: float = 2.4
    tunnel_height: float = 1.6
    flare_deg: float = 8.0
    stem_rake_deg: float = 20.0
    deckhouse: tuple = (-8.0, 2.0, 6.0, 2.6)

    def __post_init__(self):
        problems = ctv_form_problems({f.name: getattr(self, f.name) for f in fields(self)})
        if problems:
            raise ValueError("; ".join(f"{k}: {m}" for k, m in problems))
        for f in fields(self):
            v = getattr(self, f.name)
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                object.__setattr__(self, f.name, float(v))
        object.__setattr__(self, "deckhouse", tuple(float(v) for v in self.deckhouse))

    # ------------------------------------------------------------------ lines
    @property
    def entrance_exponent(self) -> float:
        """n of the forebody waterline, from the entrance half-angle."""
        return 2.0 * (1.0 - self.max_beam_station) * self.length * math.tan(math.radians(self.entrance_deg)) \
            / self.demihull_beam

    def xi(self, x) -> np.ndarray:
        """ξ = x/L + 1/2 (0 at the transom, 1 at the stem)."""
        return np.asarray(x, dtype=float) / self.length + 0.5

    def waterline_half_breadth(self, xi) -> np.ndarray:
        """η_w(ξ) of a demihull at z = 0 [m] (0 outside the hull)."""
        xi = np.asarray(xi, dtype=float)
        xm, tb = self.max_beam_station, self.transom_beam
        aft = tb + (1.0 - tb) * (1.0 - (1.0 - np.clip(xi, 0.0, xm) / xm) ** 2)
        u = np.clip((xi - xm) / (1.0 - xm), 0.0, 1.0)
        fore = 1.0 - u ** self.entrance_exponent
        out = 0.5 * self.demihull_beam * np.where(xi <= xm, aft, fore)
        return np.where((xi < 0.0) | (xi > 1.0), 0.0, out)

    def keel_depth(self, xi) -> np.ndarray:
        """Local draught d(ξ) [m] (0 outside the hull)."""
        xi = np.asarray(xi, dtype=float)
        xk, xf, td = self.keel_station, self.forefoot_station, self.transom_draft
        aft = td + (1.0 - td) * (1.0 - (1.0 - np.clip(xi, 0.0, xk) / xk) ** 2)
        v = np.clip((xi - xf) / (1.0 - xf), 0.0, 1.0)
        out = self.draft * np.where(xi <= xk, aft, np.where(xi <= xf, 1.0, 1.0 - v ** 2))
        return np.where((xi < 0.0) | (xi > 1.0), 0.0, out)

    def deadrise(self, xi) -> np.ndarray:
        """Deadrise β(ξ) [rad] of chine sections."""
        xi = np.asarray(xi, dtype=float)
        u = np.clip((xi - self.max_beam_station) / (1.0 - self.max_beam_station), 0.0, 1.0)
        return np.radians(self.deadrise_deg + (self.bow_deadrise_deg - self.deadrise_deg) * u ** 2)

    def chine(self, xi) -> tuple[np.ndarray, np.ndarray]:
        """(y_c, h_c): chine half-breadth about the demihull centreline and height above the keel [m]."""
        eta, d, beta = self.waterline_half_breadth(xi), self.keel_depth(xi), self.deadrise(xi)
        tb = np.tan(beta)
        yc = self.chine_beam * eta
        hc = yc * tb
        cap = CHINE_CAP * d
        over = hc > cap
        hc = np.where(over, cap, hc)
        yc = np.where(over, cap / tb, yc)
        return yc, hc

    def section_half_breadth(self, xi, h) -> np.ndarray:
        """y(ξ, h): half-breadth at height h above the local keel (h ∈ [0, d(ξ)]) [m]."""
        xi, h = np.broadcast_arrays(np.asarray(xi, dtype=float), np.asarray(h, dtype=float))
        eta, d = self.waterline_half_breadth(xi), self.keel_depth(xi)
        hh = np.clip(h, 0.0, d)
        if self.section == "round":
            q = np.where(d > 0, 1.0 - hh / np.where(d > 0, d, 1.0), 1.0)
            return eta * np.clip(1.0 - q ** self.bilge_exponent, 0.0, 1.0) ** (1.0 / self.bilge_exponent)
        yc, hc = self.chine(xi)
        low = np.where(hc > 0, yc * hh / np.where(hc > 0, hc, 1.0), 0.0)
        span = d - hc
        high = yc + (eta - yc) * np.where(span > 0, (hh - hc) / np.where(span > 0, span, 1.0), 1.0)
        return np.where(hh <= hc, low, high)

    def section_area(self, xi) -> np.ndarray:
        """Immersed section area of one demihull [m²] (closed form, module docstring)."""
        eta, d = self.waterline_half_breadth(xi), self.keel_depth(xi)
        if self.section == "round":
            p = self.bilge_exponent
            return 2.0 * eta * d * math.gamma(1 + 1 / p) ** 2 / math.gamma(1 + 2 / p)
        yc, hc = self.chine(xi)
        return yc * hc + (d - hc) * (yc + eta)

    # ------------------------------------------------------------------ hydrostatics
    def _length_nodes(self) -> tuple[np.ndarray, np.ndarray]:
        """Gauss nodes and weights in ξ over the pieces between the breakpoints of the lines."""
        brk = sorted({0.0, self.keel_station, self.max_beam_station, self.forefoot_station, 1.0})
        xs, ws = zip(*(_gauss(a, b, _GL_X) for a, b in zip(brk[:-1], brk[1:]) if b > a))
        return np.concatenate(xs), np.concatenate(ws)

    def _section_moments(self, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(area, ∫∫ z dA) of one demihull's section at each ξ (z from the waterline, < 0)."""
        d = self.keel_depth(xi)
        if self.section == "round":
            # h = d w^p removes the h^(1/p) singularity of the superellipse at the keel
            p = self.bilge_exponent
            w, ww = _gauss(0.0, 1.0, _GL_H)
            h = d[:, None] * w[None, :] ** p
            dh = d[:, None] * p * w[None, :] ** (p - 1.0) * ww[None, :]
            y = self.section_half_breadth(xi[:, None], h)
            return 2.0 * np.sum(y * dh, axis=1), 2.0 * np.sum(y * (h - d[:, None]) * dh, axis=1)
        yc, hc = self.chine(xi)
        # piecewise-linear y(h): exact with 2-point Gauss on each of the two pieces
        g, gw = _gauss(0.0, 1.0, 2)
        area = np.zeros_like(xi)
        mom = np.zeros_like(xi)
        for lo, hi in ((np.zeros_like(hc), hc), (hc, d)):
            h = lo[:, None] + (hi - lo)[:, None] * g[None, :]
            wgt = (hi - lo)[:, None] * gw[None, :]
            y = self.section_half_breadth(xi[:, None], h)
            area += 2.0 * np.sum(y * wgt, axis=1)
            mom += 2.0 * np.sum(y * (h - d[:, None]) * wgt, axis=1)
        return area, mom

    def hydrostatics(self) -> Hydrostatics:
        """Volume, centre of buoyancy and waterplane of both demihulls by quadrature of the lines (computed
        once per hull)."""
        if "_hydrostatics" not in self.__dict__:
            object.__setattr__(self, "_hydrostatics", self._hydrostatics())
        return self.__dict__["_hydrostatics"]

    def _hydrostatics(self) -> Hydrostatics:
        xi, w = self._length_nodes()
        x = (xi - 0.5) * self.length
        dx = w * self.length
        area, zmom = self._section_moments(xi)
        V = 2.0 * np.sum(area * dx)
        xb = 2.0 * np.sum(area * x * dx) / V
        zb = 2.0 * np.sum(zmom * dx) / V
        eta = self.waterline_half_breadth(xi)
        s2 = 0.5 * self.separation
        awp = 2.0 * np.sum(2.0 * eta * dx)
        lcf = 2.0 * np.sum(2.0 * eta * x * dx) / awp
        i_l = 2.0 * np.sum(2.0 * eta * x ** 2 * dx)
        i_t = 2.0 * np.sum((2.0 * eta * s2 ** 2 + (2.0 / 3.0) * eta ** 3) * dx)
        L, b, T = self.length, self.demihull_beam, self.draft
        am = float(self.section_area(self.max_beam_station))
        return Hydrostatics(float(V), np.array([float(xb), 0.0, float(zb)]), float(awp), float(lcf),
                            float(i_t), float(i_l), float(V / (2 * L * b * T)), am / (b * T))

    @property
    def volume(self) -> float:
        return self.hydrostatics().volume

    @property
    def centre_of_buoyancy(self) -> np.ndarray:
        return self.hydrostatics().cob

    @property
    def waterplane_area(self) -> float:
        return self.hydrostatics().waterplane_area

    @property
    def overall_beam(self) -> float:
        """Waterline breadth over both demihulls, s + b [m]."""
        return self.separation + self.demihull_beam

    @property
    def deck_beam(self) -> float:
        """Breadth over the deck edges, s + b + 2 f tan φ [m]."""
        return self.overall_beam + 2.0 * self.freeboard * math.tan(math.radians(self.flare_deg))

    @property
    def stem_x(self) -> float:
        """x of the waterline stem, L/2 [m]."""
        return 0.5 * self.length

    def stem_at(self, z: float) -> float:
        """x of the stem at height z ≥ 0 above the waterline (raked) [m]."""
        return 0.5 * self.length + max(float(z), 0.0) * math.tan(math.radians(self.stem_rake_deg))

    def restoring(self, rho: float, g: float, mass: float, cog) -> np.ndarray:
        r"""Linear restoring matrix about the origin (hydrostatics + weight), 6×6.

        .. math::
            C_{33} = \rho g A_{wp},\quad C_{35} = C_{53} = -\rho g \textstyle\int x\,dA,\quad
            C_{44} = \rho g (I_T + \nabla z_B) - m g z_G,\quad C_{55} = \rho g (I_L + \nabla z_B) - m g z_G,

        :math:`C_{46} = -\rho g \nabla x_B + m g x_G`, :math:`C_{56} = -\rho g \nabla y_B + m g y_G` (as
        Capytaine and WAMIT report them).
        """
        hs = self.hydrostatics()
        xg, yg, zg = np.asarray(cog, dtype=float)
        V, (xb, yb, zb) = hs.volume, hs.cob
        C = np.zeros((6, 6))
        C[2, 2] = rho * g * hs.waterplane_area
        C[2, 4] = C[4, 2] = -rho * g * hs.lcf * hs.waterplane_area
        C[3, 3] = rho * g * (hs.i_t + V * zb) - mass * g * zg
        C[4, 4] = rho * g * (hs.i_l + V * zb) - mass * g * zg
        C[3, 5] = -rho * g * V * xb + mass * g * xg
        C[4, 5] = -rho * g * V * yb + mass * g * yg
        return C

    # ------------------------------------------------------------------ panel layout
    def _mid_girths(self) -> tuple[float, float]:
        """Girths keel → chine and chine → waterline (round: keel → waterline, 0) at ξ_m [m]."""
        xi = self.max_beam_station
        d = float(self.keel_depth(xi))
        if self.section == "round":
            h = d * (1.0 - (1.0 - np.linspace(0.0, 1.0, 4001)) ** 2)
            y = self.section_half_breadth(xi, h)
            return float(np.sum(np.hypot(np.diff(y), np.diff(h)))), 0.0
        yc, hc = (float(v) for v in self.chine(xi))
        eta = float(self.waterline_half_breadth(xi))
        return math.hypot(yc, hc), math.hypot(eta - yc, d - hc)

    def panel_counts(self, panel_size: float) -> CTVPanelCounts:
        """Fewest panels whose largest edge along the length, the girth, the transom and the lid is
        ≤ ``panel_size``."""
        h = float(panel_size)
        if not h > 0:
            raise ValueError(f"panel_size must be > 0, got {panel_size!r}")
        g_bot, g_side = self._mid_girths()
        n_len = max(4, math.ceil(MAX_END_SPACING * self.length / h))
        if self.section == "round":
            n_bot, n_side = max(2, math.ceil(MAX_END_SPACING * g_bot / h)), 0
        else:
            n_bot = max(1, math.ceil(g_bot / h))
            n_side = max(1, math.ceil(MAX_END_SPACING * g_side / h))
        n_tr = max(2, 2 * math.ceil(self.transom_beam * self.demihull_beam / (2.0 * h)))
        n_lid = max(1, math.ceil(self.demihull_beam / h))
        return CTVPanelCounts(n_len, n_bot, n_side, n_tr, n_lid)

    def counts_from(self, n_length: int, n_girth: int | None = None, n_lid: int | None = None,
                    default: CTVPanelCounts | None = None) -> CTVPanelCounts:
        """Panel counts from the vessel file's explicit ``n_length`` / ``n_girth`` / ``n_lid``."""
        base = default or self.panel_counts(self.length / max(n_length, 1) * MAX_END_SPACING)
        if n_girth is None:
            n_bot, n_side = base.n_bottom, base.n_side
        elif self.section == "round":
            n_bot, n_side = max(2, n_girth), 0
        else:
            g_bot, g_side = self._mid_girths()
            n_bot = min(max(1, round(n_girth * g_bot / (g_bot + g_side))), n_girth - 1)
            n_side = n_girth - n_bot
        lid = n_lid if n_lid is not None else base.n_lid
        return CTVPanelCounts(int(n_length), int(n_bot), int(n_side), base.n_transom, int(lid))

    def max_panel_size(self, counts: CTVPanelCounts) -> float:
        """Largest panel edge of the half mesh with ``counts`` (an upper bound) [m]."""
        g_bot, g_side = self._mid_girths()
        edges = [MAX_END_SPACING * self.length / counts.n_length,
                 self.demihull_beam / max(counts.n_lid, 1),
                 self.transom_beam * self.demihull_beam / max(counts.n_transom, 1)]
        if self.section == "round":
            edges.append(MAX_END_SPACING * g_bot / counts.n_bottom)
        else:
            edges += [g_bot / counts.n_bottom, MAX_END_SPACING * g_side / counts.n_side]
        return max(edges)

    def stations(self, n_length: int) -> np.ndarray:
        """``n_length + 1`` values of ξ from the transom to the stem, clustered at both ends."""
        return _both_ends(n_length)

    def _levels(self, xi: np.ndarray, counts: CTVPanelCounts) -> np.ndarray:
        """Heights above the keel (Ns, K+1) of the girth lines at stations ``xi``: keel → chine evenly,
        chine → waterline clustered towards the free surface (round bilge: equal girth after the
        clustering)."""
        d = self.keel_depth(xi)
        if self.section == "round":
            p = self.bilge_exponent
            w = np.linspace(0.0, 1.0, 2001)
            target = clustered(counts.n_bottom)
            out = np.empty((xi.size, target.size))
            for i, (x, dd) in enumerate(zip(xi, d)):
                h = dd * w ** p
                y = self.section_half_breadth(x, h)
                s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(y), np.diff(h)))])
                out[i] = np.interp(target * s[-1], s, h) if s[-1] > 0 else target * dd
                out[i, 0], out[i, -1] = 0.0, dd
            return out
        _, hc = self.chine(xi)
        bot = np.linspace(0.0, 1.0, counts.n_bottom + 1)[None, :] * hc[:, None]
        side = hc[:, None] + (d - hc)[:, None] * clustered(counts.n_side)[None, 1:]
        return np.concatenate([bot, side], axis=1)

    def _section_points(self, counts: CTVPanelCounts) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """x (Ns,), z (Ns, K+1) and y about the demihull centreline (Ns, K+1) of the girth lines."""
        xi = self.stations(counts.n_length)
        h = self._levels(xi, counts)
        y = self.section_half_breadth(xi[:, None], h)
        z = h - self.keel_depth(xi)[:, None]
        x = (xi - 0.5) * self.length
        return x, z, y

    def half_panels(self, counts: CTVPanelCounts) -> tuple[np.ndarray, np.ndarray]:
        """Wetted panels of the port demihull: both sides and the immersed transom.

        Returns
        -------
        vertices : ndarray, shape (Nv, 3)
        faces : ndarray of int, shape (Np, 4)
            Normals out of the hull; panels that collapse at the stem become triangles or vanish.
        """
        x, z, y = self._section_points(counts)
        ns, nk = z.shape
        X = np.repeat(x[:, None], nk, axis=1)
        s2 = 0.5 * self.separation
        verts, faces = [], []
        base = 0
        for side in (+1.0, -1.0):
            verts.append(np.stack([X, s2 + side * y, z], axis=-1).reshape(-1, 3))
            i, k = np.meshgrid(np.arange(ns - 1), np.arange(nk - 1), indexing="ij")
            a = (base + i * nk + k).reshape(-1)
            b = a + nk
            # outer (+y) side: [a, a+1, b+1, b] has normal +y (a → a+1 up the girth, a → b towards the bow)
            faces.append(np.stack([a, a + 1, b + 1, b] if side > 0 else [a, b, b + 1, a + 1], axis=-1))
            base += ns * nk
        # transom (x = −L/2): strips between the inner and outer girth points of the first station
        m = counts.n_transom
        t = np.linspace(0.0, 1.0, m + 1)
        yin, yout = s2 - y[0], s2 + y[0]
        Y = yin[:, None] + (yout - yin)[:, None] * t[None, :]                 # (K+1, m+1)
        Z = np.repeat(z[0][:, None], m + 1, axis=1)
        verts.append(np.stack([np.full_like(Y, x[0]), Y, Z], axis=-1).reshape(-1, 3))
        k, j = np.meshgrid(np.arange(nk - 1), np.arange(m), indexing="ij")
        a = (base + k * (m + 1) + j).reshape(-1)
        # a → a+1 along +y, a → a+(m+1) up: [a, a+m+1, a+m+2, a+1] has normal (+z) × (+y) = −x
        faces.append(np.stack([a, a + m + 1, a + m + 2, a + 1], axis=-1))
        return merge_vertices(np.concatenate(verts), np.concatenate(faces))

    def mesh(self, counts: CTVPanelCounts) -> HullMesh:
        """Full wetted hull (both demihulls, transoms included, no lid) as a :class:`HullMesh`."""
        v, f = self.half_panels(counts)
        v, f = mirror_panels(v, f, axis=1)
        return HullMesh(v, f)

    # ------------------------------------------------------------------ above water (viewers only)
    def topsides(self, n_length: int = 40, n_height: int = 4) -> HullMesh:
        """Topsides, transoms, wet deck, bow plate, deck and deckhouse above the waterline, both hulls.

        For the 3D scene of the viewers (:mod:`boatland.record.scene`); not part of any hydrodynamic
        computation. Normals point outwards (up for the deck, down for the wet deck).
        """
        xi = np.linspace(0.0, 1.0, n_length + 1)
        tf = math.tan(math.radians(self.flare_deg))
        s2 = 0.5 * self.separation
        parts: list[tuple[np.ndarray, np.ndarray]] = []

        def x_at(z):
            return -0.5 * self.length + xi * (self.stem_at(z) + 0.5 * self.length)

        def half(z):
            return self.waterline_half_breadth(xi) + z * tf * (self.waterline_half_breadth(xi) > 0)

        def grid(P, flip=False):
            """Quads of a structured (ni, nj, 3) grid; flip reverses the orientation."""
            ni, nj = P.shape[:2]
            i, j = np.meshgrid(np.arange(ni - 1), np.arange(nj - 1), indexing="ij")
            a = (i * nj + j).reshape(-1)
            q = np.stack([a, a + nj, a + nj + 1, a + 1], axis=-1)
            return P.reshape(-1, 3), (q[:, [0, 3, 2, 1]] if flip else q)

        for sgn in (+1.0, -1.0):                       # port, starboard demihull
            for outer, top in ((True, self.freeboard), (False, self.tunnel_height)):
                zs = np.linspace(0.0, top, n_height + 1)
                P = np.stack([np.stack([x_at(z), sgn * (s2 + (1 if outer else -1) * half(z)),
                                        np.full_like(xi, z)], axis=-1) for z in zs], axis=1)
                # (xi, z) grid: along +x then +z gives normal −y; outward is +y on port-outer / stbd-inner
                parts.append(grid(P, flip=(sgn > 0) == outer))
            # transom of the demihull up to the wet deck
            zs = np.linspace(0.0, self.tunnel_height, n_height + 1)
            yo = self.waterline_half_breadth(0.0) + zs * tf
            P = np.stack([np.stack([np.full(2, -0.5 * self.length),
                                    sgn * (s2 + np.array([-1.0, 1.0]) * y), np.full(2, z)], axis=-1)
                          for z, y in zip(zs, yo)], axis=0)
            parts.append(grid(P, flip=sgn < 0))
        # wet deck between the inner sides and the bow plate at the tunnel's front
        y_in = s2 - half(self.tunnel_height)
        xw = x_at(self.tunnel_height)
        P = np.stack([np.stack([xw, -y_in, np.full_like(xi, self.tunnel_height)], axis=-1),
                      np.stack([xw, y_in, np.full_like(xi, self.tunnel_height)], axis=-1)], axis=1)
        parts.append(grid(P, flip=True))
        zs = np.linspace(self.tunnel_height, self.freeboard, n_height + 1)
        P = np.stack([np.stack([np.full(2, self.stem_at(z)), np.array([-s2, s2]), np.full(2, z)], axis=-1)
                      for z in zs], axis=0)
        parts.append(grid(P, flip=True))
        # cross-structure transom from the wet deck to the deck, full width
        yd = s2 + half(self.freeboard)[0]
        P = np.stack([np.stack([np.full(2, -0.5 * self.length), np.array([-yd, yd]), np.full(2, z)], axis=-1)
                      for z in zs], axis=0)
        parts.append(grid(P, flip=False))
        # deck at z = f over both hulls and the cross structure
        y_out = s2 + half(self.freeboard)
        xd = x_at(self.freeboard)
        P = np.stack([np.stack([xd, -y_out, np.full_like(xi, self.freeboard)], axis=-1),
                      np.stack([xd, y_out, np.full_like(xi, self.freeboard)], axis=-1)], axis=1)
        parts.append(grid(P, flip=False))
        # deckhouse box
        xa, xf, w, hgt = self.deckhouse
        if w > 0 and hgt > 0 and xf > xa:
            z0, z1 = self.freeboard, self.freeboard + hgt
            c = np.array([[x, y, z] for x in (xa, xf) for y in (-w / 2, w / 2) for z in (z0, z1)])
            quads = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [1, 5, 7, 3]])
            parts.append((c, quads))
        verts, faces, base = [], [], 0
        for v, f in parts:
            verts.append(v)
            faces.append(f + base)
            base += len(v)
        v, f = merge_vertices(np.concatenate(verts), np.concatenate(faces))
        return HullMesh(v, f)


def ctv_form_problems(v: dict) -> list[tuple[str, str]]:
    """Problems of the CTV form parameters ``v`` (field names of :class:`CTVCatamaran`; missing ones
    are not checked). Returns ``(field, message)`` pairs."""
    out: list[tuple[str, str]] = []

    def num(name):
        x = v.get(name)
        return None if x is None or isinstance(x, bool) or not isinstance(x, (int, float)) else float(x)

    def need(name, lo, hi, what, lo_open=False, hi_open=False):
        x = num(name)
        if name in v and v[name] is not None and x is None:
            out.append((name, f"must be a number, got {v[name]!r}"))
            return
        if x is None:
            return
        bad = (x < lo or (lo_open and x == lo) or x > hi or (hi_open and x == hi) or not math.isfinite(x))
        if bad:
            lo_s, hi_s = ("(" if lo_open else "["), (")" if hi_open else "]")
            out.append((name, f"{x:g} is outside {lo_s}{lo:g}, {hi:g}{hi_s}: {what}"))

    for name in ("length", "demihull_beam", "draft", "separation"):
        need(name, 0.0, math.inf, "a length in m", lo_open=True, hi_open=True)
    if v.get("section") is not None and v["section"] not in SECTIONS:
        out.append(("section", f"must be one of {', '.join(SECTIONS)}, got {v['section']!r}"))
    need("deadrise_deg", 0.0, 45.0, "deadrise of the bottom amidships", lo_open=True)
    need("bow_deadrise_deg", 0.0, 75.0, "deadrise at the stem", lo_open=True)
    need("chine_beam", 0.5, 1.0, "chine half-breadth / waterline half-breadth")
    need("bilge_exponent", 1.5, 10.0, "superellipse exponent of the round bilge")
    need("transom_beam", 0.3, 1.0, "transom waterline breadth / demihull beam")
    need("transom_draft", 0.2, 1.0, "transom immersion / draught")
    need("max_beam_station", 0.05, 0.7, "station of the widest waterline, fraction of L from the transom")
    need("keel_station", 0.05, 0.7, "station where the keel reaches the full draught")
    need("forefoot_station", 0.3, 0.95, "station where the forefoot starts to rise")
    need("entrance_deg", 3.0, 35.0, "half-angle of entrance of the waterline")
    need("freeboard", 0.0, 10.0, "deck height above the waterline in m", lo_open=True)
    need("tunnel_height", 0.0, 10.0, "wet-deck height above the waterline in m", lo_open=True)
    need("flare_deg", 0.0, 30.0, "flare of the topsides")
    need("stem_rake_deg", 0.0, 60.0, "rake of the stem above the waterline")
    s, b, L = num("separation"), num("demihull_beam"), num("length")
    if s is not None and b is not None and s <= b:
        out.append(("separation", f"{s:g} m is not more than demihull_beam = {b:g} m: the demihulls would overlap"))
    if L is not None and b is not None and b >= L / 2:
        out.append(("demihull_beam", f"{b:g} m is not slender (length {L:g} m): a demihull needs beam < length / 2"))
    f, ht = num("freeboard"), num("tunnel_height")
    if f is not None and ht is not None and ht > f:
        out.append(("tunnel_height", f"{ht:g} m is above the deck (freeboard {f:g} m)"))
    xm, xf = num("max_beam_station"), num("forefoot_station")
    if xm is not None and xf is not None and xf <= xm:
        out.append(("forefoot_station", f"{xf:g} must lie forward of max_beam_station = {xm:g}"))
    if L is not None and b is not None and xm is not None and num("entrance_deg") is not None and not out:
        n = 2.0 * (1.0 - xm) * L * math.tan(math.radians(num("entrance_deg"))) / b
        if n < 1.0:
            out.append(("entrance_deg", f"{num('entrance_deg'):g}° gives a waterline exponent n = {n:.2f} < 1 "
                                        "(a hollow forebody): use a wider entrance angle or a station of the "
                                        "widest waterline further aft"))
    dh = v.get("deckhouse")
    if dh is not None and (len(dh) != 4 or not all(isinstance(t, (int, float)) and math.isfinite(t) for t in dh)):
        out.append(("deckhouse", f"expected [x_aft, x_fwd, width, height] in m, got {dh!r}"))
    return out
