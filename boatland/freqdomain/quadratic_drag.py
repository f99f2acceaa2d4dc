r"""The hull drag's second-order response: why a current makes the slip margins' tail heavier than a Gaussian's.

In a current of speed μ across a strip of the hull, the strip's cross-flow drag is :math:`k\,w|w|` with the
relative velocity :math:`w = \mu - v` (v the strip's own velocity in the waves). The screening's linear model
keeps its derivative — a damping :math:`2kE|w|` (:meth:`boatland.landing.environment.Environment.drag_damping`)
— and its mean (:meth:`~boatland.landing.environment.Environment.drag_mean_shift`). What it drops is the square:
for μ ≫ σ_v the drag is exactly :math:`k(\mu - v)^2 = k\mu^2 - 2k\mu v + k v^2`, and :math:`k v^2` pushes
down-stream whichever way the hull moves. Through the landed vessel it adds to every margin a part quadratic
in the waves, at their difference frequencies and their sums, which skews the margins towards a slip: for
ctv27 in bow-quartering seas with a 1 m/s beam current the governing margin's skewness is 0.013 / 0.019 at
H_s 0.2 / 0.3 m, the time domain's 0.012 / 0.020 (tests/validation/test_drag_skewness.py), and at the H_s
where the screening's P per 30 min is 0.35 it raises the margin's slip rate ×1.2.

**Model.** Equivalent statistical quadratization (Spanos, P. D. & Donley, M. G. (1991), *Equivalent statistical
quadratization for nonlinear systems*, J. Eng. Mech. 117(6), 1289–1310) of each strip's drag
(:meth:`~boatland.landing.environment.Environment.drag_quadratic`): the force :math:`\kappa_l(v_l^2 - \sigma_l^2)`
along the strip's pattern :math:`g_l` (l = strip and axis). With the strips' velocities linear in the waves,
:math:`v_l(t) = \mathrm{Re}\sum_n V_{ln} A_n e^{i\omega_n t}`, and :math:`R_{rl}(\Omega)` margin r of the landed
vessel per unit force along :math:`g_l` at frequency Ω (the same landed system, :meth:`boatland.freqdomain.
landing.LandingSetup.response`), the margin's second-order part is the Volterra series

.. math::
    \zeta^{(2)}_r(t) = \tfrac12\,\mathrm{Re}\sum_{n,m}\sum_l \kappa_l\Big[
        R_{rl}(\omega_n + \omega_m)\,V_{ln}V_{lm}\,A_nA_m\,e^{i(\omega_n+\omega_m)t}
      + R_{rl}(\omega_n - \omega_m)\,V_{ln}V^*_{lm}\,A_nA^*_m\,e^{i(\omega_n-\omega_m)t}\Big] - E[\cdot]

(Bendat, J. S. (1998), *Nonlinear Systems Techniques and Applications*, Wiley, ch. 5: the sum and difference
kernels of a quadratic system). With :math:`A_n = c_n + i s_n`, c and s independent standard normal (each
component's variance carried by V and H), the margin is a Gaussian quadratic form
:math:`X_r = b_r^\top\xi + \xi^\top M_r\,\xi`, ξ = (c, s), whose cumulants are exact (Mathai, A. M. & Provost,
S. B. (1992), *Quadratic Forms in Random Variables*, Dekker, §3.2):

.. math::
    \kappa_2 = b^\top b + 2\,\mathrm{tr}M^2, \quad \kappa_3 = 6\,b^\top M b + 8\,\mathrm{tr}M^3, \quad
    \kappa_4 = 48\,b^\top M^2 b + 48\,\mathrm{tr}M^4 ,

the skewness :math:`\kappa_3/\kappa_2^{3/2}` and excess kurtosis :math:`\kappa_4/\kappa_2^2`
(:meth:`QuadraticDrag.tails`); their tail is Winterstein's Hermite model (:func:`boatland.freqdomain.statistics.
hermite_level`), which turns the margin's capacity into the level a Gaussian margin would have to reach as
often (:func:`boatland.freqdomain.statistics.incident_probability`).

A short-crested sea's components at one frequency are replaced by the eigenvectors of the cross-spectral matrix
of the margins and the strips' velocities there (the same Gaussian process, fewer components). The second-order
part is computed on a sub-grid of the screening's frequencies :data:`STEP` apart over the band holding all but
:data:`BAND_CUT` of the waves' variance (halving the step changes ctv27's skewness by < 1 %, tests); the landed
vessel's answer to the quadratic force is solved once per landing on the multiples of that step and
interpolated at the sums; sum frequencies above the database's band are left out (the landed vessel answers them
quasi-statically and little).
What stays out: the drag's terms beyond second order, and the second-order part's own feedback on the strips'
velocities.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["BAND_CUT", "STEP", "QuadraticDrag", "quadratic_form_cumulants"]

#: Spacing of the second-order grid [rad/s] (a sub-grid of the screening's).
STEP = 0.02
#: Share of the waves' variance (of every strip velocity and margin) the second-order band may leave out at
#: each end.
BAND_CUT = 1e-3
#: Most components (frequencies × a short-crested sea's eigen-components) of the second-order model; more
#: widen the step.
MAX_COMPONENTS = 400
#: Eigen-components of a short-crested sea kept per frequency: those above this share of the largest.
RANK_CUT = 1e-8


def quadratic_form_cumulants(b: np.ndarray, M: np.ndarray) -> np.ndarray:
    r"""Cumulants κ₂, κ₃, κ₄ (..., 3) of :math:`X = b^\top\xi + \xi^\top M\xi - \mathrm{tr}M`, ξ standard
    normal (module docstring; Mathai & Provost 1992 §3.2). ``b`` (..., d), ``M`` (..., d, d) symmetric."""
    b = np.asarray(b, dtype=float)
    M = np.asarray(M, dtype=float)
    Mb = np.einsum("...ij,...j->...i", M, b)
    M2 = M @ M
    k2 = np.einsum("...i,...i->...", b, b) + 2 * np.einsum("...ii->...", M2)
    k3 = 6 * np.einsum("...i,...i->...", b, Mb) + 8 * np.einsum("...ij,...ji->...", M2, M)
    k4 = 48 * np.einsum("...i,...i->...", Mb, Mb) + 48 * np.einsum("...ij,...ji->...", M2, M2)
    return np.stack([k2, k3, k4], axis=-1)


def quadratic_form(b_c: np.ndarray, P: np.ndarray, Q: np.ndarray):
    r"""The real form (b, M) of :math:`\mathrm{Re}\,(h^\top A) + \mathrm{Re}\,(A^\top P A) + A^\top Q \bar A` in
    :math:`A = c + i s`, ξ = (c, s): ``b_c`` (..., N) complex h, ``P`` (..., N, N) complex symmetric, ``Q``
    (..., N, N) Hermitian; returns b (..., 2N) and M (..., 2N, 2N)."""
    M = np.block([[P.real + Q.real, Q.imag - P.imag], [-P.imag - Q.imag, Q.real - P.real]])
    return np.concatenate([b_c.real, -b_c.imag], axis=-1), M


@dataclass(frozen=True, eq=False)
class QuadraticDrag:
    r"""The hull drag's quadratic force on one landed vessel and the vessel's answer to it (module docstring).

    Attributes
    ----------
    patterns : ndarray, shape (L, 6)
        The strips' generalised force patterns :math:`g_l` whose drag has a quadratic part.
    kappa : ndarray, shape (L,)
        Their coefficients :math:`\kappa_l` [N s²/m²] (:meth:`~boatland.landing.environment.Environment.
        drag_quadratic`).
    step : int
        The second-order grid's stride on the screening's frequencies.
    omega : ndarray, shape (Nw,)
        The screening's frequencies [rad/s].
    answer_omega : ndarray, shape (K,)
        Multiples of the second-order step [rad/s] (the first 0: the static answer).
    answer : ndarray of complex, shape (K, L, R)
        Each response per unit force along each pattern at those frequencies.
    top : float
        The database's highest frequency [rad/s].
    """

    patterns: np.ndarray
    kappa: np.ndarray
    step: int
    omega: np.ndarray
    answer_omega: np.ndarray
    answer: np.ndarray
    top: float

    @classmethod
    def of(cls, db, setup, omega, margin_directions, sigma=None) -> "QuadraticDrag | None":
        r"""The quadratic drag of ``setup`` (a :class:`~boatland.freqdomain.landing.LandingSetup`, its drag
        linearised), None without a current's cross-flow drag.

        Parameters
        ----------
        db : HydroDB
        setup : LandingSetup
        omega : ndarray, shape (Nw,)
            The screening's frequencies [rad/s], uniform.
        margin_directions : ndarray, shape (Np, 4, 3)
            Each contact's :math:`d_{m,c} - \mu n_c`: the margins of its contact force
            (:func:`boatland.freqdomain.screening.slip_directions`).
        sigma : ndarray, shape (n, 2), optional
            The strips' velocity standard deviations the drag is linearised at (default 0: the current alone).
        """
        env = setup.environment
        if env is None or not setup.drag_linearisable or not np.any(env.current_velocity[:2]):
            return None
        G = env.strip_maps()                                                             # (n, 2, 6)
        kap = env.drag_quadratic(np.zeros(G.shape[:2]) if sigma is None else sigma)      # (n, 2)
        on = np.abs(kap) > 0
        if not on.any():
            return None
        w = np.asarray(omega, dtype=float)
        dw = float(w[1] - w[0])
        if w.size < 2 or not np.allclose(np.diff(w), dw, rtol=1e-9, atol=0.0):
            raise ValueError("the second-order drag needs a uniform frequency grid")
        step = max(1, int(round(STEP / dw)))
        top = float(db.omega[-1])
        grid = np.arange(0.0, top + step * dw / 2, step * dw)
        grid = grid[grid <= top]
        solve = np.where(grid > 0, grid, min(1e-3, float(db.omega[0])))                 # Ω = 0: the static answer
        g = G[on]
        r = setup.response(db, solve, np.array([0.0]), loads=g)
        J, x = r.J_loads, r.x_loads                                                       # (K, L, Np, 3), (K, L, 6)
        ans = np.concatenate([np.einsum("olk,mk->olm", J[:, :, c], margin_directions[c])
                              for c in range(J.shape[2])] + [x[:, :, 3:4]], axis=-1)      # (K, L, R)
        ans[0] = ans[0].real
        return cls(patterns=g, kappa=kap[on], step=step, omega=w, answer_omega=grid, answer=ans, top=top)

    def _at(self, Omega: np.ndarray, rows) -> np.ndarray:
        """The answer (..., L, R') of the responses ``rows`` at frequencies Ω ≥ 0 (linear interpolation, exact at
        the step's multiples; 0 above the band)."""
        k = self.answer_omega
        ans = self.answer[..., rows]
        x = np.clip(Omega / k[1], 0.0, k.size - 1.0)
        i = np.rint(x).astype(int)
        if np.allclose(x, i, rtol=0.0, atol=1e-6):                                     # the differences
            out = ans[i]
        else:
            i = np.minimum(np.floor(x).astype(int), k.size - 2)
            f = (x - i)[..., None, None]
            out = (1 - f) * ans[i] + f * ans[i + 1]
        return np.where((Omega <= self.top)[..., None, None], out, 0.0)

    def components(self, weights, Y):
        """Frequencies (N,) and components (N, D) of the Gaussian vector process with transfer functions ``Y``
        (Nw, Nβ, D) and variance weights ``weights`` (Nβ, Nw) on the second-order grid (module docstring)."""
        w = self.omega
        var = np.einsum("bw,wbd->wd", weights, np.abs(Y) ** 2)                        # (Nw, D)
        tot = var.sum(axis=0)
        live = np.flatnonzero(tot > 0)
        share = np.cumsum(var[:, live], axis=0) / tot[live]
        lo = int(min(np.searchsorted(share[:, d], BAND_CUT) for d in range(live.size)))
        hi = int(min(w.size - 1, max(np.searchsorted(share[:, d], 1.0 - BAND_CUT) for d in range(live.size))))
        scale = np.sqrt(np.mean(np.abs(Y.reshape(-1, Y.shape[-1])) ** 2, axis=0))       # each row's size
        scale = np.where(scale > 0, scale, 1.0)
        stride = self.step
        while True:
            freq, comp = [], []
            for i in range(lo, hi + 1, stride):
                j = slice(max(0, i - stride // 2), min(w.size, i - stride // 2 + stride))
                Wb = weights[:, j].sum(axis=1)                          # its neighbours' variance: a coarser trapezoid
                if Y.shape[1] == 1:
                    freq.append(w[i])
                    comp.append(np.sqrt(Wb[0]) * Y[i, 0])
                    continue
                Yi = Y[i] / scale
                lam, vec = np.linalg.eigh(np.einsum("b,bd,be->de", Wb, Yi, Yi.conj()))
                for k in np.flatnonzero(lam > RANK_CUT * max(float(lam[-1]), 1e-300)):
                    freq.append(w[i])
                    comp.append(np.sqrt(lam[k]) * vec[:, k] * scale)
            if len(freq) <= MAX_COMPONENTS:
                return np.asarray(freq), np.asarray(comp)
            stride *= 2

    def tails(self, weights, H, motions) -> np.ndarray:
        r"""Skewness and excess kurtosis (R, 2) of each response with transfer functions ``H`` (Nw, Nβ, R) in
        the sea of variance weights ``weights`` (Nβ, Nw) = S(ω) dω, the landed motions ``motions``
        (Nw, Nβ, 6) (module docstring); roll's (the last) are left 0 (the statistics do not use them:
        :func:`boatland.freqdomain.statistics.incident_probability`)."""
        w = self.omega
        R = H.shape[-1] - 1
        H = H[..., :R]
        rows = slice(0, R)
        V = np.einsum("ld,wbd->wbl", self.patterns, 1j * w[:, None, None] * motions)    # (Nw, Nβ, L)
        f, comp = self.components(np.asarray(weights, dtype=float), np.concatenate([H, V], axis=-1))
        Hc, Vc = comp[:, :R], comp[:, R:]                                                 # (N, R), (N, L)
        Rsum = self._at(f[:, None] + f[None, :], rows)                                    # (N, N, L, R)
        d = f[:, None] - f[None, :]
        Rdif = self._at(np.abs(d), rows)
        Rdif = np.where((d < 0)[..., None, None], Rdif.conj(), Rdif)                      # R(−Ω) = R(Ω)*
        kV = self.kappa[None, :] * Vc
        P = 0.5 * np.einsum("nmlr,nl,ml->rnm", Rsum, kV, Vc, optimize=True)
        Q = 0.5 * np.einsum("nmlr,nl,ml->rnm", Rdif, kV, Vc.conj(), optimize=True)
        P = 0.5 * (P + P.transpose(0, 2, 1))
        Q = 0.5 * (Q + Q.transpose(0, 2, 1).conj())
        b, M = quadratic_form(Hc.T, P, Q)
        k = quadratic_form_cumulants(b, M)
        out = np.zeros((R + 1, 2))
        pos = np.flatnonzero(k[:, 0] > 0)
        out[pos, 0] = k[pos, 1] / k[pos, 0] ** 1.5
        out[pos, 1] = k[pos, 2] / k[pos, 0] ** 2
        return out
