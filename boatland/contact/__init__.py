"""Fender contact kernels: spring–damper normal force, Stribeck friction, stick–slip solve (issue 5)."""
