"""The scenario on its vessel: the fender on the landing's tubes, linearised and as the kernel takes it.

- :mod:`~boatland.landing.law` — the linear restraint of each contact (:class:`ContactLaw`), the static
  preload and its geometric stiffness, the landed natural modes.
"""
