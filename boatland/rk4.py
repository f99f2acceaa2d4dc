r"""Classic fourth-order Runge–Kutta (Kutta 1901) as data: its Butcher tableau, read by the integrator
(:mod:`boatland.integrate.cummins`), which hands the weights on to the contact kernel
(:func:`boatland.contact.fender.accumulate_sliding`: a step's slide and friction work are the b-weighted
quadrature of its stages).

.. math::
    \begin{array}{c|cccc}
    0   &     &     &   & \\
    1/2 & 1/2 &     &   & \\
    1/2 & 0   & 1/2 &   & \\
    1   & 0   & 0   & 1 & \\ \hline
        & 1/6 & 1/3 & 1/3 & 1/6
    \end{array}
    \qquad y_{n+1} = y_n + \Delta t \sum_s b_s k_s, \quad
    k_s = f\big(t_n + c_s\Delta t,\; y_n + \Delta t\, a_{s,s-1} k_{s-1}\big)

Classic RK4 is a chain: each stage uses only the previous one (:data:`A_NEXT`), its times are whole
half steps (:data:`C_HALF_STEPS`, the rows of the excitation series on the half-step grid). The update
itself is written out in the integrator as ``dt / 6.0 * (k0 + 2 k1 + 2 k2 + k3)``, which is
:math:`\Delta t \sum_s b_s k_s` (tests/test_rk4.py holds them equal).

Reference: Hairer, E., Nørsett, S. P. & Wanner, G. (1993), *Solving Ordinary Differential Equations I*,
2nd ed., Springer, §II.1, Table 1.2; San Nicolás Méndez 2024 (DTU) §4.2 for RK4 on the Cummins equation.
"""

__all__ = ["A", "B", "C", "A_NEXT", "C_HALF_STEPS", "STAGES"]

#: Number of stages.
STAGES = 4
#: Stage coefficients a_{s,j} (lower triangular).
A = ((0.0, 0.0, 0.0, 0.0),
     (0.5, 0.0, 0.0, 0.0),
     (0.0, 0.5, 0.0, 0.0),
     (0.0, 0.0, 1.0, 0.0))
#: Weights b_s (the friction work of a step is their quadrature of the stages' power).
B = (1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0)
#: Nodes c_s (fractions of the step).
C = (0.0, 0.5, 0.5, 1.0)
#: a_{s,s−1} of stages 1–3, indexed by s − 1: the step fraction from the step start to each stage's state.
A_NEXT = tuple(A[s][s - 1] for s in range(1, STAGES))
#: 2 c_s: each stage's time in half steps into the step (the row of half-step series).
C_HALF_STEPS = tuple(int(2 * c) for c in C)
