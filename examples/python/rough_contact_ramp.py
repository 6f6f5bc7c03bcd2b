"""Rough contact load ramp (thesis §1.1.2, §5.1): the real contact area A/A0 grows linearly with
the load at small loads, A/A0 = κ p_N/(E* h'_rms) (1.11), with κ between √(8/π) and √(2π).

A self-affine surface (H = 0.8) is pressed with increasing mean pressure; each BEM solve is
warm-started from the previous one. Writes rough_contact_ramp.png (A/A0 and κ against the load).
    python3 examples/python/rough_contact_ramp.py [--n 256] [--out out/examples]
"""
import math

import numpy as np

import wearscale as ws
from _common import arguments, check, finish, plt, save

args = arguments(__doc__.splitlines()[0], n=(256, "grid points per side"), seed=(1, "surface seed"))
L, e_star = 1.0, 1.0
s = ws.surface.generate(args.n, L, hurst=0.8, k_l=4, k_s=args.n // 8, seed=args.seed, slope_rms=1.0)
slope = ws.surface.analyze(s)["h_prime_rms"]
contact = ws.contact.NormalContact(s, e_star=e_star)
loads = np.geomspace(0.01, 0.2, 10) * e_star * slope  # p̃ = p/(E* h'_rms)
area, kappa = [], []
for p in loads:
    r = contact.solve(mean_pressure=p, tolerance=1e-10)
    area.append(r["contact_fraction"])
    kappa.append(r["contact_fraction"] / (p / (e_star * slope)))
    print(f"p/(E* h'rms) = {p / (e_star * slope):.4f}  A/A0 = {area[-1]:.5f}  kappa = {kappa[-1]:.3f}  "
          f"iterations = {r['iterations']}")

fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.6))
pt = loads / (e_star * slope)
a1.loglog(pt, area, "o-", label=f"BEM, {args.n}²")
a1.loglog(pt, math.sqrt(8 / math.pi) * pt, "--", label=r"$\sqrt{8/\pi}\,\tilde p$")
a1.loglog(pt, math.sqrt(2 * math.pi) * pt, ":", label=r"$\sqrt{2\pi}\,\tilde p$")
a1.set_xlabel(r"$p_N/(E^* h'_{rms})$")
a1.set_ylabel(r"$A/A_0$")
a1.legend()
a2.semilogx(pt, kappa, "o-")
a2.axhline(math.sqrt(8 / math.pi), ls="--", c="k")
a2.axhline(math.sqrt(2 * math.pi), ls=":", c="k")
a2.set_xlabel(r"$p_N/(E^* h'_{rms})$")
a2.set_ylabel(r"$\kappa$")
save(fig, f"{args.out}/rough_contact_ramp.png")

# (1.11): at small load κ lies between √(8/π) = 1.60 and √(2π) = 2.51 (the BEM's value
# depends on the resolution of the smallest wavelengths; the band is the thesis').
small = [k for k, p in zip(kappa, pt) if p <= 0.05]
check("kappa at small load (mean, p~ <= 0.05)", float(np.mean(small)), (math.sqrt(8 / math.pi) + math.sqrt(2 * math.pi)) / 2,
      (math.sqrt(2 * math.pi) - math.sqrt(8 / math.pi)) / 2)
check("A/A0 grows with the load (monotone)", float(all(b > a for a, b in zip(area, area[1:]))), 1.0, 0.0)
finish()
