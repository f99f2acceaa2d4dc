"""The result of one landing trial: labelled time series, events, slip episodes, incidents, summary."""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from functools import cached_property
from pathlib import Path

import numpy as np

from boatland.atomic import atomic_hdf5
from boatland.conventions import DOF_NAMES, DOF_UNITS
from boatland.scenario.parts import Incidents
from boatland.trial.incidents import FirstSlip, trial_incidents
from boatland.trial.events import (Event, SlipEpisode, all_touching_fraction, column_abs_max, extract_events,
                                   landing_offset, largest_single_slide,
                                   slip_episodes, slip_start_rows, worst_landing_offset)

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

    @property
    def settle_row(self) -> int:
        """The first row at or after :attr:`settled_at`."""
        return int(np.searchsorted(self.t, self.settled_at - 1e-9))

    @cached_property
    def events(self) -> list[Event]:
        """Every state change of every contact (:class:`~boatland.trial.events.Event`, by step then contact;
        :func:`~boatland.trial.events.extract_events`), built from the mode records when first asked for:
        :meth:`summary` and the verdict read the records themselves (a campaign's trial has thousands)."""
        return extract_events(self.t, self.mode, self.needed, self.available)

    @cached_property
    def episodes(self) -> list[SlipEpisode]:
        """The slip episodes (:class:`~boatland.trial.events.SlipEpisode`, :func:`~boatland.trial.events.slip_episodes`),
        built when first asked for."""
        return slip_episodes(self.t, self.mode, self.tpos)

    @cached_property
    def slip_rows(self) -> tuple[np.ndarray, np.ndarray]:
        """The steps of the stick → slip events, whole run, and how many contacts slip at each
        (:func:`~boatland.trial.events.slip_start_rows`): ``(rows, counts)``, read only."""
        rows, counts = slip_start_rows(self.mode)
        rows.flags.writeable = counts.flags.writeable = False
        return rows, counts

    @cached_property
    def peak_motions(self) -> np.ndarray:
        """(6,) largest |x| of each DOF over the run [m, rad] (NaN where the run has a NaN), read only."""
        peak = column_abs_max(np.asarray(self.x, dtype=float))
        peak.flags.writeable = False
        return peak

    def slip_events(self) -> list[Event]:
        """The stick → slip events after the settling (:attr:`settled_at`)."""
        t0 = self.settled_at - 1e-9
        return [e for e in self.events if e.kind == "stick→slip" and e.t >= t0]

    def landing_offset(self) -> np.ndarray:
        """(n, Nc) distance [m] of each fender point from where it landed after the settling (NaN while
        open, not yet caught, or settling): Grøtting's (2015) incident slip distance, see
        :func:`boatland.trial.events.landing_offset`."""
        return landing_offset(self.mode, self.tpos, self.settle_row)

    @cached_property
    def worst_offset(self) -> np.ndarray | None:
        """(n,) largest landing offset over the contacts per step [m] (0 where none has landed; see
        :meth:`landing_offset`), read only; None without contacts."""
        if not self.mode.shape[1]:
            return None
        worst = worst_landing_offset(self.mode, self.tpos, self.settle_row)
        worst.flags.writeable = False
        return worst

    @property
    def incident_definitions(self) -> tuple:
        """The incident definitions this trial reports (:func:`boatland.trial.incidents.trial_incidents`)."""
        return trial_incidents(self.incidents, contacts=bool(self.mode.shape[1]))

    def incident_times(self) -> dict[str, float | None]:
        """First time of each incident definition after the settling, by name (None: did not happen)."""
        return {d.name: d.first_time(self) for d in self.incident_definitions}

    def slip_starts(self) -> list:
        """The fender's slip events after the settling: stick → slip of one or more contacts at the same
        step counted once (a symmetric landing's two tubes slip together) —
        :class:`~boatland.trial.verdict.MergedEvent` s."""
        from boatland.trial.verdict import merge_events

        return merge_events(self.slip_events(), self.settled_at)

    def merged_events(self, which: str = "waves") -> list:
        """Events merged across contacts (:func:`boatland.trial.verdict.merge_events`).

        Parameters
        ----------
        which : {"waves", "all", "none"}
            ``"waves"``: after the settling (:attr:`settled_at`); ``"all"``: the settling's too.
        """
        from boatland.trial.verdict import merge_events

        if which not in ("waves", "all", "none"):
            raise ValueError(f"which must be 'waves', 'all' or 'none', got {which!r}")
        if which == "none":
            return []
        merged = merge_events(self.events, self.settled_at)
        return merged if which == "all" else [e for e in merged if not e.settling]

    @property
    def inputs(self) -> dict:
        """What the trial was run with (:func:`boatland.scenario.inputs.trial_inputs`): sea, direction, push, μ."""
        return dict(self.provenance.get("inputs", {}))

    def verdict(self):
        """Did the fender hold? :class:`~boatland.trial.verdict.Verdict` against the incident thresholds."""
        from boatland.trial.verdict import verdict

        return verdict(self, self.summary())

    def summary(self) -> dict:
        """Figures a user reads first (JSON-able, full precision; :meth:`report` rounds them).

        ``slip_events`` counts the fender's slip starts (contacts slipping at the same step once,
        :meth:`slip_starts`); ``contact_slip_events`` each contact's. ``max_slip_distance`` is the largest
        distance of a fender point from where it landed from the first slip on (0 without a slip);
        ``max_shear_deflection`` that distance before the first slip — the stuck rubber's elastic shear, not a
        slide. The normal forces are those after
        the settling (:attr:`settled_at`; the whole run if it never touched after it)."""
        k0 = self.settle_row
        rows, counts = self.slip_rows
        after = rows >= k0                             # the stick → slip events after the settling
        worst = self.worst_offset
        # before the first slip the fender point's offset from where it landed is the rubber's elastic shear
        first = int(rows[after][0]) if after.any() else len(self.t)
        touching = self.mode > 0
        landed = touching[k0:]                         # forces after the settling: not the first touch
        if not landed.any():
            landed = touching
        fn = np.where(landed, self.fn[len(self.t) - len(landed):], np.nan)
        s = {
            "status": self.message,
            "duration": float(self.t[-1]),
            "slip_events": int(np.count_nonzero(after)),   # = len(self.slip_starts()): each step once
            "contact_slip_events": int(counts[after].sum()),
            "time_to_first_slip": FirstSlip().first_time(self),
            "max_slip_distance": float(worst[first:].max()) if worst is not None and first < worst.size else 0.0,
            "max_shear_deflection": float(worst[k0:first].max()) if worst is not None and first > k0 else 0.0,
            "max_single_slide": largest_single_slide(self.mode, self.tpos, k0),
            "max_normal_force": None if not touching.any() else float(np.nanmax(fn)),
            "min_normal_force_in_contact": None if not touching.any() else float(np.nanmin(fn)),
            "contact_fraction": float(all_touching_fraction(self.mode)) if self.mode.shape[1] else 0.0,
            "max_motions": {f"{n} [{'deg' if u == 'rad' else u}]": float(np.degrees(a) if u == "rad" else a)
                            for n, u, a in zip(DOF_NAMES, DOF_UNITS, self.peak_motions)},
            "incidents": self.incident_times(),
            "provenance": self.provenance,
        }
        from boatland.trial.verdict import verdict

        s["verdict"] = verdict(self, s).as_dict()
        return s

    def report(self, events: str = "waves") -> dict:
        """What ``boatland run --json`` prints: the verdict, the inputs, :meth:`summary` rounded to
        physical resolution (:data:`boatland.trial.verdict.RESOLUTION`: no numerical noise), the
        settling times and the events merged across contacts (``events`` as in :meth:`merged_events`)."""
        from boatland.trial.verdict import rounded

        s = self.summary()
        units = {"duration": "s", "time_to_first_slip": "s", "max_slip_distance": "m", "max_single_slide": "m",
                 "max_shear_deflection": "m",
                 "max_normal_force": "N", "min_normal_force_in_contact": "N", "contact_fraction": "1"}
        out = {"verdict": s["verdict"], "inputs": self.inputs}
        out.update({k: rounded(v, units[k]) if k in units else v for k, v in s.items()
                    if k not in ("provenance", "verdict")})
        out["max_motions"] = {k: rounded(v, "m" if k.endswith("[m]") else "deg") for k, v in s["max_motions"].items()}
        out["incidents"] = {k: rounded(v, "s") for k, v in s["incidents"].items()}
        out["settled_at"] = self.settled_at
        out["exposure_from"] = self.exposure_from
        shown = self.merged_events(events)
        out["events"] = [e.as_dict() for e in shown]
        out["events_shown"] = events
        out["events_hidden"] = len(self.merged_events("all")) - len(shown)
        out["provenance"] = self.provenance
        return out

    def summary_text(self, events: str = "waves", max_events: int = 12) -> str:
        """The verdict line, then the figures, incidents and events for a terminal (rounded: forces to
        0.1 kN, lengths to 1 mm, angles to 0.01°).

        Parameters
        ----------
        events : {"waves", "all", "none"}
            Which events to list (:meth:`merged_events`); at most ``max_events`` of them.
        """
        from boatland.trial.verdict import fmt_angle, fmt_force, fmt_length

        s = self.summary()
        lines = [s["verdict"]["text"]]
        lines.append(f"  {s['status']} after {s['duration']:.1f} s"
                     + (f"; settled at t = {self.settled_at:g} s (thrust on; slides before it are not slips), waves "
                        f"at full height from t = {self.exposure_from:g} s" if self.mode.shape[1] and self.settled_at > 0
                        else ""))
        if self.mode.shape[1]:
            first = s["time_to_first_slip"]
            frac = 100 * s["contact_fraction"]
            lines += [
                f"  slip events          {s['slip_events']}" + (f" (first at t = {first:.2f} s)" if first is not None else "")
                + (f"; {s['contact_slip_events']} counting each contact" if s["contact_slip_events"] != s["slip_events"]
                   else ""),
                f"  max slip distance    {fmt_length(s['max_slip_distance'])} from where it landed "
                f"(largest single slide {fmt_length(s['max_single_slide'])})" if s["slip_events"] else
                f"  shear deflection     {fmt_length(s['max_shear_deflection'])} (the rubber's elastic shear while "
                "it sticks: not a slide)",
                f"  normal force         (after the settling) max {fmt_force(s['max_normal_force'])}, min in contact "
                f"{fmt_force(s['min_normal_force_in_contact'])}" if s["max_normal_force"] is not None
                else "  normal force         never in contact",
                f"  all contacts touching {'> 99.9' if 99.95 <= frac < 100 else f'{frac:.1f}'} % of the time",
            ]
        motions = []
        for k, v in s["max_motions"].items():
            name, unit = k.split(" [")
            motions.append(f"{name} {fmt_length(v) if unit == 'm]' else fmt_angle(v)}")
        lines.append("  max motions          " + ", ".join(motions))
        width = max([21] + [len(n) + 1 for n in s["incidents"]])
        for name, t in s["incidents"].items():
            lines.append(f"  incident {name:{width}s}" + ("no" if t is None else f"at t = {t:.2f} s"))
        shown = self.merged_events(events)
        hidden = len(self.merged_events("all")) - len(shown)
        if events != "none":
            head = "events after the settling" if events == "waves" else "events"
            if hidden and events == "waves":
                head += f" ({hidden} settling events hidden: --events all)"
            lines.append(f"  {head}:" if shown else f"  {head}: none")
        for e in shown[:max_events]:
            lines.append(f"    {e.text()}")
        if len(shown) > max_events:
            lines.append(f"    … {len(shown) - max_events} more (all of them in --json and in -o FILE)")
        return "\n".join(lines)

    def to_xarray(self):
        """The trial as an ``xarray.Dataset``: named variables with units over the dimensions ``time``,
        ``dof``, ``contact``, ``tangent`` (vertical, horizontal along the landing), ``event`` and
        ``episode``; the inputs, verdict, summary and provenance as attributes.

        Variables: ``motion``, ``velocity`` and ``wave_force`` (time, dof; SI units per DOF in the
        coordinate ``dof_units``), the same motions by name (``surge``, ``sway``, ``heave`` [m], ``roll``,
        ``pitch``, ``yaw`` [deg]), ``thrust`` [N], per contact ``contact_mode`` (0 open, 1 stick, 2 slip,
        3 off the landing), ``normal_force``, ``friction_force`` (with ``tangent``), ``friction_needed``,
        ``friction_available`` [N], ``friction_utilisation`` (needed / available), ``landing_position``
        and ``slide`` [m] (with ``tangent``), ``slip_distance`` [m] (from where it landed: the incident
        distance), ``friction_work`` [J]; the events (``event_time``, ``event_contact``, ``event_kind``,
        ``event_needed``, ``event_available``) and slip episodes (``episode_*``) as tables. ``-o FILE``
        of ``boatland run`` is this dataset: ``xarray.open_dataset(FILE)`` gives it back.
        """
        from boatland.trial.dataset import result_dataset

        return result_dataset(self)

    def to_hdf5(self, path: str | Path) -> Path:
        """Write the dataset of :meth:`to_xarray` as netCDF-4/HDF5 (``xarray.open_dataset(path)`` opens it with
        its dimensions and units; h5py reads it as plain HDF5), atomically (nothing half-written). Needs
        h5py only — not xarray."""

        from boatland.netcdf_h5 import write_parts
        from boatland.trial.dataset import result_parts

        path = Path(path)
        var, coords, attrs = result_parts(self)
        with atomic_hdf5(path, track_order=True) as f:
            write_parts(f, var, coords, attrs)
        return path
