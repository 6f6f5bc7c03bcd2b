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
    r = ws.dem.patch_test(d0=90, length=8, width=3, strengths=False)
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


D0 = 3e-9


def test_sheared_rough_surfaces_hold_the_pressure_wear_and_report_their_roughness():
    # The reduced §7.2 cell of tests/dem/test_rough_shear.cpp, slid half as far: 20 d0 long, Sa = 0.04 L.
    r = ws.dem.rough_shear(roughness=0.04, d0=D0, box=[20 * D0, 3.5 * D0, 14 * D0], pressure=0.5e9,
                           velocity=100.0, sliding_distance=4 * D0, settle_distance=D0)
    assert r["imposed_roughness_m"] == approx(0.04 * 20 * D0, rel=0.05)  # the carved profiles' Sa
    h = r["history"]
    assert h["roughness_bottom_m"][0] == approx(r["imposed_roughness_m"], rel=0.15)
    assert h["worn"][0] == 0 and r["worn"] > 0  # particles wear at the interface
    assert r["mean_pressure_Pa"] == approx(0.5e9, rel=0.1)  # the pressed wall holds p_N
    assert h["sliding_m"][-1] == approx(4 * D0, abs=0.05 * D0)
    assert r["friction"] == approx(r["mean_tangential_force_N"] / (r["mean_pressure_Pa"] * r["area_m2"]), rel=0.02)
    assert r["regime"] in ("rolling wear particles", "shear band", "no wear particle")
    assert r["final"]["position"].shape == (r["particles"], 3)
    with pytest.raises(ValueError, match="box"):
        ws.dem.rough_shear(box=[1e-7, 1e-8])


def test_two_trapped_particles_roll_at_a_tenth_of_a_gigapascal():
    # The reduced §7.3 cell of tests/dem/test_trapped_particles.cpp at its low load.
    r = ws.dem.trapped_particles(count=2, diameter=5 * D0, d0=D0, box=[30 * D0, 3.5 * D0, 12 * D0], pressure=0.1e9,
                                 velocity=200.0, sliding_distance=8 * D0, settle_distance=D0, fit_from=0.0)
    assert len(r["loose_particles"]) == 2 and min(r["loose_particles"]) >= 20  # discs of many DEM particles
    assert r["rolling"] and r["regime"] == "rolling", r["mean_residual"]
    assert r["history"]["tangential_force_N"].shape == r["history"]["sliding_m"].shape
