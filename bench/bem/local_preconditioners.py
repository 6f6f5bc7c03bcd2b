#!/usr/bin/env python3
"""Iterations of the preconditioned Polonsky-Keer CG with cheap preconditioners.

A numpy prototype (not wearscale's solver) asked one question of the preconditioner study:
can a preconditioner that costs no FFT keep the iterations of the FFT-based
one (z = S r, S = |q| E*/2, the inverse of the half-space operator), so that
an iteration costs one FFT pair (t = K d) instead of two?  It counts
iterations to 1e-10 (no timings) on the issue's surface (H = 0.8,
k_l = k_r = 4, k_s = 64, h'_rms = 1, p = 0.03 E*, seed 1) for:

  none          the unpreconditioned CG
  fourier       S applied by an FFT pair (what wearscale does)
  lap<c>        a + b(-Lap_h): a 5-point stencil, the symbol's best two-term
                fit to |q|/2 above q_a = 4 c q_min (c = 1, 4, 16 ...)
  poly<m>:<f>   a degree-m polynomial in -Lap_h fitted (log-minimax) to
                sqrt(lambda)/2 over lambda >= f (2 pi)^2
  twolevel<b>:<a>  a + b(-Lap_h) with S - (a + b q^2) added from a 4x coarser
                grid (block average, piecewise-constant prolongation)
  fw<a>:<b>     wearscale's TwoLevelStiffness: a + b(-Lap_h) with S - (a + b q^2)
                on the 2x coarser grid, full weighting R and P = 4 R^T
                (a, b in units of q_max; wearscale: fw0.05:1)

Usage: local_preconditioners.py N PRECONDITIONER [...]
e.g.   local_preconditioners.py 512 none fourier lap4 poly2:256 twolevel2:0.05 fw0.05:1
Needs numpy. Results recorded in docs/bem.md ("cheaper preconditioners").
"""
import sys
import time

import numpy as np


def surface(n, hurst=0.8, k_l=4, k_s=64, seed=1):
    rng = np.random.default_rng(seed)
    kx = np.fft.fftfreq(n) * n
    ky = np.fft.rfftfreq(n) * n
    k = np.hypot(kx[:, None], ky[None, :])
    amplitude = np.where((k >= k_l) & (k <= k_s), np.maximum(k, 1e-30) ** (-(1 + hurst)), 0.0)
    h = np.fft.irfft2(amplitude * np.exp(2j * np.pi * rng.random(k.shape)), s=(n, n))
    spectrum = np.fft.rfft2(h)
    weight = np.full(k.shape, 2.0)
    weight[:, 0] = 1.0
    weight[:, -1] = 1.0
    slope2 = np.sum(weight * np.abs(spectrum) ** 2 * (2 * np.pi * k) ** 2) / n ** 4
    return h / np.sqrt(slope2)  # h'_rms = 1 on the unit cell


def wavenumbers(n):
    kx = np.fft.fftfreq(n) * n
    ky = np.fft.rfftfreq(n) * n
    return 2 * np.pi * np.hypot(kx[:, None], ky[None, :])


def fourier_operator(n, symbol):
    return lambda f: np.fft.irfft2(symbol * np.fft.rfft2(f), s=(n, n))


def laplacian(f):  # -Lap_h times h^2
    return 4 * f - np.roll(f, 1, 0) - np.roll(f, -1, 0) - np.roll(f, 1, 1) - np.roll(f, -1, 1)


def solve(h, mean_pressure, K, M, tol=1e-10, max_iterations=3000):
    """Polonsky-Keer (1999) at imposed mean pressure, preconditioned by M (E* = 1)."""
    points = h.size
    p = np.full(h.shape, mean_pressure)
    d = np.zeros_like(h)
    g_old, restart = 1.0, True
    h_rms = np.sqrt(np.mean((h - h.mean()) ** 2))
    for it in range(max_iterations):
        gap = K(p) - h
        contact = p > 0
        gap -= gap[contact].mean()
        r = np.where(contact, gap, 0.0)
        z = np.where(contact, r if M is None else M(r), 0.0)
        z[contact] -= z[contact].mean()
        g = np.sum(gap[contact] * z[contact])
        d = np.where(contact, z + (0.0 if restart else g / g_old) * d, 0.0)
        g_old = g
        t = K(d)
        t -= t[contact].mean()
        tau = np.sum(gap[contact] * d[contact]) / np.sum(t[contact] * d[contact])
        p[contact] -= tau * d[contact]
        p[p < 0] = 0
        overlap = (p == 0) & (gap < 0)
        restart = bool(overlap.any())
        p[overlap] -= tau * gap[overlap]
        p *= mean_pressure * points / p.sum()
        if np.sum(p * np.abs(gap)) / (np.sum(p) * h_rms) < tol:
            return it + 1, p
    return -1, p


