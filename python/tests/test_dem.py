"""wearscale.dem: the cohesive-DEM targets (6.35), (6.62), (6.65) and a short patch test (§6.2.1)."""
import pytest

import wearscale as ws


def test_the_table_6_4_targets_give_the_critical_and_minimum_sizes():
    m = ws.dem.material()
    assert (m["young"], m["poisson"], m["tensile_strength"], m["surface_energy"]) == (1.0, 0.15, 0.2, 1.5)
    assert m["d_c"] == pytest.approx(4 * 1.5 * 1.0 / 0.2**2)  # 4γE/σ² (6.35)
    assert m["d_min"] == pytest.approx(4 * 1.5 / 0.2)  # 4γ/σ (6.62)
    with pytest.raises(ValueError, match="1/4"):
        ws.dem.material(poisson=0.3)  # pair forces give ν ≤ 1/4 (6.52)


def test_a_short_hcp_patch_test_measures_the_target_elastic_constants():
    # A short sample (L = 8 d0; the thesis' 25 d0 runs in examples/python/dem_patch_test.py):
    # its walls stiffen it, E = 1.10 here, 1.06 at 12 d0, 1.04 at 25 d0; ν is already within 0.01.
    r = ws.dem.patch_test(d0=90, length=8, width=3)
    assert r["elastic_converged"] and r["particles"] > 0
    assert r["young"] == pytest.approx(1.0, rel=0.1)
    assert r["poisson"] == pytest.approx(0.15, abs=0.01)
    assert r["tensile_strength"] is None  # strengths=False
    with pytest.raises(ValueError, match="lattice"):
        ws.dem.patch_test(lattice="fcc")
