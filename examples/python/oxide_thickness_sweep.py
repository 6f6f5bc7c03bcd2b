"""The oxide-thickness sweep of §9.3.2 (Fig. 9.21), reduced: a SiO2 pin on a Si disc under a
thermal oxide of thickness h, through the whole scale pipeline (Fig. 9.18 strength tables →
junction model (§7.1.2) → BEM pin-on-disc wear model), run through the CLI's runner. The
friction coefficient at the end of the run is plotted against h next to the experimental fit
(9.1) μ ≈ 0.337 + 0.070 h[µm].

The model's limits (VERIFICATION.md): μ = μ0(Si) = 0.14 on a bare Si disc (h = 0) and
μ0(SiO2) = 0.84 on bulk SiO2 (h = ∞) throughout; the experiments' μ lies between them.
The case is cases/oxide_thickness_sweep.toml with a coarser grid and a shorter distance
(the main job runs it whole: `wearscale run cases/oxide_thickness_sweep.toml`).

Writes oxide_thickness_sweep.png.
    python3 examples/python/oxide_thickness_sweep.py [--grid 48] [--distance 0.05] [--out out/examples]
"""
import math

import numpy as np

import wearscale as ws
from _common import SOURCE, arguments, check, finish, plt, save

args = arguments(__doc__.splitlines()[0], grid=(48, "BEM grid of the pin (case: 128)"),
                 distance=(0.05, "sliding distance [m] (case: 0.5)"))
run = ws.run(SOURCE / "cases" / "oxide_thickness_sweep.toml", out=f"{args.out}/oxide_thickness_sweep",
             scale__macro__grid=args.grid, scale__macro__distance=f"{args.distance} m")
table = run.results  # the sweep's table as columns (run.table(): a pandas DataFrame), in SI
h, mu = table[next(iter(table))], table["mu_final"]  # the swept thickness is the first column
for value, m, mean in zip(h, mu, table["mu_mean"]):
    print(f"h_layer = {value * 1e6 if math.isfinite(value) else math.inf:g} um: mu_final = {m:.4f}, mu_mean = {mean:.4f}")

finite = [(x * 1e6, m) for x, m in zip(h, mu) if math.isfinite(x)]
bulk = [m for x, m in zip(h, mu) if not math.isfinite(x)]
fig, ax = plt.subplots(figsize=(5.5, 4))
ax.plot([x for x, _ in finite], [m for _, m in finite], "o-", label="wearscale (end of run)")
if bulk:
    ax.axhline(bulk[0], c="C1", ls="--", label="wearscale, bulk SiO2")
hh = np.linspace(0, 3, 50)
ax.plot(hh, 0.337 + 0.070 * hh, "k:", label="experimental fit (9.1)")
ax.set_xlabel(r"$h_{layer}$ [µm]")
ax.set_ylabel(r"$\mu$")
ax.set_ylim(0, 1)
ax.legend()
save(fig, f"{args.out}/oxide_thickness_sweep.png")

check("mu on bare Si (h = 0) = mu0(Si)", finite[0][1], 0.14, 0.005)
if bulk:
    check("mu on bulk SiO2 = mu0(SiO2)", bulk[0], 0.84, 0.005)
check("mu between the two limits for every h", float(all(0.135 <= m <= 0.845 for _, m in finite)), 1.0, 0.0)
finish()
