"""Loads beside the waves: current and wind drag (:mod:`~boatland.loads.drag`, :mod:`~boatland.loads.current`,
:mod:`~boatland.loads.wind`), the mean and slowly varying wave drift (:mod:`~boatland.loads.drift`) and the
skipper's throttle (:mod:`~boatland.loads.skipper`). Each file holds one load: its scenario keys, its defaults
with their sources, and the arrays (or kernel function) the integrator takes.
"""
