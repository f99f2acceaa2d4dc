"""Wave kernels: spectra, seeded realisations, excitation series, diffraction (issues 4 and 9)."""
