"""The cost of calling a contact solve from Python: the wall time of NormalContact.solve()
seen from Python against the C++ solve's own wall time (solve_seconds, measured inside the
binding around the GIL-released solve), for a 512² rough contact, and the time to reach the
pressure as a NumPy array. Prints the figures (ctest -L long runs it; nothing is asserted).
    PYTHONPATH=build/python python3 python/tests/bench_overhead.py [n] [repeats]
"""
import sys
import time

import numpy as np

import wearscale as ws

n = int(sys.argv[1]) if len(sys.argv) > 1 else 512
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
s = ws.surface.generate(n, 1.0, hurst=0.8, k_l=4, k_s=n // 8, seed=1, slope_rms=1.0)
c = ws.contact.NormalContact(s, e_star=1.0)
c.solve(mean_pressure=0.03, tolerance=1e-10)  # plans made, pages touched
walls, inner = [], []
for _ in range(repeats):
    c.reset()
    t0 = time.perf_counter()
    r = c.solve(mean_pressure=0.03, tolerance=1e-10)
    walls.append(time.perf_counter() - t0)
    inner.append(r["solve_seconds"])
t0 = time.perf_counter()
for _ in range(1000):
    p = c.pressure
view = (time.perf_counter() - t0) / 1000
t0 = time.perf_counter()
cc = ws.contact.NormalContact(s, e_star=1.0)
construct = time.perf_counter() - t0
overhead = np.median(np.array(walls) - np.array(inner))
print(f"{n}² contact: Python wall {np.median(walls) * 1e3:.2f} ms, C++ solve {np.median(inner) * 1e3:.2f} ms, "
      f"overhead {overhead * 1e6:.1f} µs = {100 * overhead / np.median(inner):.4f} % ({r['iterations']} iterations); "
      f"pressure view {view * 1e6:.2f} µs; constructing the solver {construct * 1e3:.1f} ms")
