#!/usr/bin/env python3
"""How well each energy orders maps as their measured errors, over every pair of methods of a
phase-averaged `lexel sweep --out DIR` (RESULTS.md, "The edge energy's exponent"; issue 25).

Usage: concordance_table.py [--among METHOD ...] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv with <method>_h, <method>_e,
       <method>_misclassified_mean and <method>_misclassified_se)

A pair of methods on one light counts when their phase means differ beyond the noise (by more
than 1.96 standard errors of the difference, as the sweep's own tables) and the energy ranks them
(both finite, not equal). Per energy (h: the report's eq. 6; e: the edge energy at the case's
exponent, as the sweep wrote it), the % of counted pairs it orders as their errors, pooled over
the set's lights and pairs. The pairs are every two methods of lights.csv, or of the --among
methods; `optimal` minimizes e and `optimal-h` minimizes h, so pairs among baselines alone (the
`--among` of the maps neither energy chose) are the fair test. Bad input: one line, exit status 2.
"""
import csv
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fair_table import fail, parse_args  # noqa: E402

NEEDED = ("_h", "_e", "_misclassified_mean", "_misclassified_se")


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan  # an empty cell: no energy for this map (a warped or virtual one)


def read_lights(d):
    try:
        with open(os.path.join(d, "lights.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{d}: cannot read lights.csv ({e.strerror})")
    if not rows:
        fail(f"{d}/lights.csv: no lights")
    return rows


def methods_of(rows, among, d):
    have = [k[: -len("_misclassified_mean")] for k in rows[0] if k.endswith("_misclassified_mean")]
    methods = among or have
    for m in methods:
        if any(m + n not in rows[0] for n in NEEDED):
            fail(f"{d}/lights.csv: no {', '.join(m + n for n in NEEDED)} columns "
                 f"(run the sweep with --method {m} --phases K)")
    if len(methods) < 2:
        fail(f"{d}/lights.csv: fewer than two methods to pair")
    return methods


def concordance(rows, methods, energy):
    """(agreeing, counted) pairs over the rows."""
    agree = counted = 0
    for r in rows:
        for i, a in enumerate(methods):
            for b in methods[i + 1:]:
                ea, eb = number(r[a + energy]), number(r[b + energy])
                if not (math.isfinite(ea) and math.isfinite(eb)) or ea == eb:
                    continue
                ma, mb = number(r[a + "_misclassified_mean"]), number(r[b + "_misclassified_mean"])
                sa, sb = number(r[a + "_misclassified_se"]), number(r[b + "_misclassified_se"])
                if not abs(ma - mb) > 1.96 * math.hypot(sa, sb):
                    continue
                counted += 1
                agree += (ea < eb) == (ma < mb)
    return agree, counted


def percent(agree, counted):
    return f"{100 * agree / counted:.1f}%" if counted else "—"


def main(among, dirs):
    lines = []  # every set read before anything is printed: bad input prints no partial table
    for d in dirs:
        rows = read_lights(d)
        methods = methods_of(rows, among, d)
        h, e = concordance(rows, methods, "_h"), concordance(rows, methods, "_e")
        name = os.path.basename(os.path.normpath(d))
        lines.append(f"| {name} | {len(rows)} | {h[1]} / {e[1]} | {percent(*h)} | {percent(*e)} |")
    print("| set | lights | pairs | h orders as errors | e orders as errors |")
    print("| --- | ---: | ---: | ---: | ---: |")
    print("\n".join(lines))
    print(f"\nPairs of {', '.join(among) if among else 'every method'} differing beyond the phase "
          "noise and ranked by the energy (h's count / e's).")


if __name__ == "__main__":
    usage = "usage: concordance_table.py [--among METHOD ...] DIR ..."
    values, dirs = parse_args(sys.argv[1:], {"--among": "method name"}, usage)
    main(values["--among"], dirs)
