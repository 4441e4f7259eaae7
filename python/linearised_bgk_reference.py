#!/usr/bin/python3
"""Reference values of the linearised BGK model between diffuse parallel plates, against which
test/drivers/test_gas_linearised_bgk.sh checks rfmems-gas's normalised wall answers.

Plane Couette flow (walls at y = -+H/2 moving at -+U/2) and plane heat transfer (walls at
T0 -+ dT/2), lengths in H, velocities c in v0 = sqrt(2 R T0), perturbation
f = f0 (1 + h), f0 = pi^(-3/2) exp(-c^2), linearised BGK with collision frequency
delta = p0 H / (mu0 v0):
    c_y dh/dy = delta (nu + 2 c.u + tau (c^2 - 3/2) - h).
Couette: h = 2 c_z Z(y, c_y) (per U / v0), c_y dZ/dy = delta (u - Z), u = int Z g dc_y,
g = exp(-c_y^2) / sqrt(pi); diffuse walls send Z = -+1/2;
    P = -p_xy v0 / (p0 U) = -2 int c_y Z g dc_y.
Heat transfer (per dT / T0): reduced Phi = int h e(c_p) dc_p, Psi = int (c_p^2 - 1) h e(c_p) dc_p
over the two directions along the walls (e = exp(-c_p^2) / pi):
    c_y dPhi/dy = delta (nu + tau (c_y^2 - 1/2) - Phi),  c_y dPsi/dy = delta (tau - Psi),
    nu = int Phi g,  tau = 2/3 int [(c_y^2 - 1/2) Phi + Psi] g;
walls send Phi = nu_w + tau_w (c_y^2 - 1/2), Psi = tau_w (tau_w = -+1/2), nu_w from zero mass flux;
    q* = q / (p0 v0 dT / T0) = int c_y [(c_y^2 - 3/2) Phi + Psi] g dc_y  (its magnitude).
Discrete ordinates: Gauss-Legendre on each half-range c_y in (0, 6] (the half-range split
puts the wall discontinuity at c_y = 0 between the halves); along each ordinate exact
integration of the characteristic with the moments piecewise linear on a uniform y-grid;
GMRES on the moments. Second order in the y-grid: the printed value is Richardson-
extrapolated from N and 2N intervals.

Checks: the free-molecular limit 1/sqrt(pi) (both); at delta = 10 the slip and jump
asymptotes 1 / (delta + 2 sigma_P) with BGK's viscous slip coefficient sigma_P = 1.0162
(Loyalka, Petrellis & Storvick 1975) and (5/4) / (delta + 2 d_1) with BGK's temperature jump
coefficient d_1 = 1.30272 (Sone's): 0.083109 and 0.099167 (second-order slip terms aside).

Plane Poiseuille flow driven by a body force a along x (the linear equivalent of a pressure
gradient xi = (H / p0) dp/dx = -2 a H / v0^2): h = 2 (a H / v0^2) c_x Z(y, c_y),
    c_y dZ/dy = delta (u + 1 / delta - Z),  u = int Z g dc_y,  walls at rest send Z = 0;
    G = -(2 / (xi H v0)) int u_x dy = int u dy over the gap   (continuum delta / 6 + sigma_P).

Usage: linearised_bgk_reference.py [couette|heat|poiseuille] [deltas, default 0.1,1,10]
                                   [N, default 1600]
"""
import sys

import numpy as np
from scipy.sparse.linalg import LinearOperator, gmres


def half_range(m=64, cmax=6.0):
    x, w = np.polynomial.legendre.leggauss(m)
    c = (x + 1) * cmax / 2
    return c, w * cmax / 2 * np.exp(-c * c) / np.sqrt(np.pi)


def characteristic(delta, dy, c):
    """Per ordinate (|c_y| = c): f_{i+1} = f_i E + S_{i+1} A - (S_{i+1} - S_i) B."""
    a = delta * dy / c
    e = np.exp(-a)
    return e, 1 - e, (1 - e * (1 + a)) / a


def sweep(source, coeffs, inflow):
    e, a, b = coeffs
    out = np.empty_like(source)
    out[0] = inflow
    for i in range(source.shape[0] - 1):
        out[i + 1] = out[i] * e + source[i + 1] * a - (source[i + 1] - source[i]) * b
    return out


