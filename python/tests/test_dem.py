"""wearscale.dem: the cohesive-DEM targets (6.35), (6.62), (6.65) and a short patch test (§6.2.1)."""
import pytest

import wearscale as ws
from _approx import approx


def test_the_table_6_4_targets_give_the_critical_and_minimum_sizes():
    m = ws.dem.material()
    assert (m["young"], m["poisson"], m["tensile_strength"], m["surface_energy"]) == (1.0, 0.15, 0.2, 1.5)
    assert m["d_c"] == approx(4 * 1.5 * 1.0 / 0.2**2)  # 4γE/σ² (6.35)
    assert m["d_min"] == approx(4 * 1.5 / 0.2)  # 4γ/σ (6.62)
    with pytest.raises(ValueError, match="1/4"):
        ws.dem.material(poisson=0.3)  # pair forces give ν ≤ 1/4 (6.52)


def test_a_short_hcp_patch_test_measures_the_target_elastic_constants():
    # A short sample (L = 8 d0; the thesis' 25 d0 runs in examples/python/dem_patch_test.py):
    # its walls stiffen it, E = 1.10 here, 1.06 at 12 d0, 1.04 at 25 d0; ν is already within 0.01.
    r = ws.dem.patch_test(d0=90, length=8, width=3)
    assert r["elastic_converged"] and r["particles"] > 0
    assert r["young"] == approx(1.0, rel=0.1)
    assert r["poisson"] == approx(0.15, abs=0.01)
    assert r["tensile_strength"] is None  # strengths=False
    with pytest.raises(ValueError, match="lattice"):
        ws.dem.patch_test(lattice="fcc")


def test_a_junction_below_the_critical_size_deforms_and_reports_its_history_and_particles():
    r = ws.dem.sheared_junction(diameter=8e-9, d0=3e-9, box=[24e-9, 16e-9, 24e-9], sliding_distance=3e-9)
    sio2 = ws.materials.material("SiO2")
    d_star = 32 * sio2["surface_energy_J_per_m2"] * sio2["shear_modulus_Pa"] / sio2["shear_strength_Pa"] ** 2  # (6.65)
    assert r["d_star_m"] == approx(d_star, rel=1e-12)
    assert not r["detached"] and r["verdict"] == "deformed plastically"  # D = 8 nm < d* = 18.5 nm (§6.3)
    h = r["history"]
    assert h["sliding_m"].shape == h["tangential_force_N"].shape and h["sliding_m"].size > 10
    assert (h["sliding_m"][1:] >= h["sliding_m"][:-1]).all() and h["sliding_m"][-1] == approx(3e-9, rel=0.05)
    assert r["peak_tangential_force_N"] == approx(h["tangential_force_N"].max(), rel=1e-12)
    f = r["final"]
    assert f["position"].shape == (r["particles"], 3) and f["radius"].shape == (r["particles"],)
