"""Fig. 4.6 with a chosen Poisson's ratio: the wear map of two interacting micro-contacts
(thesis §4.4-4.5). Each region is the most severe detachment with R ≥ 1 of (4.48),
R = (C_n + (3π/8) C_inter d/l)(d/d*) C_case, at C_inter = (1 − ν sin²θ)/(2 − ν) (4.49);
filled: θ = 0 (most interaction), lines: θ = π/2 (least).

Writes wear_map_fig46_nu<ν>.png.
    python3 examples/python/wear_map_fig46.py [--poisson 0.3] [--out out/examples]
"""
import math

import numpy as np

import wearscale as ws
from _common import arguments, check, finish, plt, save

args = arguments(__doc__.splitlines()[0], poisson=(0.3, "Poisson's ratio nu in (-1, 0.5]"))
nu = args.poisson
c_max = ws.wear.interaction_constant(nu, 0.0)
c_min = ws.wear.interaction_constant(nu, math.pi / 2)
m = ws.wear.analytic_map_3d(c_inter=c_max)
fig, ax = plt.subplots(figsize=(5.2, 4.6))
ax.pcolormesh(m["x"], m["y"], m["region"].T, shading="nearest", cmap="Pastel1_r", vmin=0, vmax=8)
d = np.linspace(0.01, 1.0, 200)
names = ["one separated", "two separated", "combined"]
for case, colour in zip(range(3), ["C0", "C1", "C2"]):
    ax.plot(d, ws.wear.boundary_dstar_over_l(case, d, c_max), "-", c=colour, label=names[case])
    ax.plot(d, ws.wear.boundary_dstar_over_l(case, d, c_min), "--", c=colour)
ax.plot(d, d, "k:", label="d = d*")
ax.set_xlim(0, 1)
ax.set_ylim(0, 2)
ax.set_xlabel("d/l")
ax.set_ylabel("d*/l")
ax.set_title(f"Fig. 4.6 at ν = {nu:g}\nC_inter = {c_max:.3f} (θ = 0, filled), {c_min:.3f} (θ = π/2, dashed)", fontsize=10)
ax.legend(loc="upper left", fontsize=8)
save(fig, f"{args.out}/wear_map_fig46_nu{nu:g}.png")

check("C_inter(nu, 0) = 1/(2 - nu)  (4.49)", c_max, 1 / (2 - nu), 1e-15)
check("C_inter(nu, pi/2) = (1 - nu)/(2 - nu)  (4.49)", c_min, (1 - nu) / (2 - nu), 1e-15)
# On the boundary of one separated particle (C_n = 1, C_case = 1) at d/l = 1 (touching contacts):
# d*/l = 1 + 3π/8 C_inter (4.48).
check("boundary of one separated particle at d/l = 1", float(ws.wear.boundary_dstar_over_l(0, np.array([1.0]), c_max)[0]),
      1 + 3 * math.pi / 8 * c_max, 1e-12)
# Every map point's region agrees with R ≥ 1 of its case on the exact lines.
x, y = m["x"][::20], m["y"][::20]
agree = all((m["region"][20 * i, 20 * j] >= 1) == (ws.wear.energy_ratio_3d(0, xi, yj, c_max) >= 1)
            for i, xi in enumerate(x) for j, yj in enumerate(y) if xi > 0)
check("regions agree with R >= 1 (4.48)", float(agree), 1.0, 0.0)
finish()
