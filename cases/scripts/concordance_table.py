#!/usr/bin/env python3
"""How well each energy orders maps as their measured errors, over every pair of methods of a
phase-averaged `lexel sweep --out DIR` (RESULTS.md, "Does the edge energy order maps as their
errors?").

Usage: concordance_table.py [--among METHOD ...] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv with <method>_h, <method>_e,
       <method>_misclassified_mean and <method>_misclassified_se)

A pair of methods on one light counts when their phase means differ beyond the noise (by more
than 1.96 standard errors of the difference, as the sweep's own tables) and the energy ranks them
(both finite, not equal). Per energy (h: the report's eq. 6; e: the edge energy at the case's
exponent, as the sweep wrote it), the % of the pairs both energies rank that it orders as their
errors, pooled over the set's lights and pairs; then the pairs only e ranks (h = 0 on a light
without boundary samples, where e's prior decides) and e's % on those. The pairs are every two methods of lights.csv, or of the --among
methods; `optimal` minimizes e and `optimal-h` minimizes h, so pairs among baselines alone (the
`--among` of the maps neither energy chose) are the fair test. Bad input: one line, exit status 2.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_lights import beyond_noise, fail, parse_args  # noqa: E402
from sweep_lights import read_lights as read_csv  # noqa: E402

NEEDED = ("_h", "_e", "_misclassified_mean", "_misclassified_se")


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):  # an empty cell (a warped or virtual map has no energy) or
        return math.nan  # a short row


def read_lights(d):
    rows = read_csv(d)
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


def ranks(r, a, b, energy):
    """The energy's order of a and b on row r: True (a lower), False, or None (it ranks nothing:
    an infinite or missing value, or a tie, as at h = 0 on a light without boundary samples)."""
    ea, eb = number(r[a + energy]), number(r[b + energy])
    if not (math.isfinite(ea) and math.isfinite(eb)) or ea == eb:
        return None
    return ea < eb


def concordance(rows, methods):
    """Over the pairs whose errors differ beyond the noise: [agree, counted] for h and for e on
    the pairs both rank, and for e on the pairs only e ranks."""
    both_h, both_e, only_e = [0, 0], [0, 0], [0, 0]
    for r in rows:
        for i, a in enumerate(methods):
            for b in methods[i + 1:]:
                ma, mb = number(r[a + "_misclassified_mean"]), number(r[b + "_misclassified_mean"])
                sa, sb = number(r[a + "_misclassified_se"]), number(r[b + "_misclassified_se"])
                if not beyond_noise(ma, sa, mb, sb):
                    continue
                h, e = ranks(r, a, b, "_h"), ranks(r, a, b, "_e")
                if h is not None and e is not None:
                    for tally, order in ((both_h, h), (both_e, e)):
                        tally[0] += order == (ma < mb)
                        tally[1] += 1
                elif e is not None:
                    only_e[0] += e == (ma < mb)
                    only_e[1] += 1
    return both_h, both_e, only_e


def percent(agree, counted):
    return f"{100 * agree / counted:.1f}%" if counted else "—"


def main(among, dirs):
    lines = []  # every set read before anything is printed: bad input prints no partial table
    for d in dirs:
        rows = read_lights(d)
        h, e, only_e = concordance(rows, methods_of(rows, among, d))
        name = os.path.basename(os.path.normpath(d))
        lines.append(f"| {name} | {len(rows)} | {h[1]} | {percent(*h)} | {percent(*e)} | "
                     f"{only_e[1]} | {percent(*only_e)} |")
    print("| set | lights | pairs | h orders as errors | e orders as errors | pairs only e ranks "
          "| e orders those |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    print("\n".join(lines))
    print(f"\nPairs of {', '.join(among) if among else 'every method'} whose phase means differ "
          "beyond the noise: those both energies rank, then those only e ranks (h ties or is "
          "infinite there, e.g. h = 0 without boundary samples, where e has its prior).")


if __name__ == "__main__":
    usage = "usage: concordance_table.py [--among METHOD ...] DIR ..."
    values, dirs = parse_args(sys.argv[1:], {"--among": "method name"}, usage)
    twice = sorted({m for m in values["--among"] if values["--among"].count(m) > 1})
    if twice:
        fail(f"--among {twice[0]}: given twice")
    main(values["--among"], dirs)
