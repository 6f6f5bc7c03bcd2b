"""wearscale.materials: the records of Table 2.1, the Fig. 9.18 tables and the junction
model's p_crit (7.5), μ0 (9.13) and steady slope (9.17) as VERIFICATION.md lists them."""
import math

import numpy as np
import pytest

import wearscale as ws
from _approx import approx


def test_the_built_in_records_are_si_and_silica_in_si_units():
    assert {"Si", "SiO2"} <= set(ws.materials.names())
    sio2 = ws.materials.material("SiO2")
    assert sio2["young_Pa"] == approx(73e9) and sio2["poisson"] == approx(0.17)
    assert sio2["shear_modulus_Pa"] == approx(73e9 / (2 * 1.17))  # G = E/2(1+ν)
    with pytest.raises(ValueError, match="Si"):
        ws.materials.material("unobtainium")


def test_a_shipped_table_comes_as_arrays_and_a_law_interpolates_it():
    t = ws.materials.strength_table("Si")
    assert t["pressure_Pa"].dtype == np.float64 and t["pressure_Pa"].shape == t["sigma_max_Pa"].shape
    assert np.all(np.diff(t["pressure_Pa"]) >= 0)
    law = ws.materials.StrengthLaw("Si")
    p = np.array([1e9, 5e9, 15e9])
    assert np.allclose(law.sigma_max(p), 10.6e9) and np.allclose(law.sigma_dyn(p), 1.5e9)  # Fig. 9.18, p < 20 GPa
    assert law.sigma_max(1e9) == approx(10.6e9)
    with pytest.raises(ArithmeticError, match="pressure|range|table"):
        law.sigma_max(1e13)
    assert ws.materials.StrengthLaw("Si", clamp=True).sigma_max(1e13) == approx(law.sigma_max(law.pressure_range[1]))


@pytest.mark.parametrize("name,p_crit,mu0", [("Si", 10.6e9, 0.14), ("SiO2", 8.5e9, 0.84)])
def test_critical_pressure_and_friction_coefficient_reproduce_the_thesis(name, p_crit, mu0):
    law = ws.materials.StrengthLaw(name)
    pc = ws.materials.critical_pressure(law)
    assert pc == approx(p_crit, rel=0.01)
    assert ws.materials.friction_coefficient(law, pc) == approx(mu0, abs=0.005)


def test_the_interface_is_governed_by_the_weaker_material_and_the_slope_follows_9_17():
    law = ws.materials.interface_law("SiO2", "Si")
    assert law["governing"] == "Si" and law["mu0"] == approx(0.14, abs=0.005)
    sio2 = ws.materials.critical_pressure(ws.materials.StrengthLaw("SiO2"))
    assert ws.materials.steady_slope_rms(sio2, 37.6e9) == approx(0.57, abs=0.005)
    assert ws.materials.wear_rate(1e9, 1e10) == approx(0.1)
    assert ws.materials.minimum_contact_ratio(1e9, 1e10) == approx(0.1)


def test_critical_size_is_the_flat_contact_formula_4_35():
    si = ws.materials.material("Si")
    d = ws.materials.critical_size("Si", 1e9, "flat")
    c = 12 * math.pi / (2 - si["poisson"])
    assert d == approx(c * si["surface_energy_J_per_m2"] * si["shear_modulus_Pa"] / 1e18, rel=1e-12)
    with pytest.raises(ValueError, match="flat \\| colliding \\| dem"):
        ws.materials.critical_size("Si", 1e9, "square")


def test_the_data_directory_holds_the_tables_and_can_be_pointed_elsewhere(tmp_path, monkeypatch):
    d = ws.materials.data_directory()
    assert (ws.materials.strength_table("Si")["origin"]).startswith(d)
    ws.materials.set_data_directory(str(tmp_path))
    try:
        with pytest.raises(ValueError, match=str(tmp_path)):
            ws.materials.strength_table("Si")
    finally:
        ws.materials.set_data_directory("")
    assert ws.materials.data_directory() == d


def test_a_table_file_a_constant_law_and_the_tangential_resistance_7_9():
    assert "thesis" in ws.materials.shipped_sets()
    t = ws.materials.strength_table("Si")
    back = ws.materials.read_strength_table(t["origin"])
    assert np.array_equal(back["sigma_max_Pa"], t["sigma_max_Pa"]) and back["material"] == "Si"
    law = ws.materials.StrengthLaw("Si")
    assert all(law.pressure_range[0] <= p <= law.pressure_range[1] for p in law.jumps)
    # p_T = (A/A0) σ(p_N A0/A) (7.9): at A/A0 = 0.1 the junctions carry 10 GPa < 20 GPa, where
    # σ_dyn = 1.5 GPa and σ_max = 10.6 GPa (Fig. 9.18)
    assert ws.materials.tangential_resistance(law, 1e9, 0.1) == approx(1.5e8, rel=1e-9)
    assert ws.materials.tangential_resistance(law, 1e9, 0.1, peak=True) == approx(1.06e9, rel=1e-9)
    flat = ws.materials.StrengthLaw.constant("X", 2e9, 50e9)
    assert flat.sigma_max(3e9) == 2e9 and flat.sigma_dyn(np.array([1e9, 4e10])).tolist() == [2e9, 2e9]
    assert ws.materials.critical_pressure(flat) == approx(2e9, rel=1e-9)  # σ_max(p) = p (7.5)
