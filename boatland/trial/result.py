"""The result of one landing trial: labelled time series, events, slip episodes, incidents, summary."""

from __future__ import annotations

import json
from dataclasses import dataclass, field, fields
from pathlib import Path

import numpy as np

from boatland import __version__
from boatland.atomic import atomic_path
from boatland.conventions import DOF_NAMES, DOF_UNITS
from boatland.model.scenario_parts import Incidents
from boatland.trial.events import (SLID_OFF, Event, SlipEpisode, first_exceedance, landing_offset,
                                   worst_landing_offset)

__all__ = ["Result", "TrialSeries", "SERIES"]


@dataclass(frozen=True, eq=False)
class TrialSeries:
    """The time series of a trial (or of a block of its steps). Arrays are indexed by step (``t``),
    contacts by their order in the scenario.

    Attributes
    ----------
    t : (n,)
        Time [s].
    x, v : (n, 6)
        Motions and velocities of the reference point (surge, sway, heave [m]; roll, pitch, yaw [rad]).
    F_exc : (n, 6)
        Wave excitation force.
    thrust : (n,)
        Push along the vessel's x axis [N].
    mode : (n, Nc) int
        0 open, 1 stick, 2 slip, 3 off the landing (at each step start).
    fn : (n, Nc)
        Normal force [N]; ``ft`` (n, Nc, 2) friction or shear force on the vessel along the tube
        (vertical, horizontal) [N]; ``needed`` the force that would hold the contact stuck,
        ``available`` the friction available, μ_s f_n (stuck) or μ(|u|) f_n (sliding) [N]; ``tpos``
        (n, Nc, 2) the fender's position on the landing (contact height, fender centre along the
        landing) [m].
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    F_exc: np.ndarray
    thrust: np.ndarray
    mode: np.ndarray
    fn: np.ndarray
    ft: np.ndarray
    needed: np.ndarray
    available: np.ndarray
    tpos: np.ndarray


#: Names of the arrays of :class:`TrialSeries`, in order.
SERIES = tuple(f.name for f in fields(TrialSeries))


@dataclass(frozen=True, eq=False)
class Result(TrialSeries):
    """One trial: its :class:`TrialSeries` and what was found in it.

    Attributes
    ----------
    slide : (n, Nc, 2) or None
        Sliding of the fender over the tube (vertical, horizontal) during the step that ended at each row
        [m]: the rubber's anchor (compliant fender) or the contact point (rigid stick).
    work : (n, Nc) or None
        Friction work of that step [J] (never positive).
    events, episodes : list
        :class:`~boatland.trial.events.Event` and :class:`~boatland.trial.events.SlipEpisode`.
    status, message : int, str
        0 = completed; 3 = the fender slid off the landing (an outcome: the trial ends there);
        otherwise why the integration stopped (NaN, runaway) — the arrays then end there.
    provenance : dict
        boatland version, scenario name and hash, seed, dt, radiation method.
    incidents : Incidents
        Thresholds of the incident definitions (slip distances [m], roll limits [deg]); loss of
        contact is always reported.
    """

    slide: np.ndarray | None = None
    work: np.ndarray | None = None
    events: list[Event] = field(default_factory=list)
    episodes: list[SlipEpisode] = field(default_factory=list)
    status: int = 0
    message: str = "completed"
    provenance: dict = field(default_factory=dict)
    incidents: Incidents | None = None

    @property
    def completed(self) -> bool:
        return self.status == 0

    @property
    def settled_at(self) -> float:
        """Time [s] the landing has settled: the thrust is fully on and the waves begin
        (:func:`boatland.trial.simulate.wave_start`). Before it the fender is still being pushed on —
        slides then are settling, not slips: events before it are not counted as slip events, and the
        landing position is taken from it."""
        return float(self.provenance.get("waves_from", 0.0))

    @property
    def exposure_from(self) -> float:
        """Time [s] the waves have reached full height (the settling plus the waves' start-up ramp): the
        exposure of a campaign's access is counted from here."""
        return self.settled_at + float(self.provenance.get("wave_ramp", 0.0))

    def _settle_row(self) -> int:
        return int(np.searchsorted(self.t, self.settled_at - 1e-9))

    def slip_events(self) -> list[Event]:
        """The stick → slip events after the settling (:attr:`settled_at`)."""
        t0 = self.settled_at - 1e-9
        return [e for e in self.events if e.kind == "stick→slip" and e.t >= t0]

    def landing_offset(self) -> np.ndarray:
        """(n, Nc) distance [m] of each fender point from where it landed after the settling (NaN while
        open, not yet caught, or settling): Grøtting's (2015) incident slip distance, see
        :func:`boatland.trial.events.landing_offset`."""
        return landing_offset(self.mode, self.tpos, self._settle_row())

    def _worst_offset(self) -> np.ndarray | None:
        """Largest landing offset over the contacts per step (0 where none has landed); None without contacts."""
        if not self.mode.shape[1]:
            return None
        return worst_landing_offset(self.mode, self.tpos, self._settle_row())

    def incident_times(self) -> dict[str, float | None]:
        """First time of each incident definition (None: did not happen)."""
        return self._incident_times(self._worst_offset())

    def _incident_times(self, worst: np.ndarray | None) -> dict[str, float | None]:
        out: dict[str, float | None] = {}
        slip_limits = self.incidents.slip_distance if self.incidents is not None else (0.1,)
        roll_limits = self.incidents.roll_limit_deg if self.incidents is not None else ()
        for limit in slip_limits:
            out[f"slip > {limit:g} m"] = first_exceedance(self.t, worst, limit) if worst is not None else None
        for limit in roll_limits:
            out[f"roll > {limit:g}°"] = first_exceedance(self.t, self.x[:, 3], np.radians(limit))
        if self.mode.shape[1]:
            lost = [e.t for e in self.events if e.kind in ("contact lost", SLID_OFF) and e.t >= self.settled_at - 1e-9]
            out["contact loss"] = min(lost) if lost else None
            off = [e.t for e in self.events if e.kind == SLID_OFF]
            out[SLID_OFF] = min(off) if off else None
        return out

    def summary(self) -> dict:
        """Figures a user reads first (JSON-able)."""
        slips = self.slip_events()
        worst = self._worst_offset()
        touching = self.mode > 0
        fn = np.where(touching, self.fn, np.nan)
        return {
            "status": self.message,
            "duration": float(self.t[-1]),
            "slip_events": len(slips),
            "time_to_first_slip": slips[0].t if slips else None,
            "max_slip_distance": float(worst.max()) if worst is not None and worst.size else 0.0,
            "max_single_slide": max((e.distance for e in self.episodes if e.t_start >= self.settled_at - 1e-9),
                                    default=0.0),
            "max_normal_force": None if not touching.any() else float(np.nanmax(fn)),
            "min_normal_force_in_contact": None if not touching.any() else float(np.nanmin(fn)),
            "contact_fraction": float(touching.all(axis=1).mean()) if self.mode.shape[1] else 0.0,
            "max_motions": {f"{n} [{'deg' if u == 'rad' else u}]": float(np.degrees(a) if u == "rad" else a)
                            for n, u, a in zip(DOF_NAMES, DOF_UNITS, np.max(np.abs(self.x), axis=0))},
            "incidents": self._incident_times(worst),
            "provenance": self.provenance,
        }

    def summary_text(self) -> str:
        s = self.summary()
        lines = [f"{self.provenance.get('scenario', 'trial')}: {s['status']} after {s['duration']:.1f} s"]
        if self.mode.shape[1]:
            first = s["time_to_first_slip"]
            lines += [
                f"  slip events          {s['slip_events']}" + (f" (first at t = {first:.2f} s)" if first is not None else ""),
                f"  max slip distance    {s['max_slip_distance']:.3f} m from the landing position "
                f"(largest single slide {s['max_single_slide']:.3f} m)",
                f"  normal force         max {s['max_normal_force'] / 1e3:.3g} kN, min in contact "
                f"{s['min_normal_force_in_contact'] / 1e3:.3g} kN" if s["max_normal_force"] is not None
                else "  normal force         never in contact",
                f"  all contacts touching {100 * s['contact_fraction']:.1f} % of the time",
            ]
        lines.append("  max motions          " + ", ".join(f"{k} {v:.3g}" for k, v in s["max_motions"].items()))
        if self.mode.shape[1] and self.settled_at > 0:
            lines.append(f"  settled at t = {self.settled_at:g} s (thrust on; slides before it are not slips), waves "
                         f"at full height from t = {self.exposure_from:g} s")
        for name, t in s["incidents"].items():
            lines.append(f"  incident {name:21s}" + ("no" if t is None else f"at t = {t:.2f} s"))
        for e in self.events[:12]:
            lines.append(f"  event: {e.text()}")
        if len(self.events) > 12:
            lines.append(f"  … {len(self.events) - 12} more events (see --json or the output file)")
        return "\n".join(lines)

    def to_hdf5(self, path: str | Path) -> Path:
        """Write the time series, events and summary to HDF5, atomically (nothing half-written)."""
        import h5py

        path = Path(path)
        with atomic_path(path) as tmp:
            with h5py.File(tmp, "w") as f:
                f.attrs["boatland_version"] = __version__
                f.attrs["summary"] = json.dumps(self.summary())
                for name in SERIES + ("slide", "work"):
                    if getattr(self, name) is not None:
                        f.create_dataset(name, data=getattr(self, name), compression="gzip", shuffle=True)
                f["x"].attrs["columns"] = ",".join(DOF_NAMES)
                ev = np.array([(e.t, e.contact, e.kind.encode(), e.needed, e.available) for e in self.events],
                              dtype=[("t", "f8"), ("contact", "i4"), ("kind", "S24"), ("needed", "f8"),
                                     ("available", "f8")])
                f["events"] = ev
        return path
