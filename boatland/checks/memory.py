r"""Does the radiation memory a trial will use damp every landed natural mode? (:func:`check_memory`),
and the refusal a trial or campaign makes of one that does not (:func:`check_radiation`)."""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.landing.law import landed_modes
from boatland.landing.setup import Setup
from boatland.scenario.scenario import ScenarioWarning
from boatland.vessel.radiation import RadiationMemory, memory_damping

__all__ = ["MemoryCheck", "check_memory", "check_radiation"]


@dataclass(frozen=True)
class MemoryCheck:
    """:func:`check_memory`: ``problems`` and ``warnings`` as ``(key_path, message)``, ``notes`` to show."""

    problems: tuple[tuple[str, str], ...]
    warnings: tuple[tuple[str, str], ...]
    notes: tuple[str, ...]


def check_memory(setup: Setup, memory: RadiationMemory) -> MemoryCheck:
    r"""Does the radiation memory a trial will use damp every landed natural mode?

    For each undamped natural mode :math:`(\omega_k, \phi_k)` of the vessel on its landing within the
    database's band (:func:`boatland.landing.law.landed_modes`: contacts stuck, thrust preload), the modal damping of the
    memory actually used, :math:`b_k = \phi_k^\top B_{mem}(\omega_k)\phi_k`
    (:func:`boatland.vessel.radiation.memory_damping`; mass-normalised φ, so :math:`b_k = 2\zeta_k\omega_k`),
    is compared with the damping the vessel has besides it, :math:`\phi_k^\top(B_v + D_{fender})\phi_k`:

    - :math:`b_k < 0` and the total negative: the mode **grows** (energy is injected where the vessel
      lives) — a problem naming ``radiation.method`` with what to use;
    - :math:`b_k < 0` but the total positive: a warning (the fender's damping keeps it stable);
    - otherwise a note with the mode and its ζ.

    A radiation damping that is negative is an artefact of the memory: truncating K(t) (even tapered
    or at 120 s) leaves an error of order |K(T_K)|/ω that dominates the nearly zero true damping of a
    slow mode (measured on ctv24's landed sway–yaw mode, T = 37 s: true 2e-7, 40 s −2.0e-3, 40 s tapered
    −8.9e-5, 120 s −1.6e-4 s⁻¹); the passive state-space fit gives +1.2e-4.
    """
    scenario, db = setup.scenario, setup.db
    if db.M is None:                     # no landed modes without a mass (the physical checks say so)
        return MemoryCheck((), (), ())
    law = setup.contact_law()
    problems, warns, notes = [], [], []
    try:
        modes = _landed_modes(db, law, scenario.thrust.force if (law is not None and scenario.thrust) else 0.0,
                              scenario.thrust.position if scenario.thrust is not None else (0.0, 0.0, 0.0))
    except (ValueError, np.linalg.LinAlgError) as exc:
        return MemoryCheck((), (("radiation", f"the landed modes could not be found ({exc}): the memory's damping "
                                              "is not checked"),), ())
    keep = (modes.omega > 0) & (modes.omega <= db.omega[-1])
    if not np.any(keep):
        return MemoryCheck((), (), ())
    w, phi = modes.omega[keep], modes.shapes[keep]
    names = [d for d, k in zip(modes.dominant, keep) if k]
    rad = scenario.radiation
    B = memory_damping(memory, w, method=rad.method, dt=setup.dt, memory_length=rad.memory)
    b_mem = np.einsum("ki,kij,kj->k", phi, B, phi)
    Bv, _ = setup.additional_damping()
    D = law.assemble()[1] if law is not None else np.zeros((6, 6))
    b_other = np.einsum("ki,ij,kj->k", phi, Bv + D, phi)
    what = ("state-space fit" if rad.method == "state_space" else
            f"convolution over {rad.memory:g} s" + (", tapered" if rad.taper != "none" else ", not tapered"))
    where = "landed" if law is not None else "free-floating"
    if rad.method == "state_space":
        # each DOF pair's fit is passive, but a mode that couples pairs (sway–yaw) can still project to a
        # slightly negative damping where the true one is ~0 (a slow landed mode): its sign follows the memory
        advice = ("the fit of each DOF pair is passive, but this coupled mode's damping is ~0 and its sign follows "
                  "radiation.memory: try another memory length (scenario check shows ζ_rad), or add linear damping")
    else:
        advice = ("use radiation.method = \"state_space\" (passive by construction) or a tapered convolution "
                  "(radiation.taper = \"cosine\")")
    for k in range(w.size):
        mode = f"the {where} {names[k]} mode (T = {2 * math.pi / w[k]:.3g} s)"
        zeta_mem, zeta_tot = b_mem[k] / (2 * w[k]), (b_mem[k] + b_other[k]) / (2 * w[k])
        if b_mem[k] < 0 and b_mem[k] + b_other[k] < 0:
            problems.append(("radiation.method", f"the radiation memory ({what}) has negative damping in {mode}: "
                             f"ζ = {100 * zeta_mem:.3g} %, {100 * zeta_tot:.3g} % with the fender's and additional "
                             f"damping, so that mode grows; {advice}"))
        elif b_mem[k] < 0:
            warns.append(("radiation.method", f"the radiation memory ({what}) has slightly negative damping in "
                          f"{mode}: ζ = {100 * zeta_mem:.2g} % (the fender's damping keeps it stable: "
                          f"{100 * zeta_tot:.2g} % in all)"
                          + ("" if rad.method == "state_space" else "; radiation.method = \"state_space\" is passive")))
    if not problems:
        notes.append(f"radiation memory ({what}) damps every {where} mode in the band: "
                     + ", ".join(f"{n} {2 * math.pi / x:.3g} s ζ_rad {100 * b / (2 * x):.2g} %"
                                 for n, x, b in zip(names, w, b_mem)))
    return MemoryCheck(tuple(problems), tuple(warns), tuple(notes))


#: The landed modes of the last few (database, contact law, push) checked: a campaign's cases that differ only in
#: their sea share them (eight cases of the demo: 0.11 s of its start).
_MODES: dict = {}


def _landed_modes(db, law, thrust: float, position):
    """:func:`boatland.landing.law.landed_modes`, remembered by the database (the object itself) and the law's
    and push's values."""
    parts = [] if law is None else [np.ascontiguousarray(getattr(law, f.name)).tobytes()
                                    if isinstance(getattr(law, f.name), np.ndarray) else repr(getattr(law, f.name))
                                    for f in dataclasses.fields(law)]
    key = (id(db), tuple(parts), float(thrust), tuple(float(v) for v in position))
    hit = _MODES.get(key)
    if hit is not None and hit[0] is db:
        return hit[1]
    modes = landed_modes(db, law, thrust, position)
    if len(_MODES) >= 16:
        _MODES.pop(next(iter(_MODES)))
    _MODES[key] = (db, modes)
    return modes


def check_radiation(setup: Setup, memory: RadiationMemory) -> None:
    """Refuse a radiation memory that would make a landed natural mode grow (:func:`check_memory`); warn
    where its damping is negative but the mode stays damped. Done once per memory (a campaign checks
    each case before its trials).

    Raises
    ------
    BoatlandInputError
        The first problem, naming the scenario file and the key.
    """
    check = check_memory(setup, memory)
    if check.problems:
        key, msg = check.problems[0]
        raise BoatlandInputError(f"{setup.source}: {key}: {msg}")
    for key, msg in check.warnings:
        warnings.warn(f"{setup.source}: {key}: {msg}", ScenarioWarning, stacklevel=3)