def two_term_fit(n, c):
    q_min, q_max = 2 * np.pi, np.pi * n * np.sqrt(2)
    q_a = 4 * c * q_min
    b = 0.5 / (2 * np.sqrt(q_a * q_max))
    return b * q_a * q_max, b  # a + b q^2 >= |q|/2, equal at sqrt(q_a q_max)


def polynomial_fit(m, lam_min, lam_max):
    lam = np.geomspace(lam_min, lam_max, 400)
    target = np.sqrt(lam) / 2
    w = np.ones_like(lam)
    A = np.vstack([lam ** j for j in range(m + 1)]).T / target[:, None]
    for _ in range(200):  # Lawson-like reweighting towards the minimax of log(P/target)
        c, *_ = np.linalg.lstsq(A * w[:, None], w, rcond=None)
        e = np.abs(np.log(np.maximum(A @ c, 1e-300)))
        w *= 1 + e / e.max()
        w /= w.max()
    return c


def coarse_correction(n, a, b, factor):
    """a + b q^2 from a, b in units of q_max; the coarse grid (n / factor) and S - (a + b q^2) on it."""
    q_max = np.pi * n * np.sqrt(2)
    a, b = a * q_max, b / q_max
    nc = n // factor
    qc = wavenumbers(nc)
    return a, b, nc, np.where(qc > 0, qc / 2 - (a + b * qc ** 2), 0.0)


def preconditioner(name, n):
    dx = 1.0 / n
    q = wavenumbers(n)
    if name == "none":
        return None
    if name == "fourier":
        return fourier_operator(n, np.where(q > 0, q / 2, 0.0))
    if name.startswith("lap"):
        a, b = two_term_fit(n, float(name[3:] or 1))
        return lambda f: a * f + b * laplacian(f) / dx ** 2
    if name.startswith("poly"):
        m, f = name[4:].split(":")
        c = polynomial_fit(int(m), float(f) * (2 * np.pi) ** 2, 8 / dx ** 2)

        def apply(r):
            out, x = c[0] * r, r
            for j in range(1, len(c)):
                x = laplacian(x) / dx ** 2
                out = out + c[j] * x
            return out
        return apply
    if name.startswith("twolevel"):
        b, a = (float(v) for v in name[8:].split(":"))
        a, b, nc, correction = coarse_correction(n, a, b, 4)
        correction = np.maximum(correction, 0.0)

        def apply(r):
            rc = r.reshape(nc, 4, nc, 4).mean(axis=(1, 3))
            coarse = np.fft.irfft2(correction * np.fft.rfft2(rc), s=(nc, nc))
            return a * r + b * laplacian(r) / dx ** 2 + np.repeat(np.repeat(coarse, 4, 0), 4, 1)
        return apply
    if name.startswith("fw"):
        a, b = (float(v) for v in name[2:].split(":"))
        a, b, nc, correction = coarse_correction(n, a, b, 2)

        def weight(f, axis):  # (f[2I-1] + 3 f[2I] + 3 f[2I+1] + f[2I+2]) / 8, periodic
            even, odd = np.take(f, range(0, f.shape[axis], 2), axis), np.take(f, range(1, f.shape[axis], 2), axis)
            return (np.roll(odd, 1, axis) + 3 * even + 3 * odd + np.roll(even, -1, axis)) / 8

        def prolong(c, axis):  # 2 R^T along one axis: (c[I-1] + 3c[I])/4, (3c[I] + c[I+1])/4
            out = np.repeat(c, 2, axis)
            lo, hi = [slice(None)] * 2, [slice(None)] * 2
            lo[axis], hi[axis] = slice(0, None, 2), slice(1, None, 2)
            out[tuple(lo)] = (np.roll(c, 1, axis) + 3 * c) / 4
            out[tuple(hi)] = (3 * c + np.roll(c, -1, axis)) / 4
            return out

        def apply(r):
            coarse = np.fft.irfft2(correction * np.fft.rfft2(weight(weight(r, 0), 1)), s=(nc, nc))
            return a * r + b * laplacian(r) / dx ** 2 + prolong(prolong(coarse, 0), 1)
        return apply
    raise SystemExit(f"unknown preconditioner '{name}'")


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    n = int(sys.argv[1])
    h = surface(n)
    K = fourier_operator(n, np.where(wavenumbers(n) > 0, 2 / np.maximum(wavenumbers(n), 1e-300), 0.0))
    for name in sys.argv[2:]:
        start = time.time()
        iterations, p = solve(h, 0.03, K, preconditioner(name, n))
        print(f"{n}^2 {name:>16}: {iterations} iterations, A/A0 = {np.mean(p > 0):.4f} ({time.time() - start:.1f} s)")


if __name__ == "__main__":
    main()
