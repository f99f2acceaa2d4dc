"""The time domain's friction margin while the fender is stuck (shared by tests/test_rigid.py and
tests/validation/test_drag_skewness.py): contact 1's up-slip margin −(μ f_n + f_v), the load-like side, from the
access's start to a record's first slip."""

from __future__ import annotations

import numpy as np


def up_margin_records(sc, db, seeds: int, mu: float = 0.8, contact: int = 1, first_seed: int = 500) -> list:
    """One array per seed (``first_seed`` …) of −(μ f_n + f_v) at ``contact`` over the stuck part of the access."""
    from boatland.landing.setup import Setup
    from boatland.trial.simulate import simulate

    memory = Setup.of(sc, db).memory()
    out = []
    for k in range(seeds):
        r = simulate(sc.replace({"simulation.seed": first_seed + k}), db, memory=memory)
        rows = np.flatnonzero(r.t >= r.exposure_from)
        slips = r.slip_rows[0]
        slips = slips[slips >= rows[0]]
        if slips.size:
            rows = rows[rows < slips[0]]
        out.append(-(mu * r.fn[rows, contact] + r.ft[rows, contact, 0]))
    return out
