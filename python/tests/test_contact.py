"""wearscale.contact: BEM normal and frictional contact from Python against Hertz, Mindlin,
the contact conditions (2.43) and the CLI; arrays are views of the right shape and dtype."""
import json
import math
import subprocess
import threading
import time

import numpy as np
import pytest

import wearscale as ws
from _approx import approx

E_STAR = 1e11


@pytest.fixture(scope="module")
def rough():
    return ws.surface.generate(64, 1e-4, hurst=0.8, k_l=2, k_s=16, seed=4, slope_rms=0.1)


def test_hertz_check_agrees_with_the_analytic_sphere():
    r = ws.contact.hertz_check(64)
    assert r["approach_relative_error"] < 1e-3       # δ = a²/R
    assert r["peak_pressure_relative_error"] < 1e-2  # p0 = 3F/2πa²
    assert r["contact_radius_relative_error"] < 2e-2  # a from the contact area, one cell of 4a/64
    # The unworn SiO2 pin on a SiO2 disc of §8.1 (R = 3 mm, 1 N): contact diameter 78.2 µm.
    h = ws.contact.hertz(3e-3, 1.0, ws.contact.effective_modulus(73e9, 0.17, 73e9, 0.17))
    assert 2 * h["contact_radius_m"] == approx(78.2e-6, rel=2e-3)
    assert h["mean_pressure_Pa"] == approx(2 / 3 * h["peak_pressure_Pa"], rel=1e-14)


