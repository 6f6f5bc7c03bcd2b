"""wearscale.run: cases through the CLI's runner, from a file, a TOML string or a dict, with
--set-style overrides; bad cases are ValueErrors naming the key, before anything is written."""
import pytest

import wearscale as ws
from wearscale.run import to_toml
from _approx import approx


def test_the_hertz_pin_case_gives_the_thesis_contact_diameter(source_dir, tmp_path):
    r = ws.run(source_dir / "cases" / "hertz_pin.toml", out=tmp_path / "o")
    assert isinstance(r, dict) and r.output_dir == tmp_path / "o"
    values = r.results
    diameter = 2 * values["contact_radius"]
    assert diameter == approx(78.2e-6, rel=2e-3)  # §8.1


def test_check_writes_nothing_and_a_run_lists_its_hdf5_outputs(source_dir, tmp_path):
    case = source_dir / "cases" / "hertz_pin.toml"
    assert ws.run.__module__ == "wearscale.run"
    from wearscale.run import check
    assert [str(d) for d in check(case)] and not (tmp_path / "o").exists()
    with pytest.raises(ValueError, match="normal_load"):
        check(case, scale__macro__normal_load="-1 N")
    r = ws.run(case, out=tmp_path / "o")
    assert tmp_path / "o" / "run.h5" in r.h5_files()


def test_a_dict_case_with_keyword_overrides_runs_like_its_file(source_dir, tmp_path):
    case = {"case": {"name": "hertz-dict"},
            "scale": {"macro": {"backend": "hertz", "pin_radius": "3 mm", "normal_load": "1 N",
                                "elastic_modulus": "73 GPa", "poisson_ratio": 0.17}}}
    a = ws.run(case, out=tmp_path / "a").results
    b = ws.run(case, out=tmp_path / "b", scale__macro__normal_load="8 N").results
    assert b["contact_radius"] == approx(2 * a["contact_radius"], rel=1e-12)  # a ∝ F^(1/3)
    from wearscale.run import to_toml
    assert ws.run(to_toml(case), out=tmp_path / "c").results == a  # the same case as TOML text


def test_a_bad_key_is_a_value_error_with_its_range_and_nothing_is_written(tmp_path):
    case = {"case": {"name": "bad"}, "scale": {"macro": {"backend": "hertz", "pin_radius": "3 mm", "normal_load": "1 N",
                                "elastic_modulus": "73 GPa", "poisson_ratio": 0.7}}}
    with pytest.raises(ws.InputError, match=r"key 'scale.macro.poisson_ratio' = 0.7: out of range; allowed: \[-1, 0.5\)"):
        ws.run(case, out=tmp_path / "bad")
    assert not (tmp_path / "bad").exists()


def test_a_dict_case_reads_its_files_relative_to_the_working_directory_and_names_itself(tmp_path, monkeypatch):
    # The case goes to the runner as text: "s.h5" is the working directory's (it was looked for in
    # the folder of a temporary file before), and a message names "<case dict>", not a deleted file.
    monkeypatch.chdir(tmp_path)
    s = ws.surface.generate(32, 1e-4, k_l=2, k_s=8, seed=1, slope_rms=0.1)
    ws.surface.write("s.h5", s)
    case = {"case": {"name": "relative"}, "contact": {"surface": "s.h5", "e_star": "100 GPa", "mean_pressure": "1 MPa"}}
    r = ws.run(case, out="o")
    c = ws.contact.NormalContact(s, e_star=1e11)
    c.solve(mean_pressure=1e6)
    assert r.results["contact_fraction"] == approx(float((c.pressure > 0).mean()), rel=1e-12)
    case["contact"]["mean_pressure"] = "-1 MPa"
    with pytest.raises(ws.InputError, match=r"<case dict>:\d+: key 'contact.mean_pressure'"):
        ws.run(case, out="bad")
    with pytest.raises(ws.InputError, match=r"<case string>:"):
        ws.run(to_toml(case), out="bad")


