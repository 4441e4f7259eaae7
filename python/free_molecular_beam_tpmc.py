#!/usr/bin/python3
"""Free-molecular damping of the gas damping study's beam over its substrate, by a linearised
(deviational) test-particle Monte Carlo: an independent reference for ESBGK at Kn >> 1
(docs/gas_damping.md).

Collisionless gas, f = M + df with M the ambient Maxwellian (rho, T) and df linear in the beam
velocity U = (0, -V). Geometry of cases/gas_damping_regimes (full width): substrate y = 0
(diffuse, at rest), beam [-b, b] x [g, g + t] (diffuse, moving), open sides x = +-X and top
y = Y (incoming df = 0: the pressure boundaries). Diffuse walls re-emit every incident
deviational particle with its weight (a number flux) as a flux-weighted half-Maxwellian at T
(zero net flux through a wall at rest). The moving beam also emits, per unit area on each
face with normal m (out of the gas) and U_m = U . m, the first-order part of its re-emitted
Maxwellian n_w M(c - U) that does not depend on the incident gas:
    s(c) = rho Mhat(c) [c . U / (R T) - U_m / (2 sqrt(R T / 2 pi))]   on c . m < 0,
the drift term plus the density change that keeps the wall impermeable in its own frame
(its net flux is rho U_m, the gas the face sweeps). Sampled from the flux-weighted
half-Maxwellian, each source particle carries the signed weight
    (face length / N) sqrt(R T / 2 pi) rho [c . U / (R T) - U_m / (2 sqrt(R T / 2 pi))].
Force on the beam: the sum over its wall crossings of weight x (c_in - c_out), the source
particles' -weight x c_out included. The isolated beam (--no-substrate: the substrate open)
must give the closed form p / sqrt(2 pi R T) [(4 + pi) w + 2 t] (free_molecular_wall.hpp).

Only in-plane velocities matter (2D geometry); the normal component of an emitted particle is
Rayleigh(sqrt(R T)), the tangential one normal(0, R T).

Usage: free_molecular_beam_tpmc.py [--particles 200000] [--batches 10] [--no-substrate]
       [--pressure 0.1] [--seed 1]   -> one JSON line: c (N s/m^2 per unit depth), its
       standard error from the batches, the closed form, and their ratio.
"""
import argparse
import json
import math

import numpy as np

R, T = 208.13, 273.15
V = 0.1
B, GAP, THICK = 22.5e-6, 7e-6, 1.5e-6
X, Y = B + 3 * GAP, GAP + THICK + 3 * GAP
RT = R * T
S = math.sqrt(RT)
FLUX = math.sqrt(RT / (2 * math.pi))


def emit(rng, n, normal_out, tangent):
    """Velocities of n particles emitted by a wall whose normal (out of the gas) is
    normal_out: flux-weighted half-Maxwellian at T."""
    cn = S * np.sqrt(-2 * np.log(1 - rng.random(n)))
    ct = S * rng.standard_normal(n)
    e = -np.asarray(normal_out)
    return cn[:, None] * e[None, :] + ct[:, None] * np.asarray(tangent)[None, :]


# Beam faces: (name, normal out of the gas, tangent, point a, point b)
FACES = [
    ("bottom", (0.0, 1.0), (1.0, 0.0), (-B, GAP), (B, GAP)),
    ("top", (0.0, -1.0), (1.0, 0.0), (-B, GAP + THICK), (B, GAP + THICK)),
    ("left", (1.0, 0.0), (0.0, 1.0), (-B, GAP), (-B, GAP + THICK)),
    ("right", (-1.0, 0.0), (0.0, 1.0), (B, GAP), (B, GAP + THICK)),
]


