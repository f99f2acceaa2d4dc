"""Sinks receive the trial while it runs: consecutive final blocks that add up to the result."""

import numpy as np
import pytest

from boatland.trial.sink import TrialSink
from boatland.trial.simulate import BlowUpError, simulate
from boatland.landing.setup import Setup


class Collector:
    def __init__(self):
        self.calls, self.blocks, self.info, self.result = [], [], None, None

    def start(self, info):
        self.calls.append("start")
        self.info = info

    def steps(self, block):
        self.calls.append("steps")
        self.blocks.append({k: np.array(getattr(block, k)) for k in ("t", "x", "mode", "fn", "ft", "tpos", "F_exc")}
                           | {"k": (block.k0, block.k1), "events": list(block.events)})

    def finish(self, result):
        self.calls.append("finish")
        self.result = result


def test_blocks_cover_every_step_and_equal_the_result(landing):
    sc, db = landing
    sc = sc.replace({"simulation.duration": 90.0})
    sink = Collector()
    assert isinstance(sink, TrialSink)
    r = simulate(sc, db, sinks=[sink])
    assert sink.calls[0] == "start" and sink.calls[-1] == "finish" and set(sink.calls[1:-1]) == {"steps"}
    assert sink.info.n_steps == len(r.t) - 1 and sink.result is r
    ks = [b["k"] for b in sink.blocks]
    assert ks[0][0] == 0 and ks[-1][1] == len(r.t) and all(a[1] == b[0] for a, b in zip(ks, ks[1:]))
    per = round(1.0 / Setup.of(sc, db).dt)                                     # one second of simulated time,
    assert all((k1 - k0) % per == 0 for k0, k1 in ks[:-1]) and max(k1 - k0 for k0, k1 in ks) >= per  # or several
    for name in ("t", "x", "mode", "fn", "ft", "tpos", "F_exc"):
        np.testing.assert_array_equal(np.concatenate([b[name] for b in sink.blocks]), getattr(r, name))
    assert [e for b in sink.blocks for e in b["events"]] == r.events and r.slip_events()


def test_a_blown_up_run_still_reaches_the_sink(landing):
    sc, db = landing
    bad = sc.replace({"simulation.duration": 60.0, "simulation.dt": 0.05, "fender.stiffness": 5e8})
    sink = Collector()
    with pytest.raises(BlowUpError) as err:
        simulate(bad, db, sinks=[sink])
    assert sink.result is err.value.result and sink.result.status != 0
    assert sink.blocks[-1]["k"][1] == len(sink.result.t)
