"""wearscale.run: cases through the CLI's runner, from a file, a TOML string or a dict, with
--set-style overrides; bad cases are ValueErrors naming the key, before anything is written."""
import pytest

import wearscale as ws
from _approx import approx


def test_the_hertz_pin_case_gives_the_thesis_contact_diameter(source_dir, tmp_path):
    r = ws.run(source_dir / "cases" / "hertz_pin.toml", out=tmp_path / "o")
    assert isinstance(r, dict) and r.output_dir == tmp_path / "o"
    values = r.results
    diameter = 2 * values["contact_radius"]
    assert diameter == approx(78.2e-6, rel=2e-3)  # §8.1


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
    with pytest.raises(ws.InputError, match="poisson_ratio.*0.7"):
        ws.run(case, out=tmp_path / "bad")
    assert not (tmp_path / "bad").exists()
