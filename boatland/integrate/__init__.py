"""Time integration kernels: RK4 Cummins stepper with convolution or state-space memory (issue 5)."""
