r"""The skipper's throttle: a constant push, or a controller holding the fender's normal force.

A skipper landing a CTV does not push a constant force: when the bow starts to move, the throttle goes up.
``[thrust] control = { kind = "hold_force", ... }`` models that as a discrete PI controller on the sum of
the fender's normal forces :math:`N = \sum_c f_{n,c}`, updated once per RK4 step and held over the step
(a zero-order hold, as a throttle lever is), after the push's ramp:

.. math::
    e_n = N^\ast - N_{n-d}, \qquad I_n = I_{n-1} + \frac{K_p\,\Delta t}{T_i}\,e_n, \qquad
    T^{cmd}_n = T_0 + K_p e_n + I_n,

    T_n = \operatorname{clip}\!\big(T_{n-1} + \operatorname{clip}(T^{cmd}_n - T_{n-1},
          -\dot T_{max}\Delta t,\ \dot T_{max}\Delta t),\ T_{min},\ T_{max}\big)

with the reaction delay :math:`d = \lceil \tau/\Delta t\rceil \ge 1` steps (the skipper reacts to what the
bow did τ ago), the throttle's rate limit :math:`\dot T_{max}` and the propulsion's range
:math:`[T_{min}, T_{max}]`; the integral stops while the output is limited in the direction of the error
(anti-windup). :math:`T_0` is the nominal push (``thrust.force``), :math:`N^\ast` the normal force to hold
(default :math:`T_0`: a push straight at the landing carries its whole force on the fender).

No published model of a CTV skipper's throttle control was found: the structure is what the issue asks
(PI on the normal force, rate limit, reaction delay) and the defaults (:data:`DEFAULTS`) are stated
assumptions, each with its reasoning; vary them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from boatland.tomlspec import Key, Table

__all__ = ["CONTROL_KINDS", "DEFAULTS", "SKIPPER_TABLE", "Skipper", "skipper_measure", "skipper_state",
           "skipper_thrust"]

CONTROL_KINDS = ("constant", "hold_force")

#: Defaults of the "hold_force" controller — assumptions (no published skipper model), with their reasoning:
#: gain 0.5 N of push per N of normal force lost (a skipper answers a lost half of the push by half again
#: more throttle, not by a step to the limit); integral time 10 s (the slow trim of the throttle a skipper
#: makes over a few wave periods, slower than the waves so that he does not chase single waves); reaction
#: delay 0.7 s (a human's simple reaction time ~0.2–0.3 s plus a waterjet's spool-up, ~0.5 s); throttle rate
#: 50 kN/s (full bollard push of a 27 m CTV, ~250 kN for 4 × 588 kW waterjets, in ~5 s); range 0 … 1.5 × the
#: nominal push.
DEFAULTS = {"gain": 0.5, "integral_time": 10.0, "delay": 0.7, "rate": 5.0e4, "max_factor": 1.5}

#: ``[thrust.control]`` of a scenario file.
SKIPPER_TABLE = Table({
    "kind": Key(str, default="constant", choices=CONTROL_KINDS,
                doc="'constant': the push thrust.force (after its ramp); 'hold_force': a PI controller on the "
                    "fender's normal force (boatland.loads.skipper)"),
    "target": Key(float, gt=0.0, doc="normal force to hold, summed over the contacts [N] (default thrust.force)"),
    "gain": Key(float, ge=0.0, doc=f"proportional gain K_p [N/N] (default {DEFAULTS['gain']:g}, an assumption)"),
    "integral_time": Key(float, gt=0.0, doc=f"integral time T_i [s] (default {DEFAULTS['integral_time']:g}, "
                                            "an assumption)"),
    "delay": Key(float, ge=0.0, doc=f"reaction delay τ [s] (default {DEFAULTS['delay']:g}: reaction plus "
                                    "spool-up, an assumption)"),
    "rate": Key(float, gt=0.0, doc=f"largest throttle rate [N/s] (default {DEFAULTS['rate']:g}, an assumption)"),
    "max_force": Key(float, gt=0.0, doc=f"largest push [N] (default {DEFAULTS['max_factor']:g} × thrust.force)"),
    "min_force": Key(float, ge=0.0, doc="smallest push [N] (default 0)"),
}, doc="how the skipper holds the throttle (default: a constant push)")


@dataclass(frozen=True, kw_only=True)
class Skipper:
    """The push controller of a scenario (module docstring); ``kind = "constant"`` is no controller."""

    kind: str = "constant"
    target: float | None = None
    gain: float = DEFAULTS["gain"]
    integral_time: float = DEFAULTS["integral_time"]
    delay: float = DEFAULTS["delay"]
    rate: float = DEFAULTS["rate"]
    max_force: float | None = None
    min_force: float = 0.0

    @classmethod
    def from_table(cls, t) -> "Skipper":
        return cls(**{k: v for k, v in dict(t).items() if k in cls.__dataclass_fields__})

    @property
    def active(self) -> bool:
        return self.kind == "hold_force"

    def kernel(self, force: float, ramp: float, dt: float) -> np.ndarray:
        """The kernel's parameters (9,): on, first controlled step, delay [steps], K_p, K_p Δt/T_i, rate
        per step, T_min, T_max, N* — for a push ``force`` [N] ramped over ``ramp`` [s] at step ``dt``."""
        if not self.active:
            return np.zeros(9)
        start = math.ceil(ramp / dt - 1e-9)
        d = max(1, math.ceil(self.delay / dt - 1e-9))
        t_max = self.max_force if self.max_force is not None else DEFAULTS["max_factor"] * force
        target = self.target if self.target is not None else force
        return np.array([1.0, start, d, self.gain, self.gain * dt / self.integral_time, self.rate * dt,
                         self.min_force, t_max, target])

    def text(self) -> str:
        if not self.active:
            return "constant push"
        tgt = "the push" if self.target is None else f"{self.target / 1e3:.0f} kN"
        return (f"skipper holds the fender force at {tgt} (PI: gain {self.gain:g}, T_i {self.integral_time:g} s, "
                f"delay {self.delay:g} s, ≤ {self.rate / 1e3:g} kN/s)")


@njit(cache=True)
def skipper_state(sk):
    """(ring buffer of measured normal forces (delay + 1,), state (3,): last push, integral, steps measured)."""
    d = int(sk[2]) if sk[0] != 0.0 else 0
    return np.zeros(d + 1), np.zeros(3)


@njit(cache=True, _nrt=False, forceinline=True)
def skipper_thrust(n, ff, sk, buf, state):
    """(held, T): the push of step ``n``; ``held`` False before the controller starts (the stages then
    follow the ramp ``ff`` at the half steps)."""
    start = int(sk[1])
    if n < start:
        state[0] = ff[2 * n]
        return False, ff[2 * n]
    if n == start:
        state[0] = ff[2 * n]           # the controller takes over from the nominal push
    d = int(sk[2])
    L = buf.shape[0]
    e = 0.0
    if n - d >= 0 and state[2] > n - d:
        e = sk[8] - buf[(n - d) % L]
    T_prev = state[0]
    integral = state[1] + sk[4] * e
    T_cmd = ff[2 * n] + sk[3] * e + integral
    step = T_cmd - T_prev
    limited = False
    if step > sk[5]:
        step = sk[5]
        limited = True
    elif step < -sk[5]:
        step = -sk[5]
        limited = True
    T = T_prev + step
    if T > sk[7]:
        T = sk[7]
        limited = True
    elif T < sk[6]:
        T = sk[6]
        limited = True
    if not (limited and ((e > 0.0 and T >= T_prev) or (e < 0.0 and T <= T_prev))):
        state[1] = integral            # anti-windup: no integration while limited in the error's direction
    state[0] = T
    return True, T


@njit(cache=True, _nrt=False, forceinline=True)
def skipper_measure(n, fn, buf, state):
    """Store the normal force sum of row ``n`` (``fn`` per contact) for the delayed controller."""
    s = 0.0
    for c in range(fn.shape[0]):
        s += fn[c]
    buf[n % buf.shape[0]] = s
    state[2] = n + 1
