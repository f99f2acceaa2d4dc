"""Wave kernels: spectra, seeded realisations, measured records, excitation series (issue 4);
diffraction (issue 9).

Modules: :mod:`~boatland.waves.dispersion` (ω² = g k tanh kh, TMA depth factor),
:mod:`~boatland.waves.spectra` (JONSWAP, PM, TMA, cos-2s spreading),
:mod:`~boatland.waves.realisation` (seeded components), :mod:`~boatland.waves.measured` (gauge
records), :mod:`~boatland.waves.synthesis` (elevation, fast harmonic sums),
:mod:`~boatland.waves.excitation` (F_exc(t) through X(ω, β)). The validated model objects that
compile into these arrays are in :mod:`boatland.model.seastate`.
"""
