#!/usr/bin/env python3
"""Trims the NASA TM-2015-218675 check-case CSVs to what nasa_check_tests compares.

Maintenance script, not needed to build or test: it was run once to produce
tests/data/nasa/<case>/<case>_sim_NN.csv from the raw NASA files (units and column names are
kept as NASA wrote them; the test's loader converts to SI).

usage: trim_reference.py RAW_DIR OUT_DIR [--period 0.5]
"""
import argparse
import csv
import os
import re

CASES = ["Atmos_01", "Atmos_02", "Atmos_03", "Atmos_06", "Atmos_07", "Atmos_09", "Atmos_10"]
COLUMNS = [
    "time", "altitudeMsl_ft", "latitude_deg", "longitude_deg",
    "feVelocity_ft_s_X", "feVelocity_ft_s_Y", "feVelocity_ft_s_Z",
    "eulerAngle_deg_Roll", "eulerAngle_deg_Pitch", "eulerAngle_deg_Yaw",
    "bodyAngularRateWrtEi_deg_s_Roll", "bodyAngularRateWrtEi_deg_s_Pitch",
    "bodyAngularRateWrtEi_deg_s_Yaw",
]


def short(value):
    """12 significant figures: ample for the ~1e-9 relative agreement between NASA's tools."""
    text = "%.12g" % float(value)
    return "0" if text in ("-0", "0") else text


def trim(src, dst, period):
    with open(src, newline="") as f:
        rows = list(csv.DictReader(f))
    keep = [c for c in COLUMNS if c in rows[0]]
    with open(dst, "w", newline="") as f:
        f.write(",".join(keep) + "\n")
        for row in rows:
            t = float(row["time"])
            if abs(t / period - round(t / period)) > 1e-6:
                continue
            f.write(",".join(short(round(t, 6)) if c == "time" else short(row[c]) for c in keep) + "\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("raw_dir")
    parser.add_argument("out_dir")
    parser.add_argument("--period", type=float, default=0.5)
    args = parser.parse_args()
    for folder in sorted(os.listdir(args.raw_dir)):
        case = folder[:8]
        if case not in CASES:
            continue
        os.makedirs(os.path.join(args.out_dir, case), exist_ok=True)
        for name in sorted(os.listdir(os.path.join(args.raw_dir, folder))):
            if re.match(r"Atmos_\d\d_sim_\d\d\.csv$", name):
                trim(os.path.join(args.raw_dir, folder, name),
                     os.path.join(args.out_dir, case, name), args.period)


if __name__ == "__main__":
    main()
