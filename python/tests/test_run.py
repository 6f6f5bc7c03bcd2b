"""wearscale.run: cases through the CLI's runner, from a file, a TOML string or a dict, with
--set-style overrides; bad cases are ValueErrors naming every key in error, before anything is
written; wearscale.check reads a case as run does and writes nothing; results carry their units
in their keys as the CSV tables do, and a sweep's table is a DataFrame."""
import json
import sys

import pytest

import wearscale as ws
from wearscale.runner import to_toml
from _approx import approx

HERTZ = {"case": {"name": "hertz-dict"},
         "scale": {"macro": {"backend": "hertz", "pin_radius": "3 mm", "normal_load": "1 N",
                             "elastic_modulus": "73 GPa", "poisson_ratio": 0.17}}}


def test_the_hertz_pin_case_gives_the_thesis_contact_diameter(source_dir, tmp_path):
    r = ws.run(source_dir / "cases" / "hertz_pin.toml", out=tmp_path / "o")
    assert isinstance(r, dict) and r.output_dir == tmp_path / "o"
    values = r.results
    diameter = 2 * values["contact_radius_m"]
    assert diameter == approx(78.2e-6, rel=2e-3)  # §8.1
    # Keyed as the CSV tables name their columns, each figure's unit in its key and in .units.
    assert set(values) == {"approach_m", "contact_radius_m", "effective_modulus_Pa", "mean_pressure_Pa",
                           "peak_pressure_Pa"}
    assert r.units["contact_radius_m"] == "m" == r["results"]["contact_radius"]["unit"]
    assert values["contact_radius_m"] == r["results"]["contact_radius"]["value"]


def test_run_check_and_merge_are_three_functions_of_the_package(source_dir, tmp_path):
    # wearscale.run is the function (not a module hiding it), wearscale.check the validator.
    assert callable(ws.run) and ws.run.__module__ == "wearscale.runner"
    assert ws.check is ws.runner.check and ws.merge is ws.runner.merge
    assert not hasattr(ws.run, "check")


