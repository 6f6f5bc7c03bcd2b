"""Mindlin partial slip (Cattaneo 1938, Mindlin 1949; Appendix A): a sphere pressed with P and
sheared with Q < μP sticks on a central disc of radius c = a (1 − Q/μP)^(1/3) and slips on the
annulus around it. ν = 0.5 removes the normal–tangential coupling, as Mindlin's solution assumes.

Writes mindlin_partial_slip.png (c/a against Q/μP, and the stick/slip map at one load).
    python3 examples/python/mindlin_partial_slip.py [--n 96] [--out out/examples]
"""
import numpy as np

import wearscale as ws
from _common import arguments, check, finish, plt, save

args = arguments(__doc__.splitlines()[0], n=(96, "grid points per side"), mu=(0.5, "Coulomb friction coefficient"))
R, L, E, p_n = 1e-2, 4e-4, 1e9, 2e5
s = ws.surface.sphere(args.n, L, radius=R)
c = ws.contact.FrictionalContact(s, young=E, poisson=0.5, law="coulomb", mu=args.mu)
ratios = np.array([0.1, 0.3, 0.5, 0.7, 0.85])
stick = []
maps = {}
for q in ratios:
    r = c.solve(mean_pressure=p_n, traction_x=q * args.mu * p_n)
    stick.append(np.sqrt(r["stick_fraction"] / r["contact_fraction"]))  # c/a from the areas
    maps[q] = c.stick_slip.copy()
    print(f"Q/muP = {q:.2f}  c/a = {stick[-1]:.4f}  Mindlin {(1 - q) ** (1 / 3):.4f}  iterations {r['iterations']}")

fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.8))
qq = np.linspace(0, 1, 101)
a1.plot(qq, (1 - qq) ** (1 / 3), "k-", label="Mindlin")
a1.plot(ratios, stick, "o", label=f"BEM {args.n}²")
a1.set_xlabel(r"$Q/\mu P$")
a1.set_ylabel("c/a")
a1.legend()
a2.imshow(maps[0.5].T, origin="lower", extent=[0, L * 1e6, 0, L * 1e6], cmap="viridis")
a2.set_title("0 open, 1 stick, 2 slip (Q/μP = 0.5)")
a2.set_xlabel("x [µm]")
save(fig, f"{args.out}/mindlin_partial_slip.png")
for q, ca in zip(ratios, stick):
    check(f"c/a at Q/muP = {q}", ca, (1 - q) ** (1 / 3), 0.04)  # about one cell of the contact radius
finish()
