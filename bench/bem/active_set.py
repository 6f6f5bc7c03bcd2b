#!/usr/bin/env python3
"""An active-set (primal-dual) outer loop around plain preconditioned CG: does it beat
Polonsky-Keer in FFT pairs?  A numpy prototype (not wearscale's solver) asked one
question of the preconditioner study: inside a fixed contact set no point is clipped, so u = K p
follows by linearity (u -= tau K t: one FFT pair an inner iteration, plus the
two-level preconditioner's quarter) and u = K p is transformed once per update of
the set.  It counts inner iterations, set updates and FFT pairs to 1e-10 on the
issue's surface (local_preconditioners.surface), with wearscale's TwoLevelStiffness
(local_preconditioners' fw0.05:1); no timings.

Usage: active_set.py N ETA [ETA ...]   (ETA: inner CG stops at ETA x its first residual)
e.g.   active_set.py 512 0.1 0.3
Results recorded in docs/bem.md ("The two-level preconditioner").
"""
import sys
import time

import numpy as np

import local_preconditioners as lp

COARSE_PAIR = 0.23  # the two-level's FFT pair on a quarter of the points, in pairs of the grid


def active_set_solve(h, mean_pressure, K, M, eta, tol=1e-10, max_inner=200, max_outer=200):
    points = h.size
    h_rms = np.sqrt(np.mean((h - h.mean()) ** 2))
    p = np.full(h.shape, mean_pressure)
    u = K(p)
    pairs, inner = 1.0, 0
    active = np.ones(h.shape, bool)
    for outer in range(max_outer):
        # Plain preconditioned CG on the set, at zero mean on it (the load stays imposed).
        d, rz_old, r_first = np.zeros_like(h), None, None
        for _ in range(max_inner):
            gap = u - h
            r = np.where(active, gap - gap[active].mean(), 0.0)
            norm = np.sqrt(np.sum(r * r))
            r_first = norm if r_first is None else r_first
            if norm <= eta * r_first or np.sum(np.abs(p * r)) / (np.sum(np.abs(p)) * h_rms) < tol:
                break
            z = np.where(active, M(r), 0.0)
            z[active] -= z[active].mean()
            rz = np.sum(r * z)
            d = z if rz_old is None else z + rz / rz_old * d
            rz_old = rz
            t = K(d)
            pairs += 1.0 + COARSE_PAIR
            inner += 1
            tau = np.sum(r * d) / np.sum((t - t[active].mean())[active] * d[active])
            p, u = p - tau * d, u - tau * t  # no clipping inside the set: exact
        # The set update: pressures kept where positive, penetrating points admitted.
        gap = u - h
        g = gap - gap[active].mean()
        admitted = (~active) & (g < 0)
        p = np.where(active, np.maximum(p, 0.0), 0.0) + np.where(admitted, -1e-3 * g, 0.0)
        active = p > 0
        p *= mean_pressure * points / p.sum()
        u = K(p)
        pairs += 1.0
        gap = u - h
        g = gap - gap[active].mean()
        if np.sum(p * np.abs(g)) / (np.sum(p) * h_rms) < tol and not np.any((~active) & (g < 0)):
            return outer + 1, inner, pairs, p
    return -1, inner, pairs, p


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    n = int(sys.argv[1])
    h = lp.surface(n)
    q = lp.wavenumbers(n)
    K = lp.fourier_operator(n, np.where(q > 0, 2 / np.maximum(q, 1e-300), 0.0))
    M = lp.preconditioner("fw0.05:1", n)
    for eta in (float(v) for v in sys.argv[2:]):
        start = time.time()
        outer, inner, pairs, p = active_set_solve(h, 0.03, K, M, eta)
        print(f"{n}^2 eta {eta}: {outer} set updates, {inner} inner iterations, {pairs:.1f} FFT pairs "
              f"({pairs / max(outer + inner, 1):.2f} a step), A/A0 = {np.mean(p > 0):.4f} ({time.time() - start:.1f} s)")


if __name__ == "__main__":
    main()
