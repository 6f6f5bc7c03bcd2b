"""The DEM patch test of §6.2.1: an HCP sample of the Table 6.4 targets (E = 1, ν = 0.15, no
units; d0 = 0.6 d_c) between two walls in confined compression; C11 = σ_yy/ε_yy and
C12 = σ_xx/ε_yy give ν = C12/(C11 + C12) and E = C11 (1 + ν)(1 − 2ν)/(1 − ν), to be compared
with the targets the particle parameters were calibrated for (6.52). The sample length L is
varied up to the thesis' 25 d0: the walls stiffen short samples.

Writes dem_patch_test.png (E and ν against L/d0).
    python3 examples/python/dem_patch_test.py [--out out/examples]
"""
import wearscale as ws
from _common import arguments, check, finish, plt, save

args = arguments(__doc__.splitlines()[0])
targets = ws.dem.material()
lengths = [8, 12, 25]
results = []
for length in lengths:
    r = ws.dem.patch_test(d0=0.6 * targets["d_c"], length=length, width=3, strengths=False)
    results.append(r)
    print(f"L = {length} d0: {r['particles']} particles, E = {r['young']:.4f}, nu = {r['poisson']:.4f}, "
          f"{r['elastic_steps']} steps")
fig, (a1, a2) = plt.subplots(1, 2, figsize=(8, 3.4))
a1.plot(lengths, [r["young"] for r in results], "o-")
a1.axhline(targets["young"], c="k", ls="--", label="target (Table 6.4)")
a1.set_xlabel("L/d0")
a1.set_ylabel("E")
a1.legend()
a2.plot(lengths, [r["poisson"] for r in results], "o-")
a2.axhline(targets["poisson"], c="k", ls="--")
a2.set_xlabel("L/d0")
a2.set_ylabel("ν")
save(fig, f"{args.out}/dem_patch_test.png")
thesis = results[-1]
check("E at L = 25 d0 (target 1)", thesis["young"], targets["young"], 0.04)
check("nu at L = 25 d0 (target 0.15)", thesis["poisson"], targets["poisson"], 0.01)
check("E approaches the target as L grows",
      float(all(abs(b["young"] - 1) < abs(a["young"] - 1) for a, b in zip(results, results[1:]))), 1.0, 0.0)
finish()
