"""Rigid-body kinematics shared by the kernels (bottom layer: numba, no dependencies on boatland)."""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["rotation_matrix", "add_point_force"]


@njit(cache=True)
def rotation_matrix(phi, theta, psi):
    """Body → global rotation for roll φ, pitch θ, yaw ψ (z-y-x convention, R = Rz(ψ) Ry(θ) Rx(φ))."""
    cf, sf = np.cos(phi), np.sin(phi)
    ct, st = np.cos(theta), np.sin(theta)
    cp, sp = np.cos(psi), np.sin(psi)
    R = np.empty((3, 3))
    R[0, 0] = cp * ct
    R[0, 1] = cp * st * sf - sp * cf
    R[0, 2] = cp * st * cf + sp * sf
    R[1, 0] = sp * ct
    R[1, 1] = sp * st * sf + cp * cf
    R[1, 2] = sp * st * cf - cp * sf
    R[2, 0] = -st
    R[2, 1] = ct * sf
    R[2, 2] = ct * cf
    return R


@njit(cache=True, _nrt=False, forceinline=True)
def add_point_force(rx, ry, rz, d0, d1, d2, f, out):
    """Add to ``out`` (6) the generalised force of the force f·d acting at lever r from the reference
    point: [f d; r × f d]."""
    fx, fy, fz = f * d0, f * d1, f * d2
    out[0] += fx
    out[1] += fy
    out[2] += fz
    out[3] += ry * fz - rz * fy
    out[4] += rz * fx - rx * fz
    out[5] += rx * fy - ry * fx
