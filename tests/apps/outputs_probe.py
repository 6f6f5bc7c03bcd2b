"""What a pandas or h5py user finds in wearscale's pin-on-disc outputs
(tests/apps/test_outputs_cli.cpp runs it; it exits non-zero naming what is wrong).

  outputs_probe.py run FOLDER NORMAL_LOAD_N LAYERED   a run's folder (LAYERED: 1 if an oxide of
                                                       finite thickness lies on a substrate)
  outputs_probe.py sweep FOLDER                        the oxide sweep's folder
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pandas as pd


def check(condition, what):
    if not condition:
        sys.exit(f"outputs_probe: {what}")


def floats_only(csv, label_columns=()):
    """Every column pandas reads as float64 (a column written "0" would be int64), no "-0"."""
    df = pd.read_csv(csv)
    for c in df.columns:
        if c not in label_columns:
            check(df[c].dtype == np.float64, f"{csv}: column {c} is {df[c].dtype}, not float64")
    with open(csv) as f:
        for line in f:
            for cell in line.strip().split(","):
                check(cell not in ("-0", "-0.0"), f"{csv}: a cell '{cell}'")
    return df


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel * max(abs(a), abs(b))


def run(folder, normal_load, layered):
    friction = floats_only(os.path.join(folder, "friction.csv"))
    profile = floats_only(os.path.join(folder, "disc_profile.csv"))
    results = json.load(open(os.path.join(folder, "summary.json")))["results"]
    # Archard's specific wear rate k = V / (F_N s) in mm^3/(N m), by hand from the same run's V and s.
    s = results["distance"]["value"]
    for body in ("pin", "disc"):
        k = results[f"{body}_specific_wear_rate"]
        check(k["unit"] == "mm^3/(N·m)", f"{body}: unit {k['unit']}")
        by_hand = results[f"{body}_wear"]["value"] * 1e9 / (normal_load * s)
        check(close(k["value"], by_hand), f"{body}: k = {k['value']}, V/(F s) = {by_hand}")
        column = friction[f"{body}_specific_wear_rate_mm3_per_N_per_m"]
        check(close(column.iloc[-1], by_hand, 1e-9), f"friction.csv: last k of the {body} {column.iloc[-1]}")
        check(math.isnan(column.iloc[0]), "friction.csv: k at s = 0 is not nan")
    # Grooves (bands worn through an oxide into the substrate) exist only with both.
    if not layered:
        check(friction["grooves"].isna().all(), "friction.csv: grooves without an oxide on a substrate")
        check(profile["through_layer"].isna().all(), "disc_profile.csv: through_layer without an oxide on a substrate")
        check("grooves" not in results, "summary.json: grooves without an oxide on a substrate")
    else:
        check(friction["grooves"].iloc[-1] == results["grooves"]["value"], "grooves: friction.csv and summary differ")

    h5 = h5py.File(os.path.join(folder, "run.h5"), "r")
    for name in ("pin_wear", "pin_specific_wear_rate", "mu_mean"):
        d = h5["/results/" + name]
        check(d.shape == (), f"run.h5 /results/{name}: shape {d.shape}, not ()")
        check(isinstance(d.attrs["unit"], str), f"run.h5 /results/{name}: unit {d.attrs['unit']!r} is not a str")
    check(h5["/results/pin_wear"].attrs["unit"] == "m^3", "run.h5: pin_wear's unit")
    check(isinstance(h5.attrs["case_toml"], str), "run.h5: case_toml is not a str")
    disc = h5["/macro/final/disc"]
    check(disc.attrs["axes"] == "x,y", f"disc: axes {disc.attrs['axes']!r}")
    check(isinstance(disc.attrs["description"], str) and disc.attrs["description"], "disc: no description")
    nx, ny = disc.shape
    lx, x0 = disc.attrs["lx"], disc.attrs["x0"]
    check(x0 == -lx / 2, f"disc: x0 = {x0}, lx = {lx}")
    # One x for the disc everywhere: run.h5, final_surfaces.xdmf, disc_profile.csv (and its figure, drawn from it).
    x_h5 = x0 + np.arange(nx) * (lx / nx)
    check(np.allclose(profile["x_m"].to_numpy(), x_h5, rtol=0, atol=1e-18), "disc_profile.csv x is not run.h5's x")
    depth_h5 = -disc[...].mean(axis=1)
    check(np.allclose(profile["worn_depth_m"].to_numpy(), depth_h5, rtol=1e-9, atol=1e-20),  # the CSV: 10 digits
          "disc_profile.csv's depth is not run.h5's disc")
    deepest_h5 = x_h5[int(np.argmax(depth_h5))]
    deepest_csv = profile["x_m"][profile["worn_depth_m"].idxmax()]
    geometry = ET.parse(os.path.join(folder, "final_surfaces.xdmf")).getroot().find(".//Geometry")
    origin, spacing = [[float(v) for v in item.text.split()] for item in geometry.findall("DataItem")]
    deepest_xdmf = origin[2] + int(np.argmax(depth_h5)) * spacing[2]  # XDMF lists z, y, x
    check(deepest_h5 == deepest_csv == deepest_xdmf,
          f"deepest point at x = {deepest_h5} (run.h5), {deepest_csv} (csv), {deepest_xdmf} (xdmf)")
    check(deepest_csv == 0.0, f"the deepest point is at x = {deepest_csv}, not on the pin's axis")


def sweep(folder):
    table = os.path.join(folder, "friction_vs_thickness.csv")
    df = floats_only(table)
    check(df.columns[0] == "layer_thickness_m", f"first column {df.columns[0]}")
    units = json.load(open(table + ".json"))["units"]
    check(units["layer_thickness_m"] == "m", f"sidecar unit {units['layer_thickness_m']}")
    check(units["pin_specific_wear_rate_mm3_per_N_per_m"] == "mm^3/(N·m)", "k's unit")
    h = df["layer_thickness_m"]
    for i in range(len(df)):
        layered = 0 < h[i] < math.inf
        check(math.isnan(df["grooves"][i]) != layered, f"h = {h[i]}: grooves {df['grooves'][i]}")
    check(df["pin_wear_m3"][h == 0].iloc[0] == 0.0, "no pin wear without an oxide")


if __name__ == "__main__":
    if sys.argv[1] == "run":
        run(sys.argv[2], float(sys.argv[3]), sys.argv[4] == "1")
    else:
        sweep(sys.argv[2])
