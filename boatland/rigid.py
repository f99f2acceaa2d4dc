"""Rigid-body kinematics shared by the kernels (bottom layer: numba, no dependencies on boatland)."""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["add_point_force", "angular_velocity", "euler_moment", "rotation_into", "rotation_matrix"]


@njit(cache=True, _nrt=False, forceinline=True)
def rotation_into(phi, theta, psi, R):
    """Body → global rotation for roll φ, pitch θ, yaw ψ (z-y-x convention, R = Rz(ψ) Ry(θ) Rx(φ)), written
    into ``R`` (3, 3) — for a kernel's step loop, which must not allocate."""
    cf, sf = np.cos(phi), np.sin(phi)
    ct, st = np.cos(theta), np.sin(theta)
    cp, sp = np.cos(psi), np.sin(psi)
    R[0, 0] = cp * ct
    R[0, 1] = cp * st * sf - sp * cf
    R[0, 2] = cp * st * cf + sp * sf
    R[1, 0] = sp * ct
    R[1, 1] = sp * st * sf + cp * cf
    R[1, 2] = sp * st * cf - cp * sf
    R[2, 0] = -st
    R[2, 1] = ct * sf
    R[2, 2] = ct * cf


@njit(cache=True)
def rotation_matrix(phi, theta, psi):
    """Body → global rotation for roll φ, pitch θ, yaw ψ (z-y-x convention, R = Rz(ψ) Ry(θ) Rx(φ));
    a new array (:func:`rotation_into` fills one)."""
    R = np.empty((3, 3))
    rotation_into(phi, theta, psi, R)
    return R


@njit(cache=True, _nrt=False, forceinline=True)
def euler_moment(R, mx, my, mz):
    r"""The generalised forces of the Euler angles (φ, θ, ψ) of a moment M (local frame, about the reference
    point) on the body rotated by ``R``: its components about the Euler angles' own axes,

    .. math:: Q_\phi = M\cdot e_\phi,\quad Q_\theta = M\cdot e_\theta,\quad Q_\psi = M\cdot e_z,\qquad
              e_\phi = R\,e_x = (c_\psi c_\theta,\ s_\psi c_\theta,\ -s_\theta),\quad
              e_\theta = R_z(\psi)\,e_y = (-s_\psi,\ c_\psi,\ 0)

    (z-y-x angles: ψ about the local z, θ about the once-turned y, φ about the body x). They are the virtual
    work of the load per unit change of each angle, :math:`Q_j = F\cdot\partial p/\partial q_j` with
    :math:`\partial(Rr)/\partial q_j = e_j \times Rr` (e.g. Goldstein, Poole & Safko (2002), *Classical
    Mechanics*, 3rd ed., §1.4 and §4.4). The moment's local components would add terms of the order of an angle
    times a moment that the body does not feel — at a landing, yaw turning the fender's pitch moment (its lever
    ≈ 14 m × the vertical friction) into roll. To first order in the angles
    :math:`Q_\phi = M_x + \psi M_y - \theta M_z`, :math:`Q_\theta = M_y - \psi M_x`
    (:func:`boatland.landing.law.preload_stiffness` takes these terms of the static loads)."""
    h = np.sqrt(R[0, 0] * R[0, 0] + R[1, 0] * R[1, 0])
    return (mx * R[0, 0] + my * R[1, 0] + mz * R[2, 0], (-mx * R[1, 0] + my * R[0, 0]) / h, mz)


@njit(cache=True, _nrt=False, forceinline=True)
def angular_velocity(R, v):
    r"""The body's angular velocity ω (local frame) from the Euler-angle rates ``v[3:6]`` = (φ̇, θ̇, ψ̇):
    :math:`\omega = e_\phi\dot\phi + e_\theta\dot\theta + e_z\dot\psi` (:func:`euler_moment`: the same
    axes, so that a load's power is :math:`Q\cdot\dot q`), and :math:`\dot e_\phi\dot\phi +
    \dot e_\theta\dot\theta` (the axes' own turning, for accelerations): returns
    (ωx, ωy, ωz, ax, ay, az)."""
    h = np.sqrt(R[0, 0] * R[0, 0] + R[1, 0] * R[1, 0])
    c, s = R[0, 0] / h, R[1, 0] / h                   # cos ψ, sin ψ
    fd, td, pd = v[3], v[4], v[5]
    wx = R[0, 0] * fd - s * td
    wy = R[1, 0] * fd + c * td
    wz = R[2, 0] * fd + pd
    # ė_φ = ω × e_φ (the body x axis turns with the body); ė_θ = ψ̇ (−cos ψ, −sin ψ, 0)
    ax = fd * (wy * R[2, 0] - wz * R[1, 0]) - td * pd * c
    ay = fd * (wz * R[0, 0] - wx * R[2, 0]) - td * pd * s
    az = fd * (wx * R[1, 0] - wy * R[0, 0])
    return wx, wy, wz, ax, ay, az


@njit(cache=True, _nrt=False, forceinline=True)
def add_point_force(R, rx, ry, rz, d0, d1, d2, f, out):
    """Add to ``out`` (6) the generalised force of the force f·d (local frame) acting at lever r from the
    reference point, on the body rotated by ``R``: [f d; Q(r × f d)], Q the moment's components about the
    Euler axes (:func:`euler_moment`)."""
    fx, fy, fz = f * d0, f * d1, f * d2
    out[0] += fx
    out[1] += fy
    out[2] += fz
    q4, q5, q6 = euler_moment(R, ry * fz - rz * fy, rz * fx - rx * fz, rx * fy - ry * fx)
    out[3] += q4
    out[4] += q5
    out[5] += q6
