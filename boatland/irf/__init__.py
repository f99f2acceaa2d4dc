"""Radiation memory kernels: impulse-response functions, A∞ (Ogilvie), state-space fits (issue 3)."""
