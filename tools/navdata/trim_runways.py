#!/usr/bin/env python3
"""Builds data/nav/runways.csv from OurAirports' runways.csv (public domain).

Keeps open, hard-surface runways of at least --min-length-ft with both ends positioned, one row per
runway END (the end a pilot lands on), with the columns fedsim uses, in SI where it matters.
Usage: trim_runways.py OURAIRPORTS_RUNWAYS_CSV OUT_CSV [--min-length-ft 5000]
"""
import argparse
import csv

HARD = ("ASP", "CON", "PEM", "BIT", "TAR", "PAV")
FT = 0.3048


def ends(row):
    """Yields (ident, lat, lon, elev_ft, heading, displaced_ft, opposite) for both ends."""
    for this, other in (("le", "he"), ("he", "le")):
        yield (row[f"{this}_ident"], row[f"{this}_latitude_deg"], row[f"{this}_longitude_deg"],
               row[f"{this}_elevation_ft"], row[f"{this}_heading_degT"],
               row[f"{this}_displaced_threshold_ft"], other)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("source")
    parser.add_argument("out")
    parser.add_argument("--min-length-ft", type=float, default=5000.0)
    args = parser.parse_args()
    kept = 0
    with open(args.source, newline="") as src, open(args.out, "w", newline="") as dst:
        out = csv.writer(dst)
        out.writerow(["airport", "runway", "threshold_lat_deg", "threshold_lon_deg",
                      "elevation_m", "heading_true_deg", "length_m", "displaced_threshold_m"])
        for row in csv.DictReader(src):
            try:
                length_ft = float(row["length_ft"] or 0)
            except ValueError:
                continue
            if row["closed"] == "1" or length_ft < args.min_length_ft:
                continue
            if not row["surface"].upper().startswith(HARD):
                continue
            needed = ("le_ident", "he_ident", "le_latitude_deg", "le_longitude_deg",
                      "he_latitude_deg", "he_longitude_deg")
            if not all(row[k] for k in needed):
                continue
            for ident, lat, lon, elev_ft, heading, displaced_ft, other in ends(row):
                if not heading:
                    continue
                elev = float(elev_ft or row[f"{other}_elevation_ft"] or 0) * FT
                out.writerow([row["airport_ident"], ident, lat, lon, f"{elev:.1f}", heading,
                              f"{length_ft * FT:.0f}", f"{float(displaced_ft or 0) * FT:.0f}"])
                kept += 1
    print(f"{kept} runway ends written to {args.out}")


if __name__ == "__main__":
    main()
