r"""The limiting Hs against the tidal current: its speed and its direction relative to the landed vessel, and
the landing side a skipper should choose in a given current (``boatland screen --current-sweep``).

For each current (speed U, relative direction θ_c, the direction the water moves towards: 180° onto the bow,
90° towards port — from starboard) the scenario's landing is screened again (:func:`~boatland.freqdomain.
screening.screening_grid` at one Tp and the scenario's relative wave direction): the current's drag at rest
enters the landed equilibrium (a sideways current uses friction capacity before the waves do; one along the
vessel changes the normal force), the skipper trims the push against its yaw moment
(:meth:`boatland.landing.environment.Environment.trim`) and its drag, linearised about the current, damps the
motions (:mod:`boatland.landing.environment`).

Choosing the landing side. A turbine's boat landings face different ways; the skipper picks the one whose
approach puts the current where the vessel tolerates it best. With the waves' relative direction held at the
scenario's, the best side in a current of speed U is the relative current direction with the highest limiting
Hs (:meth:`CurrentSweep.advice`). Both turn together with the side in reality (the waves come from one
direction too): ``boatland operability`` weighs both over a site's weather, each sea state in its own current
(:mod:`boatland.site.flows`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import screening_grid
from boatland.freqdomain.statistics import ACCEPT_PRESETS, ACCESS_DURATION, DEFAULT_STATISTICS
from boatland.loads.current import side_words
from boatland.vessel.database import HydroDB

__all__ = ["DEFAULT_SPEEDS", "CurrentSweep", "current_sweep", "figure_current_sweep", "plot_current_sweep"]

#: Current speeds of the sweep [m/s]: calm to the 1–2 m/s of tidal sites in UK and German waters.
DEFAULT_SPEEDS = (0.0, 0.25, 0.5, 0.75, 1.0, 1.5)


@dataclass(frozen=True, eq=False)
class CurrentSweep:
    """Limiting Hs ``Hs`` (Nu, Nθ) [m] at peak period ``Tp`` and relative wave direction ``wave_deg`` for the
    current speeds ``speeds`` (Nu,) [m/s] and relative current directions ``directions_deg`` (Nθ,) (towards);
    ``governing`` the response at each limit, ``accept`` the accepted probability per access."""

    Tp: float
    wave_deg: float
    speeds: np.ndarray
    directions_deg: np.ndarray
    Hs: np.ndarray
    governing: np.ndarray
    accept: float
    statistics: str

    def text(self) -> str:
        head = "U [m/s] \\ current towards [deg] " + "".join(f"{d:>7g}" for d in self.directions_deg)
        rows = [head]
        for i, u in enumerate(self.speeds):
            rows.append(f"{u:>31.2f} " + "".join(f"{h:>7.3f}" if np.isfinite(h) else f"{'–':>7}" for h in self.Hs[i]))
        return "\n".join(rows)

    def advice(self) -> list[str]:
        """Per current speed above zero: the best and the worst relative current direction, in words."""
        out = []
        for i, u in enumerate(self.speeds):
            if u <= 0:
                continue
            h = np.where(np.isfinite(self.Hs[i]), self.Hs[i], -1.0)
            b, w = int(np.argmax(h)), int(np.argmin(h))
            calm = self.Hs[np.argmin(self.speeds)] if self.speeds.min() == 0 else None
            ref = f" (no current: {calm[b]:.2f} m)" if calm is not None else ""
            out.append(f"{u:g} m/s: land with the current {self._where(i, b)}: limit {self.Hs[i, b]:.2f} m{ref}; "
                       f"worst {self._where(i, w)}: {self.Hs[i, w]:.2f} m")
        return out

    def _where(self, i: int, j: int) -> str:
        """The direction in words, "either side" when its port–starboard mirror is as good (within 0.1 %)."""
        d = float(self.directions_deg[j])
        mirror = np.flatnonzero(np.isclose(self.directions_deg, (360.0 - d) % 360.0))
        if mirror.size and int(mirror[0]) != j and np.isclose(self.Hs[i, mirror[0]], self.Hs[i, j], rtol=1e-3):
            d, m = sorted((d, (360.0 - d) % 360.0))       # a tie within round-off: the smaller angle first
            words = f"{side_words(d)} ({d:g}°)"
            return words.replace(" from starboard", "").replace(" from port", "") + f" or {m:g}° (either side)"
        return f"{side_words(d)} ({d:g}°)"

    def as_dict(self) -> dict:
        fin = lambda a: [[None if not np.isfinite(v) else float(v) for v in row] for row in a]  # noqa: E731
        return {"Tp": self.Tp, "wave_relative_direction_deg": self.wave_deg, "speeds": self.speeds.tolist(),
                "current_relative_direction_deg": self.directions_deg.tolist(), "Hs_limit": fin(self.Hs),
                "governing": self.governing.tolist(), "accept": self.accept, "statistics": self.statistics,
                "advice": self.advice()}


def current_sweep(db: HydroDB, scenario, Tp: float, *, speeds=DEFAULT_SPEEDS, directions_deg=None,
                  accept=ACCEPT_PRESETS["best"], statistics: str = DEFAULT_STATISTICS, sea=None,
                  water_depth: float | None = None, access_duration: float = ACCESS_DURATION, roll_limit_deg=None,
                  progress=None) -> CurrentSweep:
    """The limiting Hs of ``scenario``'s landing at ``Tp`` against the current (module docstring).

    Parameters
    ----------
    db : HydroDB
    scenario : Scenario
        Its landing, push, fender, wind and sea's shape and relative direction; its own ``[current]`` is replaced.
    Tp : float
        Peak period [s].
    speeds : sequence of float
        Current speeds [m/s].
    directions_deg : sequence of float, optional
        Relative current directions (towards) [deg]; default every 45°.
    progress : callable, optional
        ``progress(done, total)`` after each screened current.
    """
    th = np.arange(0.0, 360.0, 45.0) if directions_deg is None else np.asarray(directions_deg, dtype=float)
    U = np.asarray(speeds, dtype=float)
    wave = (scenario.sea.waves.parts[0].direction_deg - scenario.vessel.heading_deg) % 360.0 \
        if scenario.sea is not None and getattr(scenario.sea.waves, "parts", None) else 180.0
    Hs = np.full((U.size, th.size), np.nan)
    gov = np.full((U.size, th.size), "", dtype=object)
    total, done = U.size * th.size, 0
    for i, u in enumerate(U):
        for j, d in enumerate(th):
            sc = scenario.replace({"current": {"speed": float(u), "relative_direction_deg": float(d)}})
            setup = LandingSetup.from_scenario(sc, db, roll_limit_deg=roll_limit_deg)
            t = screening_grid(db, setup, [Tp], [wave], accept=accept, statistics=statistics, sea=sea,
                               water_depth=water_depth, access_duration=access_duration)
            Hs[i, j], gov[i, j] = t.Hs[0, 0], t.governing[0, 0]
            done += 1
            if progress is not None:
                progress(done, total)
            if u == 0.0:                         # no current: every direction is the same landing
                Hs[i, :], gov[i, :] = Hs[i, j], gov[i, j]
                done += th.size - 1
                if progress is not None:
                    progress(done, total)
                break
    return CurrentSweep(Tp=float(Tp), wave_deg=float(wave), speeds=U, directions_deg=th, Hs=Hs,
                        governing=gov.astype(str), accept=float(t.accept), statistics=statistics)


def figure_current_sweep(sweep: CurrentSweep, *, title: str = ""):
    """Limiting Hs [m] against the current's relative direction, one line per speed (the calm line dashed)."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.6), constrained_layout=True)
    d = np.r_[sweep.directions_deg, sweep.directions_deg[0] + 360.0]
    for i, u in enumerate(sweep.speeds):
        h = np.r_[sweep.Hs[i], sweep.Hs[i, 0]]
        ax.plot(d, h, "--" if u == 0 else "-o", color="0.4" if u == 0 else plt.cm.viridis(0.1 + 0.75 * u / max(sweep.speeds.max(), 1e-9)),
                ms=3.5, lw=1.2, label="no current" if u == 0 else f"{u:g} m/s")
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xticklabels([f"{a}°\n{side_words(a % 360, short=True)}" for a in range(0, 361, 45)], fontsize=7)
    ax.set(xlabel="current relative to the vessel (the direction it flows towards)", ylabel="limiting Hs [m]",
           xlim=(0, 360))
    ax.set_title(title or f"limiting Hs at Tp {sweep.Tp:g} s, waves at {sweep.wave_deg:g}°", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(title="current speed", fontsize=8)
    return fig


def plot_current_sweep(sweep: CurrentSweep, path: str | Path, *, title: str = "", dpi: int = 100) -> Path:
    """Save :func:`figure_current_sweep` to ``path`` (PNG), written whole or not at all."""
    from boatland.plotstyle import save_figure

    return save_figure(figure_current_sweep(sweep, title=title), path, dpi=dpi)
