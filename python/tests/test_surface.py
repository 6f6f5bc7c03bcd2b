"""wearscale.surface: generated surfaces have the PSD, roughness and metadata asked for;
files round-trip; bad parameters are ValueErrors naming the key and its range."""
import math

import numpy as np
import pytest

import wearscale as ws
from _approx import approx


def test_generate_returns_float64_heights_of_the_grid_and_its_parameters():
    s = ws.surface.generate(64, 2e-3, hurst=0.7, k_l=2, k_s=16, seed=3, ny=32, ly=1e-3)
    assert s.shape == (64, 32) and s.heights.dtype == np.float64 and s.heights.flags.c_contiguous
    assert (s.lx, s.ly) == (2e-3, 1e-3)
    assert s.meta == {"lx_m": 2e-3, "ly_m": 1e-3, "hurst": 0.7, "k_l": 2.0, "k_r": 2.0, "k_s": 16.0, "seed": 3}
    assert abs(s.heights.mean()) < 1e-12 * np.abs(s.heights).max()  # zero mean height


def test_a_seed_gives_the_same_surface_and_another_seed_another():
    a = ws.surface.generate(32, 1.0, seed=5).heights
    assert np.array_equal(a, ws.surface.generate(32, 1.0, seed=5).heights)
    assert not np.array_equal(a, ws.surface.generate(32, 1.0, seed=6).heights)


@pytest.mark.parametrize("key,target", [("sa", 2e-7), ("rms", 1e-6), ("slope_rms", 0.3)])
def test_rescaling_hits_the_requested_roughness_to_round_off(key, target):
    s = ws.surface.generate(64, 1e-3, k_l=2, k_s=24, seed=1, **{key: target})
    measured = {"sa": ws.surface.sa(s.heights), "rms": ws.surface.h_rms(s.heights),
                "slope_rms": ws.surface.h_prime_rms(s.heights, s.lx)}[key]
    assert measured == approx(target, rel=1e-12)
    a = s.analyze()
    assert a[{"sa": "sa_m", "rms": "h_rms_m", "slope_rms": "h_prime_rms"}[key]] == approx(target, rel=1e-12)


@pytest.mark.parametrize("hurst", [0.5, 0.8])
def test_analyze_recovers_the_hurst_exponent_within_its_standard_error(hurst):
    n, L, k_l, k_s = 128, 1e-3, 4, 48
    s = ws.surface.generate(n, L, hurst=hurst, k_l=k_l, k_s=k_s, seed=2)
    q = 2 * math.pi / L
    a = ws.surface.analyze(s, q_min=k_l * q, q_max=k_s * q)
    # The generated amplitudes equal the target PSD exactly (no random amplitudes),
    # so the fit returns H up to the binning of the annuli.
    assert a["hurst"] == approx(hurst, abs=max(3 * a["hurst_error"], 0.01))
    assert a["psd_q_rad_per_m"].shape == a["psd_c_m4"].shape and len(a["psd_count"]) == a["psd_q_rad_per_m"].size
    assert a["psd_2d_m4"].shape == (n, n // 2 + 1)


def test_a_written_surface_reads_back_bit_for_bit_with_its_size(tmp_path):
    s = ws.surface.generate(32, 5e-4, seed=1, rms=1e-7)
    ws.surface.write(tmp_path / "s.h5", s)
    back = ws.surface.read(tmp_path / "s.h5")
    assert np.array_equal(back.heights, s.heights) and (back.lx, back.ly) == (s.lx, s.ly)
    assert "HDF5" in back.meta["format"] or "wearscale" in back.meta["format"]


def test_a_text_topography_is_read_with_the_size_it_declares_or_the_one_given(tmp_path):
    h = np.arange(12.0).reshape(3, 4) * 1e-9
    f = tmp_path / "t.txt"
    f.write_text("# lx = 3e-6\n# ly = 4e-6\n" + "\n".join(" ".join(repr(v) for v in row) for row in h) + "\n")
    t = ws.surface.read(f)
    assert np.array_equal(t.heights, h) and (t.lx, t.ly) == (3e-6, 4e-6)
    assert ws.surface.read(f, lx=6e-6, ly=8e-6).lx == 6e-6


def test_bad_parameters_name_the_key_and_the_allowed_range():
    with pytest.raises(ws.InputError, match=r"hurst.*1\.5.*\(0, 1\]"):
        ws.surface.generate(64, 1.0, hurst=1.5)
    with pytest.raises(ValueError, match="k_s"):
        ws.surface.generate(64, 1.0, k_s=40)  # above the Nyquist wavenumber 32
    with pytest.raises(ValueError, match="at most one"):
        ws.surface.generate(64, 1.0, sa=1.0, rms=1.0)


def test_the_supported_formats_are_named_and_an_h5_output_is_seen_by_io(tmp_path):
    formats = ws.surface.supported_formats()
    assert len(formats) >= 5 and all(isinstance(f, str) and f for f in formats)
    s = ws.surface.generate(16, 1e-4, k_s=8, seed=1)
    ws.surface.write(tmp_path / "s.h5", s)
    assert ws.io.exists(str(tmp_path / "s.h5"), "/surface/height")
    assert not ws.io.exists(str(tmp_path / "s.h5"), "/surface/nothing")
    assert np.array_equal(ws.io.read(str(tmp_path / "s.h5"), "/surface/height"), s.heights)


def test_a_missing_file_is_a_value_error_naming_it(tmp_path):
    with pytest.raises(ValueError, match="nothing.h5"):
        ws.surface.read(tmp_path / "nothing.h5")


def test_the_roughness_measures_take_a_surface_as_the_contact_does():
    s = ws.surface.generate(64, 2e-4, k_l=2, k_s=16, seed=3, slope_rms=0.2, ny=32, ly=1e-4)
    assert ws.surface.h_prime_rms(s) == ws.surface.h_prime_rms(s.heights, s.lx, s.ly) == approx(0.2, rel=1e-12)
    assert ws.surface.sa(s) == ws.surface.sa(s.heights)
    assert ws.surface.h_rms(s) == ws.surface.h_rms(s.heights)
    with pytest.raises(ValueError, match="lx"):
        ws.surface.h_prime_rms(s.heights)  # a plain array needs its size


def test_generate_and_read_say_they_return_a_surface():
    for call in (ws.surface.generate, ws.surface.read):
        doc = call.__doc__
        assert "Returns a Surface" in doc and "Returns (heights" not in doc, doc
    assert isinstance(ws.surface.generate(16, 1e-4, k_s=8), ws.surface.Surface)


def test_a_fit_that_is_not_self_affine_is_reported_failed_and_the_rest_stands():
    # A sphere's PSD is no power law of 0 < H <= 1 over every bin.
    cap = ws.surface.sphere(64, 1e-3, radius=2e-3)
    a = ws.surface.analyze(cap)
    assert a["hurst_fit"]["status"] == "failed" and "not self-affine" in a["hurst_fit"]["reason"]
    assert "hurst" not in a and a["sa_m"] > 0 and a["h_prime_rms"] > 0 and a["psd_c_m4"].size > 10
    s = ws.surface.generate(128, 1e-3, hurst=0.8, k_l=4, k_s=48, seed=2)
    q = 2 * math.pi / 1e-3
    good = ws.surface.analyze(s, q_min=4 * q, q_max=48 * q)
    assert good["hurst_fit"] == {"status": "done", "reason": ""} and "hurst" in good
