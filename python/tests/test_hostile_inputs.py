"""Every Python entry point refuses what the CLI refuses, by the same checks (the solvers' own):
out-of-range sizes, unphysical values, complex arrays, file names as bytes, a solver shared by two
threads. And a seeded generator tries new hostile values on each entry point every run
(WEARSCALE_HOSTILE_SEED replays one): each call is refused (ValueError, TypeError) or gives finite
numbers, never a crash, a hang or a silent wrong answer."""
import math
import os
import random
import threading
import time

import numpy as np
import pytest

import wearscale as ws


def test_a_patch_test_of_2000_d0_is_refused_as_the_cli_refuses_it():
    with pytest.raises(ValueError, match=r"L \(in d0\) = 2000; allowed: 6 … 400"):
        ws.dem.patch_test(length=2000)


def test_hertz_refuses_a_negative_radius():
    with pytest.raises(ValueError, match="radius R = -1"):
        ws.contact.hertz(-1, 1, 1)
    with pytest.raises(ValueError, match="Poisson's ratio"):
        ws.contact.effective_modulus(1e9, 2.0, 1e9, 0.3)


def test_a_complex_height_array_is_refused_not_truncated():
    h = ws.surface.generate(32, 1.0, k_l=2, k_s=8, seed=1, slope_rms=0.5)
    z = np.asarray(h.heights, dtype=complex) * (1 + 1j)
    with pytest.raises(ValueError, match="complex128.*imaginary part would be lost"):
        ws.contact.NormalContact(z, lx=1.0, e_star=1.0)
    with pytest.raises(ValueError, match="complex"):
        ws.surface.h_rms(z, 1.0)
    with pytest.raises(ValueError, match="where numbers are expected"):
        ws.surface.sa(np.full((4, 4), "1.5"), 1.0)


def test_a_tolerance_that_ends_a_solve_before_it_has_an_answer_is_refused():
    c = ws.contact.NormalContact(ws.surface.generate(32, 1.0, k_l=2, k_s=8, seed=1, slope_rms=0.5), e_star=1.0)
    with pytest.raises(ValueError, match=r"tolerance = 0.999999; allowed: \(0, 0.001\]"):
        c.solve(mean_pressure=0.01, tolerance=0.999999)


def test_a_rough_surface_steeper_than_the_bound_is_refused():
    with pytest.raises(ValueError, match="gives an RMS slope"):
        ws.surface.generate(256, 1.0, hurst=0.3, k_l=4, k_s=128, seed=1, rms=1.0)


def test_a_folder_given_as_bytes_is_the_folder_it_names(tmp_path, source_dir):
    out = tmp_path / "bytes-folder"
    r = ws.run(str(source_dir / "cases/pin_on_disc_si_oxide.toml"), out=os.fsencode(out), quiet=True,
               scale__macro__grid=32, scale__macro__distance=0.001)
    assert (out / "summary.json").exists()
    assert r.output_dir == out
    assert not any("b'" in p.name for p in tmp_path.iterdir())


def test_an_empty_folder_or_task_is_refused_not_taken_as_the_default(tmp_path, source_dir):
    case = str(source_dir / "cases/pin_on_disc_si_oxide.toml")
    with pytest.raises(ValueError, match="an empty folder name"):
        ws.run(case, out="", scale__macro__grid=32, scale__macro__distance=0.001)
    with pytest.raises(ValueError, match="not a shard"):
        ws.run(case, out=tmp_path / "t", task="", scale__macro__grid=32, scale__macro__distance=0.001)