def test_ctrl_c_stops_a_run_cleanly_with_keyboard_interrupt_and_it_resumes(source_dir, tmp_path):
    # The reduced pin-on-disc run of the CLI's SIGINT test (a second or two): SIGINT once run.h5
    # is being written. The run saves its checkpoint, removes its unfinished files and raises
    # KeyboardInterrupt naming the signal; Python's own handler is back afterwards; it resumes.
    import os
    import signal
    import subprocess
    import sys
    import time
    script = f"""
import signal, sys, wearscale as ws
args = dict(scale__macro__grid=64, scale__macro__distance=0.3, run__fft_planning="estimate")
try:
    ws.run({str(source_dir / "cases" / "pin_on_disc_si_oxide.toml")!r}, out="stopped", **args)
except KeyboardInterrupt as e:
    print("KeyboardInterrupt:", e, file=sys.stderr)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # Python's handler is back
    r = ws.run({str(source_dir / "cases" / "pin_on_disc_si_oxide.toml")!r}, resume="stopped", **args)
    print("resumed", r.results["mu_final"], file=sys.stderr)
    sys.exit(3)
"""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    p = subprocess.Popen([sys.executable, "-c", script], cwd=tmp_path, env=env, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and p.poll() is None:
        if any(f.name.startswith(".run.h5.partial-") for f in (tmp_path / "stopped").glob(".*")):
            break
        time.sleep(0.005)
    assert p.poll() is None, "the run ended before it could be interrupted: " + p.stderr.read()
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=120)[1]
    assert p.returncode == 3, err
    assert "KeyboardInterrupt:" in err and "interrupted by SIGINT" in err and "resumed" in err


def test_shards_of_a_wear_maps_surfaces_then_merge_give_the_map_run_at_once(tmp_path, monkeypatch):
    # A job array driven from Python: two shards of a two-surface wear map into one folder, then
    # merge; the map equals the one run at once. Merging before the second shard ran is refused,
    # naming the surface and its shard.
    monkeypatch.chdir(tmp_path)
    case = {"case": {"name": "map"}, "wearmap": {"rough": {"n": 32, "q_l": 2, "seeds": 2, "n_loads": 2, "n_dstar": 2}}}
    whole = ws.run(case, out="whole")
    ws.run(case, out="shards", task="1/2")
    with pytest.raises(ws.InputError, match=r"seed 2 \(shard 2/2 has not run\)"):
        ws.merge("shards")
    assert not (tmp_path / "shards" / "summary.json").exists()
    ws.run(case, out="shards", task="2/2")
    merged = ws.merge("shards")
    untimed = lambda results: {k: v for k, v in results.items() if "seconds" not in k}  # noqa: E731
    assert untimed(merged.results) == untimed(whole.results)
    assert (tmp_path / "shards" / "wearmap_rough.csv").read_text() == (tmp_path / "whole" / "wearmap_rough.csv").read_text()


def _libgomp_settings(env_extra):
    """What libgomp reports it read (OMP_DISPLAY_ENV) in a fresh interpreter that imports wearscale."""
    import os, subprocess, sys
    env = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    env.update(env_extra, OMP_DISPLAY_ENV="verbose")
    r = subprocess.run([sys.executable, "-c", "import wearscale"], env=env, capture_output=True, text=True,
                       check=True)
    return r.stderr


def test_threads_spin_briefly_then_sleep_as_in_the_cli_unless_the_user_chose():
    from wearscale import _wearscale
    assert ws._WAITING_SPIN_COUNT == _wearscale._waiting_spin_count  # the C++ constant the CLI sets
    assert f"GOMP_SPINCOUNT = '{ws._WAITING_SPIN_COUNT}'" in _libgomp_settings({})
    chosen = _libgomp_settings({"OMP_WAIT_POLICY": "active"})
    assert "OMP_WAIT_POLICY = 'ACTIVE'" in chosen and f"GOMP_SPINCOUNT = '{ws._WAITING_SPIN_COUNT}'" not in chosen