def batch(rng, n_per_face_unit, rho, substrate):
    U = np.array([0.0, -V])
    pos, vel, w = [], [], []
    force = np.zeros(2)
    for _, m, tau, a, b in FACES:
        a, b = np.array(a), np.array(b)
        length = np.linalg.norm(b - a)
        n = max(1, int(n_per_face_unit * length / (2 * B)))
        p = a[None, :] + rng.random(n)[:, None] * (b - a)[None, :]
        c = emit(rng, n, m, tau)
        u_m = U @ np.array(m)
        weight = length / n * FLUX * rho * (c @ U / RT - u_m / (2 * FLUX))
        force -= (weight[:, None] * c).sum(axis=0)
        pos.append(p)
        vel.append(c)
        w.append(weight)
    pos, vel, w = np.concatenate(pos), np.concatenate(vel), np.concatenate(w)
    inf = np.inf
    for _ in range(100000):
        if len(w) == 0:
            break
        x, y, u, v = pos[:, 0], pos[:, 1], vel[:, 0], vel[:, 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            # open boundaries
            t_open = np.minimum(np.where(u > 0, (X - x) / u, np.where(u < 0, (-X - x) / u, inf)),
                                np.where(v > 0, (Y - y) / v, inf))
            t_sub = np.where(v < 0, -y / v, inf) if substrate else np.full_like(x, inf)
            t_bot = np.where((v > 0) & (y < GAP), (GAP - y) / v, inf)
            t_top = np.where((v < 0) & (y > GAP + THICK), (GAP + THICK - y) / v, inf)
            t_lft = np.where((u > 0) & (x < -B), (-B - x) / u, inf)
            t_rgt = np.where((u < 0) & (x > B), (B - x) / u, inf)
        # beam faces only count where the crossing lies on the face
        t_bot = np.where(np.abs(x + np.where(np.isfinite(t_bot), t_bot, 0) * u) <= B, t_bot, inf)
        t_top = np.where(np.abs(x + np.where(np.isfinite(t_top), t_top, 0) * u) <= B, t_top, inf)
        yl = y + np.where(np.isfinite(t_lft), t_lft, 0) * v
        t_lft = np.where((yl >= GAP) & (yl <= GAP + THICK), t_lft, inf)
        yr = y + np.where(np.isfinite(t_rgt), t_rgt, 0) * v
        t_rgt = np.where((yr >= GAP) & (yr <= GAP + THICK), t_rgt, inf)
        ts = np.stack([t_open, t_sub, t_bot, t_top, t_lft, t_rgt])
        which = np.argmin(ts, axis=0)
        t = ts[which, np.arange(len(w))]
        pos = pos + t[:, None] * vel
        keep = which != 0
        new_vel = vel.copy()
        hit_sub = which == 1
        if hit_sub.any():
            new_vel[hit_sub] = emit(rng, hit_sub.sum(), (0.0, -1.0), (1.0, 0.0))
            pos[hit_sub, 1] = 0.0
        for k, (_, m, tau, a, b) in enumerate(FACES):
            hit = which == 2 + k
            if hit.any():
                c_out = emit(rng, hit.sum(), m, tau)
                force += (w[hit][:, None] * (vel[hit] - c_out)).sum(axis=0)
                new_vel[hit] = c_out
                if m[1] != 0:
                    pos[hit, 1] = a[1]
                else:
                    pos[hit, 0] = a[0]
        pos, vel, w = pos[keep], new_vel[keep], w[keep]
    return force


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--particles", type=int, default=200000, help="source particles per batch")
    ap.add_argument("--batches", type=int, default=10)
    ap.add_argument("--pressure", type=float, default=0.1)
    ap.add_argument("--no-substrate", action="store_true")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    rho = args.pressure / RT
    # particles per face proportional to its length: n_per_face_unit for the bottom face
    n_unit = args.particles / (2 + 2 * THICK / (2 * B))
    c = np.array([batch(rng, n_unit, rho, not args.no_substrate)[1] / V
                  for _ in range(args.batches)])
    closed = args.pressure / math.sqrt(2 * math.pi * RT) * ((4 + math.pi) * 2 * B + 2 * THICK)
    out = {"pressure": args.pressure, "substrate": not args.no_substrate,
           "particles": args.particles, "batches": args.batches,
           "c": c.mean(), "standard_error": c.std(ddof=1) / math.sqrt(len(c)),
           "closed_form_isolated": closed, "ratio_to_closed_form": c.mean() / closed}
    print(json.dumps(out))


if __name__ == "__main__":
    main()
