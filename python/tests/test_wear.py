"""wearscale.wear: the analytic wear maps of Fig. 3.7 and Fig. 4.6 ((4.48), (4.49)) and the
rough-surface map of §5.3 on a small grid."""
import math

import numpy as np
import pytest

import wearscale as ws
from _approx import approx


def test_the_interaction_constant_spans_one_third_to_two_thirds():
    assert ws.wear.interaction_constant(0.5, 0.0) == approx(2 / 3)
    assert ws.wear.interaction_constant(0.5, math.pi / 2) == approx(1 / 3)
    assert ws.wear.interaction_constant(0.3, 0.0) == approx(1 / 1.7)  # (1 − ν sin²θ)/(2 − ν)
    with pytest.raises(ValueError):
        ws.wear.interaction_constant(0.7, 0.0)


def test_the_3d_map_has_the_regions_of_fig_4_6_and_r_is_1_on_their_boundaries():
    m = ws.wear.analytic_map_3d(c_inter=2 / 3, nx=51, ny=41)
    assert m["region"].shape == (51, 41) and m["x"].shape == (51,) and m["y"].shape == (41,)
    assert set(np.unique(m["region"])) == {0, 1, 2, 3}
    d = np.array([0.2, 0.5, 0.9])
    for case in (0, 1, 2):
        line = ws.wear.boundary_dstar_over_l(case, d, 2 / 3)
        for x, y in zip(d, line):
            assert ws.wear.energy_ratio_3d(case, x, y, 2 / 3) == approx(1.0, rel=1e-12)
    # a case other than 0, 1, 2 is refused, not read as C_case = 0 (a boundary at d*/l = 0)
    with pytest.raises(ws.InputError, match=r"case = 3.*0 \(one separated\) \| 1 \(two separated\) \| 2 \(combined\)"):
        ws.wear.boundary_dstar_over_l(3, d, 2 / 3)
    with pytest.raises(ValueError, match="case = -1"):
        ws.wear.energy_ratio_3d(-1, 0.5, 0.5, 2 / 3)
    # less interaction (1/3) shrinks every wear region
    weak = ws.wear.analytic_map_3d(c_inter=1 / 3, nx=51, ny=41)
    assert np.count_nonzero(weak["region"] > 0) < np.count_nonzero(m["region"] > 0)


def test_the_2d_map_comes_with_its_layers():
    m = ws.wear.analytic_map_2d(nx=31, ny=61)
    assert m["region"].shape == (31, 61) and len(m["region_names"]) >= 2
    assert all(a.shape == (31, 61) for a in m["layers"].values())


def test_the_rough_wear_map_detaches_more_at_smaller_critical_size():
    m = ws.wear.rough_wear_map(n=64, k_l=4, k_s=8, loads=[0.1], critical_diameters=[0.02, 0.2], seeds=[1])
    assert m["count_mean"].shape == (1, 2) and m["valid"].dtype == np.bool_
    assert m["volume_mean"][0, 0] >= m["volume_mean"][0, 1]
    assert 0 < m["contact_fraction"][0, 0] < 1


def test_the_energy_released_by_one_of_two_contacts_is_4_44_minus_4_33():
    # Two discs of d = 16 cells, l = 32 cells apart along x (θ = 0), loaded by q = σ_j:
    # detaching one releases E_el,2 − E_el,1 = (2−ν)d³q²/(12G) + πd⁴q²/(32Gl)   (4.33), (4.44),
    # so over the energy of one disc alone (4.33): 1 + 3πd/(8(2−ν)l).
    n, lx, G, nu, q = 128, 128e-9, 30e9, 0.3, 1e9
    d_cells, l_cells = 16, 32
    d = d_cells * lx / n
    a = (40, 64, d_cells)
    b = (40 + l_cells, 64, d_cells)
    two = ws.wear.energy_release(ws.wear.disc_mask(n, n, a) | ws.wear.disc_mask(n, n, b), lx, G, nu, q, a)
    one = ws.wear.energy_release(ws.wear.disc_mask(n, n, a), lx, G, nu, q, a)
    assert two["release_J"] == approx(two["work_J"] - two["self_energy_J"], rel=1e-14)
    with pytest.raises(ValueError, match=r"disc \(i, j, cells\) = \(120, 64, 16\); allowed: .*i \+ cells <= nx = 128"):
        ws.wear.energy_release(ws.wear.disc_mask(n, n, a), lx, G, nu, q, (120, 64, 16))
    assert one["release_J"] == approx(one["elastic_energy_J"], rel=1e-9)  # one contact: all of it
    # the 16-cell staircase disc holds 3.6 % less energy than the circle of (4.33)
    assert one["release_J"] == approx((2 - nu) * d**3 * q**2 / (12 * G), rel=0.04)
    # the interaction term of (4.44), where the staircase cancels: measured 0.15 % off
    assert two["release_J"] / one["release_J"] == approx(1 + 3 * math.pi * d_cells / (8 * (2 - nu) * l_cells), rel=3e-3)
