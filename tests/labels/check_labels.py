#!/usr/bin/env python3
"""Every CTest test carries exactly one of the project's labels (cmake/FedsimTestLabels.cmake).

Reads the test list as `ctest --show-only=json-v1` writes it (from a build folder, or from a file
for the negative control), prints how many tests carry each label and fails (exit 1) naming every
test with no label, more than one, or one that is not a project label: such a test would run in
no preset but the default one, or in the wrong one.

Usage: check_labels.py (--build DIR --ctest CTEST | --json FILE) --labels LABEL...
"""
import argparse
import json
import subprocess
import sys
from collections import Counter


def load_tests(args):
    if args.json:
        with open(args.json, encoding="utf-8") as f:
            return json.load(f)["tests"]
    listing = subprocess.run([args.ctest, "--show-only=json-v1", "--test-dir", args.build],
                             check=True, capture_output=True, text=True)
    return json.loads(listing.stdout)["tests"]


def labels_of(test):
    for prop in test.get("properties", []):
        if prop["name"] == "LABELS":
            return prop["value"]
    return []


def problems_of(tests, allowed):
    problems = []
    for test in tests:
        labels = labels_of(test)
        if not labels:
            problems.append(f"{test['name']}: no label")
        elif len(labels) > 1:
            problems.append(f"{test['name']}: {len(labels)} labels ({', '.join(labels)}), not one")
        elif labels[0] not in allowed:
            problems.append(f"{test['name']}: label '{labels[0]}' is not one of {', '.join(allowed)}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build")
    parser.add_argument("--ctest", default="ctest")
    parser.add_argument("--json")
    parser.add_argument("--labels", nargs="+", required=True)
    args = parser.parse_args()
    if bool(args.build) == bool(args.json):
        parser.error("give --build or --json")
    tests = load_tests(args)
    counts = Counter(labels_of(t)[0] for t in tests if len(labels_of(t)) == 1)
    print(f"test labels: {len(tests)} tests: "
          + ", ".join(f"{label} {counts.get(label, 0)}" for label in args.labels))
    problems = problems_of(tests, args.labels)
    for problem in problems:
        print(f"test labels: {problem}")
    if problems:
        print(f"test labels: FAILED: {len(problems)} test(s) without exactly one project label")
        return 1
    if not tests:
        print("test labels: FAILED: no test listed")
        return 1
    print("test labels: every test has exactly one label")
    return 0


if __name__ == "__main__":
    sys.exit(main())
