"""Time integration kernels: RK4 Cummins stepper with convolution or state-space memory (issue 5)."""

from boatland.integrate.cummins import STATUS_MESSAGES, STATUS_NAN, STATUS_OK, STATUS_RUNAWAY, run_cummins

__all__ = ["run_cummins", "STATUS_OK", "STATUS_NAN", "STATUS_RUNAWAY", "STATUS_MESSAGES"]
