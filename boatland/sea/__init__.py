"""The sea: spectral parts, sea states, records, the Gaussian sea, the excitation they drive, the pile's
scattered wave.

- :mod:`~boatland.sea.states` — :class:`SpectrumPart`, :class:`SeaState`, :class:`RegularWave`,
  :class:`MeasuredRecord` (one interface: ``realise`` and ``excitation``) and the excitation assembly;
- :mod:`~boatland.sea.gaussian` — the sea as a Gaussian process on a fixed grid (rare-event sampling);
- :mod:`~boatland.sea.records` — wave-gauge records read from CSV;
- :mod:`~boatland.sea.pile` — the monopile's scattered wave (MacCamy–Fuchs) and its force on the hull.

The numerical kernels (spectra, synthesis, diffraction series) are :mod:`boatland.waves`, one layer down.
"""
