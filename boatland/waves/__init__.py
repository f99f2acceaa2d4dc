"""Wave kernels: spectra, seeded realisations, measured records, excitation series (issue 4);
diffraction (issue 9).

Modules: :mod:`~boatland.waves.dispersion` (ω² = g k tanh kh, TMA depth factor),
:mod:`~boatland.waves.spectra` (JONSWAP, PM, TMA, cos-2s spreading),
:mod:`~boatland.waves.realisation` (seeded components), :mod:`~boatland.waves.measured` (gauge
records), :mod:`~boatland.waves.synthesis` (elevation, harmonic sums on time grids: direct or
:mod:`~boatland.waves.nufft`, a non-uniform FFT for long records),
:mod:`~boatland.waves.excitation` (F_exc(t) through X(ω, β)),
:mod:`~boatland.waves.diffraction` (MacCamy–Fuchs field around the monopile). The validated model
objects that compile into these arrays are in :mod:`boatland.sea.states` (and
:mod:`boatland.sea.pile` for the pile's scattered wave on the hull).
"""