def test_two_threads_on_one_normal_contact_are_told_it_is_not_thread_safe():
    s = ws.surface.generate(256, 1.0, k_l=2, k_s=64, seed=1, slope_rms=0.5)
    c = ws.contact.NormalContact(s, e_star=1.0)
    errors, results = [], []

    def solve(p):
        try:
            for _ in range(4):
                results.append(c.solve(mean_pressure=p, tolerance=1e-10)["mean_pressure_Pa"])
        except Exception as e:  # noqa: BLE001 - what the second thread meets is the point
            errors.append(e)

    threads = [threading.Thread(target=solve, args=(p,)) for p in (0.01, 0.05)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    # Either the solves did not overlap, or the second was refused naming the cause; never a NumericalError.
    assert all(isinstance(e, RuntimeError) and "not thread-safe" in str(e) for e in errors), errors
    for p in results:
        assert p == pytest.approx(0.01, rel=1e-9) or p == pytest.approx(0.05, rel=1e-9)
    # One object per thread solves in parallel.
    own = [ws.contact.NormalContact(s, e_star=1.0) for _ in range(2)]
    answers = [None, None]
    threads = [threading.Thread(target=lambda k=k: answers.__setitem__(k, own[k].solve(mean_pressure=0.02)))
               for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert answers[0]["contact_fraction"] == answers[1]["contact_fraction"]


# ---------------------------------------------------------------------------
# The generator: one hostile value at a time in one argument of a fast call of each entry point.

HOSTILE = [math.nan, math.inf, -math.inf, -1.0, -1e300, 0.0, 1e300]

# entry point, its fast arguments
FLAT = np.zeros((16, 16))
FLAT[4:12, 4:12] = 1e-3
CALLS = {
    "contact.hertz": (ws.contact.hertz, dict(radius=3e-3, load=1.0, e_star=37.6e9)),
    "contact.effective_modulus": (ws.contact.effective_modulus, dict(e1=73e9, nu1=0.17, e2=160e9, nu2=0.22)),
    "contact.hertz_check": (ws.contact.hertz_check, dict(n=16, radius=3e-3, load=1.0, e_star=37.6e9)),
    "surface.generate": (ws.surface.generate, dict(n=16, size=1.0, hurst=0.8, k_l=1.0, k_s=4.0, slope_rms=0.5)),
    "surface.sphere": (ws.surface.sphere, dict(n=16, size=1e-3, radius=1e-2)),
    "surface.h_rms": (ws.surface.h_rms, dict(heights=FLAT, lx=1e-3)),
    "contact.NormalContact": (ws.contact.NormalContact, dict(heights=FLAT, lx=1e-3, e_star=1e9)),
    "contact.stresses": (ws.contact.stresses, dict(pressure=FLAT, lx=1e-3, poisson=0.3, depths=(0.0,))),
    "dem.material": (ws.dem.material, dict(name="SiO2", scaling_exponent=0.5)),
    "dem.patch_test": (ws.dem.patch_test, dict(d0=90.0, length=8.0, width=3.0, load=0.01, time_step=0.1,
                                               max_elastic_steps=1000)),
    "dem.sheared_junction": (ws.dem.sheared_junction, dict(diameter=8e-9, d0=3e-9, box=[24e-9, 16e-9, 24e-9],
                                                           velocity=10.0, pressure=1e8, sliding_distance=1e-10,
                                                           time_step=0.1)),
    "wear.analytic_map_2d": (ws.wear.analytic_map_2d, dict(x_max=3.0, y_max=6.0, nx=4, ny=4)),
    "wear.analytic_map_3d": (ws.wear.analytic_map_3d, dict(c_inter=0.5, x_max=1.0, y_max=2.0, nx=4, ny=4)),
    "materials.critical_pressure": (ws.materials.critical_pressure, dict(law=ws.materials.StrengthLaw("Si"))),
    "materials.wear_rate": (ws.materials.wear_rate, dict(p_n=1e9, p_crit=1e10)),
}


def _numbers(value):
    """Every number a result holds (dicts, lists, arrays), for the finiteness check."""
    if isinstance(value, dict):
        for v in value.values():
            yield from _numbers(v)
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _numbers(v)
    elif isinstance(value, np.ndarray) and value.dtype.kind == "f":
        yield from value.ravel()[:1000]
    elif isinstance(value, float):
        yield value


def test_generated_hostile_arguments_are_refused_or_give_finite_answers():
    seed = int(os.environ.get("WEARSCALE_HOSTILE_SEED", time.time_ns() % 1000000007))
    rng = random.Random(seed)
    print(f"[ hostile  ] python entry points: WEARSCALE_HOSTILE_SEED={seed} replays it")
    tried = 0
    for name, (function, arguments) in sorted(CALLS.items()):
        numeric = [k for k, v in arguments.items() if isinstance(v, float)]
        for _ in range(2):
            if not numeric:
                break
            key = rng.choice(numeric)
            value = rng.choice(HOSTILE)
            args = dict(arguments, **{key: value})
            start = time.monotonic()
            try:
                result = function(**args)
            except (ValueError, TypeError, ArithmeticError):
                pass  # refused, or a numerical failure said as one
            else:
                bad = [x for x in _numbers(result) if not math.isfinite(x)]
                # A map's NaN marks a cell outside the model (documented); the other figures are finite.
                if not name.startswith("wear."):
                    assert not bad, f"{name}({key}={value}) gave non-finite numbers (seed {seed})"
            assert time.monotonic() - start < 60, f"{name}({key}={value}) took too long (seed {seed})"
            tried += 1
    assert tried > 20
