"""Recording a trial (edge layer): the MCAP run log, the Rerun stream, replay and report figures.

- :class:`~boatland.record.mcap_log.McapLog` — the run log, a sink written while the trial runs
  (protobuf: ``foxglove.FrameTransform``, ``foxglove.Log``, ``foxglove.SceneUpdate`` and our own
  messages, :mod:`.schemas`; framed by the ``mcap`` library with CRCs);
- :mod:`~boatland.record.foxglove_scene` — the 3-D scene and force arrows for Foxglove, and its layout
  file ``foxglove_layout.json``;
- :class:`~boatland.record.rerun_log.RerunLog` — the live Rerun stream (file, server, viewer);
- :func:`~boatland.record.reader.read_run_log` — a log read back, a truncated one recovered;
- :func:`~boatland.record.replay.replay` — a log into Rerun, same scene and layout as live;
- :func:`~boatland.record.plot.plot_run` — the report figure.

Heavy libraries (rerun, matplotlib) are imported where they are used.
"""