def test_normal_contact_meets_the_contact_conditions_and_the_imposed_load(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    r = c.solve(mean_pressure=2e6)
    p, g, u = c.pressure, c.gap, c.displacement
    for a in (p, g, u):
        assert a.shape == (64, 64) and a.dtype == np.float64 and not a.flags.writeable
    assert p.mean() == approx(2e6, rel=1e-12) and r["mean_pressure_Pa"] == approx(2e6, rel=1e-12)
    assert p.min() >= 0.0
    scale = rough.heights.std()
    assert np.abs(g[p > 0]).max() < 1e-8 * scale and g.min() > -1e-8 * scale  # g = 0 in contact, ≥ 0 outside
    assert r["contact_fraction"] == approx(np.count_nonzero(p > 0) / p.size, abs=0)
    assert np.array_equal(c.contact, p > 0) and c.contact.dtype == np.bool_
    assert abs(u.mean()) < 1e-12 * np.abs(u).max()
    assert r["error"] < 1e-12 and r["solve_seconds"] > 0


def test_every_method_reaches_the_same_contact(rough):
    # "two-level" (the preconditioner on a 2x coarser grid), "preconditioned" and
    # "polonsky-keer": the same contact set and pressures to the tolerance's accuracy.
    results = {}
    for method in ("preconditioned", "two-level", "polonsky-keer"):
        c = ws.contact.NormalContact(rough, e_star=E_STAR)
        r = c.solve(mean_pressure=2e6, tolerance=1e-12, method=method)
        results[method] = (r, c.pressure.copy())
    r0, p0 = results["preconditioned"]
    for method in ("two-level", "polonsky-keer"):
        r, p = results[method]
        assert np.array_equal(p > 0, p0 > 0), method
        assert np.abs(p - p0).max() < 1e-8 * p0.max(), method
    with pytest.raises(ws.InputError, match="method.*preconditioned \\| two-level \\| polonsky-keer"):
        ws.contact.NormalContact(rough, e_star=E_STAR).solve(mean_pressure=2e6, method="multigrid")


def test_result_arrays_are_views_on_the_solver_without_a_copy(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    c.solve(mean_pressure=1e6)
    a, b = c.pressure, c.pressure
    assert np.shares_memory(a, b)  # both view the solver's own pressure
    del c
    assert np.isfinite(a).all()  # the view keeps its solver alive
    with pytest.raises(ValueError):
        a[0, 0] = 1.0  # read-only: the next solve overwrites it


def test_a_warm_started_load_ramp_matches_cold_solves_in_fewer_iterations(rough):
    loads = np.linspace(0.5e6, 4e6, 6)
    warm = ws.contact.NormalContact(rough, e_star=E_STAR)
    ramp = warm.ramp(loads)
    cold_iterations = 0
    for p0, w in zip(loads, ramp):
        cold = ws.contact.NormalContact(rough, e_star=E_STAR)
        r = cold.solve(mean_pressure=p0)
        cold_iterations += r["iterations"]
        assert w["contact_fraction"] == approx(r["contact_fraction"], abs=2 / 64**2)
    assert sum(w["iterations"] for w in ramp[1:]) < cold_iterations - ws.contact.NormalContact(
        rough, e_star=E_STAR).solve(mean_pressure=loads[0])["iterations"]
    assert all(b["contact_fraction"] >= a["contact_fraction"] for a, b in zip(ramp, ramp[1:]))  # A grows with p
    assert ramp[-1]["contact_fraction"] > 2 * ramp[0]["contact_fraction"]


def test_the_load_predictor_gives_the_plain_ramps_solutions_in_fewer_iterations(rough):
    loads = np.linspace(2e6, 2.2e6, 8)  # steps of about 1.4 %
    predicted = ws.contact.NormalContact(rough, e_star=E_STAR)
    plain = ws.contact.NormalContact(rough, e_star=E_STAR)
    a = predicted.ramp(loads, tolerance=1e-10)
    b = plain.ramp(loads, tolerance=1e-10, predict_load=False)
    assert predicted.kept_solutions == 2 and plain.kept_solutions == 0
    for x, y in zip(a, b):
        assert x["contact_fraction"] == approx(y["contact_fraction"], abs=2 / 64**2)
    assert np.abs(predicted.pressure - plain.pressure).max() < 1e-6 * plain.pressure.max()
    # From the third load on (two kept solutions): fewer iterations in all.
    assert sum(r["iterations"] for r in a[2:]) < sum(r["iterations"] for r in b[2:])
    predicted.reset()
    assert predicted.kept_solutions == 0


def test_the_warm_start_state_restores_a_bit_identical_next_solve(rough):
    a = ws.contact.NormalContact(rough, e_star=E_STAR)
    a.solve(mean_pressure=1e6)
    state = (a.warm_start[0].copy(), a.warm_start[1])
    b = ws.contact.NormalContact(rough, e_star=E_STAR)
    b.warm_start = state
    ra, rb = a.solve(mean_pressure=1.5e6), b.solve(mean_pressure=1.5e6)
    assert ra["iterations"] == rb["iterations"] and np.array_equal(a.pressure, b.pressure)


def test_an_interference_solve_reaches_the_imposed_interference(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    r = c.solve(interference=0.3 * rough.heights.std())
    assert r["interference_m"] == approx(0.3 * rough.heights.std(), rel=1e-6)


def test_bad_contact_input_is_a_value_error_with_the_key_and_range(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    with pytest.raises(ValueError, match="exactly one"):
        c.solve()
    with pytest.raises(ws.InputError, match="boundary.*periodic \\| free"):
        ws.contact.NormalContact(rough, e_star=E_STAR, boundary="open")
    with pytest.raises(ValueError):
        c.solve(mean_pressure=-1.0)
    with pytest.raises(ValueError, match="shape"):
        c.set_surface(np.zeros((8, 8)))
    with pytest.raises(ValueError, match="finite"):
        ws.contact.NormalContact(np.full((8, 8), np.nan), 1.0, e_star=1.0)


def test_a_numerical_failure_is_an_arithmetic_error_with_its_message(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    with pytest.raises(ArithmeticError) as e:
        c.solve(mean_pressure=1e6, max_iterations=2, tolerance=1e-14)
    assert isinstance(e.value, ws.NumericalError) and "iteration" in str(e.value)


def sphere_frictional(n=64, poisson=0.5, mu=0.5):
    R, L = 1e-2, 4e-4
    s = ws.surface.sphere(n, L, radius=R)
    return ws.contact.FrictionalContact(s, young=1e9, poisson=poisson, law="coulomb", mu=mu)


def test_frictional_contact_gives_mindlins_stick_zone_and_the_arrays_of_tractions():
    # Cattaneo–Mindlin (ν = 0.5: no coupling): the stick radius c = a (1 − Q/μP)^(1/3).
    c = sphere_frictional()
    p_n, ratio = 2e5, 0.5
    r = c.solve(mean_pressure=p_n, traction_x=ratio * 0.5 * p_n)
    assert r["mean_traction_x_Pa"] == approx(ratio * 0.5 * p_n, rel=1e-9)
    assert r["stick_fraction"] + r["slip_fraction"] == approx(r["contact_fraction"], rel=1e-12)
    stick_over_contact = r["stick_fraction"] / r["contact_fraction"]  # (c/a)²
    assert math.sqrt(stick_over_contact) == approx((1 - ratio) ** (1 / 3), abs=0.05)
    m = c.stick_slip
    assert m.dtype == np.uint8 and m.shape == (64, 64) and set(np.unique(m)) <= {0, 1, 2}
    assert np.array_equal(m > 0, c.pressure > 0)
    for name in ("pressure", "traction_x", "traction_y", "gap", "slip_x", "slip_y", "displacement",
                 "displacement_x", "displacement_y"):
        a = getattr(c, name)
        assert a.shape == (64, 64) and a.dtype == np.float64
    pt = np.hypot(c.traction_x, c.traction_y)
    assert (pt <= 0.5 * c.pressure * (1 + 1e-9) + 1e-9 * p_n).all()  # inside the friction cone (A.2)
    assert np.abs(c.slip_x[m == 1]).max() == 0.0  # no slip where sticking


def test_a_tangential_load_beyond_friction_is_refused_never_clamped():
    c = sphere_frictional(n=32)
    with pytest.raises(ValueError, match="slid|friction"):
        c.solve(mean_pressure=2e5, traction_x=0.6 * 2e5)


def test_stresses_at_the_surface_carry_the_pressure_and_decay_with_depth(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    c.solve(mean_pressure=2e6)
    s = ws.contact.stresses(c.pressure, rough.lx, poisson=0.3, depths=[0.0, 2e-5], tensor=True)
    top, deep = s[0.0], s[2e-5]
    assert np.allclose(top["zz_Pa"], -c.pressure, atol=1e-9 * c.pressure.max())  # σ_zz = −p at z = 0
    assert deep["zz_Pa"].mean() == approx(-2e6, rel=1e-9)  # the mean load carries to every depth
    assert np.ptp(deep["zz_Pa"]) < np.ptp(top["zz_Pa"])  # and spreads
    assert (top["sigma_I_Pa"] >= top["sigma_III_Pa"]).all()
    assert np.allclose(top["tau_max_Pa"], (top["sigma_I_Pa"] - top["sigma_III_Pa"]) / 2)
    with pytest.raises(ValueError):
        ws.contact.stresses(c.pressure, rough.lx, poisson=0.3, depths=[-1e-6])


def test_a_python_solve_equals_the_cli_on_the_same_case(cli, tmp_path):
    case = tmp_path / "case.toml"
    case.write_text("""[case]
name = "py-vs-cli"
[contact]
grid = 64
size = "100 um"
e_star = "100 GPa"
mean_pressure = "200 MPa"
tolerance = 1e-12
[contact.rough]
hurst = 0.8
k_l = 2
k_r = 2
k_s = 16
seed = 4
hprime_rms = 0.1
""")
    out = tmp_path / "out"
    done = subprocess.run([cli, "-q", "-j", "1", "contact", str(case), "--out", str(out), "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    summary = json.loads(done.stdout)
    h = ws.io.read(str(out / "contact.h5"), "/surface/height")
    p_cli = ws.io.read(str(out / "contact.h5"), "/fields/pressure")
    lx = ws.io.attribute(str(out / "contact.h5"), "/surface/height", "lx")
    c = ws.contact.NormalContact(h, lx, e_star=1e11)
    r = c.solve(mean_pressure=2e8, tolerance=1e-12)
    assert np.count_nonzero(p_cli > 0) > 200  # A/A0 = 5.9 %: a field worth comparing (at 2 MPa, 3 points)
    assert np.abs(c.pressure - p_cli).max() <= 1e-12 * p_cli.max()
    assert r["contact_fraction"] == approx(summary["results"]["contact_fraction"]["value"], rel=1e-12)
    # run() takes the same case through the same study
    res = ws.run(str(case), out=tmp_path / "out2")
    assert np.abs(res.load("/fields/pressure") - p_cli).max() <= 1e-12 * p_cli.max()


def test_two_solves_in_two_threads_run_at_once_without_the_gil(capsys):
    s = ws.surface.generate(256, 1e-4, k_l=2, k_s=64, seed=1, slope_rms=0.1)
    sequential = [ws.contact.NormalContact(s, e_star=E_STAR) for _ in range(2)]
    t0 = time.perf_counter()
    for c in sequential:
        c.solve(mean_pressure=2e6)
    sequence = time.perf_counter() - t0
    ref = [c.pressure.copy() for c in sequential]
    contacts = [ws.contact.NormalContact(s, e_star=E_STAR) for _ in range(2)]
    threads = [threading.Thread(target=c.solve, kwargs={"mean_pressure": 2e6}) for c in contacts]
    t0, c0 = time.perf_counter(), time.process_time()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    parallel, cpu = time.perf_counter() - t0, time.process_time() - c0
    for c, p in zip(contacts, ref):
        assert np.array_equal(c.pressure, p)  # same answer from a thread
    with capsys.disabled():
        print(f"\n[GIL] two 256² solves: sequence {sequence:.3f} s, two threads {parallel:.3f} s "
              f"(ratio {parallel / sequence:.2f}; 0.5 = fully parallel) using {cpu / parallel:.2f} cores "
              f"(CPU time over wall time: near 1 when no second core was free)")


def test_python_code_runs_while_a_solve_runs_in_another_thread():
    # If the solve held the GIL, the main thread could not tick until it returned.
    s = ws.surface.generate(256, 1e-4, k_l=2, k_s=64, seed=2, slope_rms=0.1)
    c = ws.contact.NormalContact(s, e_star=E_STAR)
    c.solve(mean_pressure=2e6)  # plans made: the timed solve is the iteration itself
    c.reset()
    worker = threading.Thread(target=c.solve, kwargs={"mean_pressure": 3e6})
    ticks = 0
    worker.start()
    while worker.is_alive():
        ticks += 1
    worker.join()
    assert ticks > 1000


def test_the_solver_keeps_its_surface_and_history_and_a_shifted_surface_carries_the_same_pressure(rough):
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    r = c.solve(mean_pressure=2e6)
    assert np.array_equal(c.surface, rough.heights) and c.e_star == E_STAR and c.shape == (64, 64)
    assert 0 < len(c.history) <= min(12, r["iterations"]) and c.history[-1] == approx(r["error"], rel=1e-12)
    p = c.pressure.copy()
    c.set_surface(rough.heights + 1e-6)  # a rigid shift: under an imposed mean pressure nothing changes
    c.solve(mean_pressure=2e6)
    assert np.abs(c.pressure - p).max() < 1e-9 * p.max()


def test_stresses_of_a_frictional_contact_are_those_of_its_tractions():
    c = sphere_frictional(n=32, poisson=0.3)
    c.solve(mean_pressure=2e5, traction_x=0.2 * 2e5)
    lx, ly = c.size
    a = ws.contact.stresses_of(c, [1e-5])[1e-5]
    b = ws.contact.stresses(c.pressure, lx, ly, 0.3, [1e-5], c.traction_x, c.traction_y)[1e-5]
    assert np.array_equal(a["sigma_I_Pa"], b["sigma_I_Pa"]) and a["tau_max_Pa"].shape == (32, 32)
    n = ws.contact.stresses(c.pressure, lx, ly, 0.3, [1e-5])[1e-5]
    assert not np.array_equal(a["tau_max_Pa"], n["tau_max_Pa"])  # the tangential traction counts


def test_ctrl_c_ends_a_long_solve_within_an_iteration_as_keyboard_interrupt():
    # A Python signal handler that raises (as Ctrl-C's does) is heard while the
    # solve runs with the GIL released: KeyboardInterrupt long before it converges.
    import signal
    s = ws.surface.generate(512, 1e-4, k_l=2, k_s=128, seed=3, slope_rms=0.1)
    c = ws.contact.FrictionalContact(s, 1e-4, young=7e10, poisson=0.17, law="coulomb", mu=0.3)

    def raise_interrupt(signum, frame):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, raise_interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.5)
        with pytest.raises(KeyboardInterrupt) as stopped:
            c.solve(mean_pressure=1e7, traction_x=2e6, tolerance=1e-14, max_iterations=100000)
        # The solver's own words: raised by the handler only after the solve, it would have none.
        assert "stopped at iteration" in str(stopped.value)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def test_a_force_controlled_solve_imposes_the_load_over_the_window(rough):
    # load = F [N] is the mean pressure F / (lx ly), as the CLI's --load (contact.normal_load).
    area = rough.lx * rough.ly
    by_load = ws.contact.NormalContact(rough, e_star=E_STAR)
    r = by_load.solve(load=2e6 * area)
    by_pressure = ws.contact.NormalContact(rough, e_star=E_STAR)
    q = by_pressure.solve(mean_pressure=2e6)
    assert np.array_equal(by_load.pressure, by_pressure.pressure)
    assert r["normal_load_N"] == approx(2e6 * area, rel=1e-12) and r["mean_pressure_Pa"] == approx(2e6, rel=1e-12)
    assert by_load.pressure.sum() * area / by_load.pressure.size == approx(2e6 * area, rel=1e-12)
    with pytest.raises(ValueError, match="exactly one of mean_pressure"):
        by_load.solve(load=1.0, mean_pressure=1.0)
    with pytest.raises(ValueError, match="load = -1"):
        by_load.solve(load=-1.0)
    f = sphere_frictional(n=32)
    lx, ly = f.size
    a = f.solve(load=2e5 * lx * ly, traction_x=0.2e5)
    assert a["mean_pressure_Pa"] == approx(2e5, rel=1e-9) and a["normal_load_N"] == approx(2e5 * lx * ly, rel=1e-9)


def test_a_force_controlled_solve_equals_the_cli_contact_with_load(cli, tmp_path):
    case = tmp_path / "load.toml"
    case.write_text("""[case]
name = "by-load"
[contact]
grid = 32
size = "100 um"
e_star = "100 GPa"
normal_load = "2 N"
[contact.rough]
hurst = 0.8
k_l = 2
k_s = 8
seed = 4
hprime_rms = 0.1
""")
    out = tmp_path / "out"
    done = subprocess.run([cli, "-q", "-j", "1", "contact", str(case), "--out", str(out), "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    h = ws.io.read(str(out / "contact.h5"), "/surface/height")
    lx = ws.io.attribute(str(out / "contact.h5"), "/surface/height", "lx")
    c = ws.contact.NormalContact(h, lx, e_star=1e11)
    c.solve(load=2.0)
    p_cli = ws.io.read(str(out / "contact.h5"), "/fields/pressure")
    assert np.abs(c.pressure - p_cli).max() <= 1e-12 * p_cli.max()


def test_a_contact_writes_the_fields_of_the_cli_for_paraview(cli, rough, tmp_path):
    import xml.etree.ElementTree as ET
    h5py = pytest.importorskip("h5py")
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    c.solve(mean_pressure=2e6)
    sidecar = c.write(str(tmp_path / "mine.h5"))
    assert sidecar == str(tmp_path / "mine.xdmf")
    with h5py.File(tmp_path / "mine.h5", "r") as f:
        assert np.array_equal(f["/fields/pressure"][()], c.pressure)
        assert np.array_equal(f["/fields/gap"][()], c.gap)
        assert np.array_equal(f["/surface/height"][()], rough.heights)
        assert np.array_equal(f["/fields/contact"][()], c.contact.astype(float))
        assert f["/surface/height"].attrs["lx"] == approx(rough.lx, rel=1e-15)
        mine = {k for k in f["/fields"]}
    # The CLI's contact.h5 of a normal contact: the same fields under the same names.
    s = tmp_path / "s.h5"
    ws.surface.write(s, rough)
    done = subprocess.run([cli, "-q", "-j", "1", "contact", "--surface", str(s), "--pressure", "2e6", "--e-star", "1e11",
                           "--out", str(tmp_path / "cli")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with h5py.File(tmp_path / "cli" / "contact.h5", "r") as f:
        assert mine == {k for k in f["/fields"]}
        assert np.abs(f["/fields/pressure"][()] - c.pressure).max() <= 1e-10 * c.pressure.max()
    # The sidecar names the views ParaView reads, in the file beside it.
    items = [e.text.strip() for e in ET.parse(sidecar).iter("DataItem") if e.get("Format") == "HDF"]
    assert "mine.h5:/xdmf/fields/pressure" in items and "mine.h5:/xdmf/surface/height" in items
    f = sphere_frictional(n=32)
    f.solve(mean_pressure=2e5, traction_x=0.2e5)
    f.write(str(tmp_path / "fr.h5"))
    with h5py.File(tmp_path / "fr.h5", "r") as g:
        assert np.array_equal(g["/fields/stick_slip"][()], f.stick_slip.astype(float))
        assert np.array_equal(g["/fields/traction_x"][()], f.traction_x)
    with pytest.raises(ValueError, match=r"\.h5"):
        c.write(str(tmp_path / "mine.hdf"))


def test_paraview_opens_what_a_contact_writes(rough, tmp_path, source_dir):
    import shutil
    if shutil.which("pvpython") is None:
        pytest.skip("ParaView's pvpython is not on PATH: the XDMF written from Python is checked with h5py only")
    c = ws.contact.NormalContact(rough, e_star=E_STAR)
    c.solve(mean_pressure=2e6)
    sidecar = c.write(str(tmp_path / "c.h5"))
    dx = rough.lx / rough.shape[0]
    done = subprocess.run(["pvpython", str(source_dir / "tests" / "apps" / "paraview_probe.py"), sidecar, "pressure",
                           str(5 * dx), str(7 * dx)], capture_output=True, text=True)
    line = [l for l in done.stdout.splitlines() if l.startswith("PROBE ")]
    assert line, done.stdout + done.stderr
    for reader in json.loads(line[0][6:]).values():
        assert reader["value"] == approx(c.pressure[5, 7], rel=1e-12, abs=1e-300)