def fixed_point(apply, n):
    """Solves x = apply(x) for the linear map apply (affine part at x = 0) by GMRES."""
    b = apply(np.zeros(n))
    op = LinearOperator((n, n), matvec=lambda x: x - (apply(x) - b))
    x, info = gmres(op, b, tol=1e-13, atol=0, restart=300, maxiter=3000)
    if info != 0:
        raise RuntimeError(f"GMRES: {info}")
    return x


def couette(delta, n):
    c, w = half_range()
    k = characteristic(delta, 1.0 / n, c)

    def profiles(u):
        s = np.repeat(u[:, None], c.size, axis=1)
        up = sweep(s, k, -0.5 * np.ones(c.size))  # c_y > 0, from the wall at -U/2
        down = sweep(s[::-1], k, 0.5 * np.ones(c.size))[::-1]
        return up, down

    u = fixed_point(lambda u: sum(z @ w for z in profiles(u)), n + 1)
    up, down = profiles(u)
    return np.mean(-2 * (up @ (c * w) - down @ (c * w)))


def heat(delta, n):
    c, w = half_range()
    c2 = c * c
    k = characteristic(delta, 1.0 / n, c)
    t_bottom, t_top = -0.5, 0.5

    def profiles(x):
        nu, tau, n_bottom, n_top = x[: n + 1], x[n + 1 : 2 * n + 2], x[-2], x[-1]
        s_phi = nu[:, None] + tau[:, None] * (c2[None, :] - 0.5)
        s_psi = np.repeat(tau[:, None], c.size, axis=1)
        return (
            sweep(s_phi, k, n_bottom + t_bottom * (c2 - 0.5)),
            sweep(s_psi, k, t_bottom * np.ones(c.size)),
            sweep(s_phi[::-1], k, n_top + t_top * (c2 - 0.5))[::-1],
            sweep(s_psi[::-1], k, t_top * np.ones(c.size))[::-1],
        )

    def apply(x):
        phi_up, psi_up, phi_down, psi_down = profiles(x)
        nu = (phi_up + phi_down) @ w
        tau = 2 / 3 * ((phi_up + phi_down) @ ((c2 - 0.5) * w) + (psi_up + psi_down) @ w)
        # Zero mass flux at each wall: nu_w / (2 sqrt(pi)) + tau_w / (4 sqrt(pi)) equals the
        # outgoing flux int_{c_y < 0} |c_y| Phi g (bottom), int_{c_y > 0} c_y Phi g (top).
        n_bottom = -t_bottom / 2 + 2 * np.sqrt(np.pi) * (phi_down[0] @ (c * w))
        n_top = -t_top / 2 + 2 * np.sqrt(np.pi) * (phi_up[-1] @ (c * w))
        return np.concatenate([nu, tau, [n_bottom, n_top]])

    phi_up, psi_up, phi_down, psi_down = profiles(fixed_point(apply, 2 * n + 4))
    flux = lambda phi, psi: phi @ (c * (c2 - 1.5) * w) + psi @ (c * w)
    return abs(np.mean(flux(phi_up, psi_up) - flux(phi_down, psi_down)))


def poiseuille(delta, n):
    c, w = half_range(128)
    k = characteristic(delta, 1.0 / n, c)

    def profiles(u):
        s = np.repeat(u[:, None] + 1 / delta, c.size, axis=1)
        up = sweep(s, k, np.zeros(c.size))  # walls at rest re-emit Z = 0
        down = sweep(s[::-1], k, np.zeros(c.size))[::-1]
        return up, down

    u = fixed_point(lambda u: sum(z @ w for z in profiles(u)), n + 1)
    return np.sum((u[1:] + u[:-1]) / 2) / n


def main():
    problem = sys.argv[1] if len(sys.argv) > 1 else "couette"
    deltas = [float(d) for d in (sys.argv[2] if len(sys.argv) > 2 else "0.1,1,10").split(",")]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 1600
    solve = {"couette": couette, "heat": heat, "poiseuille": poiseuille}[problem]
    for delta in deltas:
        coarse, fine = solve(delta, n // 2), solve(delta, n)
        print(f"{problem} delta = {delta:g}: {fine + (fine - coarse) / 3:.7f} "
              f"(N = {n}: {fine:.7f}, N = {n // 2}: {coarse:.7f})")


if __name__ == "__main__":
    main()