def test_check_reads_the_case_as_run_does_and_writes_nothing(source_dir, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    case = source_dir / "cases" / "hertz_pin.toml"
    c = ws.check(case, out=tmp_path / "o")
    assert not (tmp_path / "o").exists() and list(tmp_path.iterdir()) == []
    assert c["valid"] and c["study"] == "pipeline" and c["output_dirs"] == [str(tmp_path / "o")]
    # The resolved case: the file's values and every default the run applies, marked.
    assert c["parameters"]["scale"]["macro"]["normal_load"] == "1 N"
    assert c["defaults"]["run.fft_planning"] == c["parameters"]["run"]["fft_planning"] == "measure"
    assert "fft_planning = \"measure\"    # default" in c.text and "[scale.macro]" in c.text
    # The same through the CLI's runner as run() would take it: keywords, dicts
    assert ws.check(HERTZ, scale__macro__normal_load="2 N")["parameters"]["scale"]["macro"]["normal_load"] == "2 N"
    with pytest.raises(ValueError, match="normal_load"):
        ws.check(case, scale__macro__normal_load="-1 N")
    r = ws.run(case, out=tmp_path / "o")
    assert tmp_path / "o" / "run.h5" in r.h5_files()


def test_every_independent_error_of_a_case_is_reported_at_once(tmp_path):
    case = {"case": {"name": "bad"},
            "run": {"fft_planning": "exhaustive"},  # not a choice: a key with a default
            "scale": {"macro": {"backend": "hertz", "pin_radius": "-3 mm", "normal_load": "1 N",
                                "elastic_modulus": "73 GPa", "poisson_ratio": 0.7, "pin_radus": 1}}}
    with pytest.raises(ws.InputError) as e:
        ws.check(case, out=tmp_path / "bad")
    message = str(e.value)
    assert "4 errors in the case" in message, message
    for key in ("run.fft_planning", "scale.macro.pin_radius", "scale.macro.poisson_ratio", "scale.macro.pin_radus"):
        assert f"key '{key}'" in message, (key, message)
    assert "did you mean 'pin_radius'?" in message
    with pytest.raises(ws.InputError) as again:  # run() refuses it alike, before writing anything
        ws.run(case, out=tmp_path / "bad")
    assert str(again.value) == message and not (tmp_path / "bad").exists()


def sweep_case():
    case = json.loads(json.dumps(HERTZ))
    case["case"]["name"] = "hertz-sweep"
    case["sweep"] = {"key": "scale.macro.normal_load", "values": ["1 N", "8 N", "27 N"]}
    return case


def test_a_sweeps_results_and_table_are_its_csv_table(tmp_path):
    pandas = pytest.importorskip("pandas")
    r = ws.run(sweep_case(), out=tmp_path / "s")
    assert r.is_sweep and len(r.runs) == 3
    table = r.table()
    on_disk = pandas.read_csv(tmp_path / "s" / "sweep.csv")
    assert list(table.columns) == list(on_disk.columns)
    assert table.columns[0] == "macro_normal_load_N"
    assert ((table - on_disk).abs() <= 1e-9 * on_disk.abs()).all().all()  # the CSV's 10 significant digits
    assert table.attrs["units"]["contact_radius_m"] == "m"
    # a ∝ F^(1/3) (1.12)
    a = table["contact_radius_m"]
    assert a[1] / a[0] == approx(2.0, rel=1e-12) and a[2] / a[0] == approx(3.0, rel=1e-12)
    assert r.results["contact_radius_m"] == list(a) and r.results["macro_normal_load_N"] == [1.0, 8.0, 27.0]
    one = r.runs[1]
    assert one.results["contact_radius_m"] == a[1] and one["value"] == "8 N"
    assert one.output_dir.parent == tmp_path / "s" and (one.output_dir / "run.h5").exists()


def test_without_pandas_a_table_is_plain_columns(tmp_path, monkeypatch):
    import numpy as np
    r = ws.run(sweep_case(), out=tmp_path / "s")
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas raises ImportError
    table = r.table()
    assert isinstance(table, dict) and isinstance(table["contact_radius_m"], np.ndarray)
    assert list(table["macro_normal_load_N"]) == [1.0, 8.0, 27.0]
    single = ws.run(HERTZ, out=tmp_path / "one").table()
    assert single["contact_radius_m"].shape == (1,)


def test_a_dict_case_with_keyword_overrides_runs_like_its_file(source_dir, tmp_path):
    case = HERTZ
    a = ws.run(case, out=tmp_path / "a").results
    b = ws.run(case, out=tmp_path / "b", scale__macro__normal_load="8 N").results
    assert b["contact_radius_m"] == approx(2 * a["contact_radius_m"], rel=1e-12)  # a ∝ F^(1/3)
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


def test_run_h5_says_what_a_rough_discs_heights_are_measured_from(source_dir, tmp_path):
    h5py = pytest.importorskip("h5py")
    import numpy as np
    case = source_dir / "cases" / "pin_on_disc_si_oxide.toml"
    small = dict(scale__macro__grid=16, scale__macro__distance="5 mm", scale__macro__track="resolved")
    smooth = ws.run(case, out=tmp_path / "smooth", **small)
    rough = ws.run(case, out=tmp_path / "rough", **small,
                   scale__macro__disc_surface={"hurst": 0.8, "k_l": 2, "k_s": 8, "seed": 5, "sa": "0.2 um"})
    with h5py.File(smooth.output_dir / "run.h5") as f:
        assert "0 unworn" in f["macro/final/disc_track"].attrs["description"]
    with h5py.File(rough.output_dir / "run.h5") as f:
        track = f["macro/final/disc_track"]
        # Not "0 unworn": the heights are the initial rough surface lowered where worn.
        assert "0 unworn" not in track.attrs["description"]
        assert "initial rough surface" in track.attrs["description"]
        assert "initial rough surface" in f["macro/final/disc"].attrs["description"]
        # The unworn strip keeps the generated roughness: its RMS is the surface's Sq (within the worn share).
        sq = rough.results["disc_surface_sq_m"]
        assert np.sqrt(np.mean(np.asarray(track) ** 2)) == approx(sq, rel=0.3)
