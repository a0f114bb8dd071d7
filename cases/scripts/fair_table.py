#!/usr/bin/env python3
"""Summarize phase-averaged `lexel sweep --out DIR` runs of the fair comparison (RESULTS.md).

Usage: fair_table.py [--against METHOD ...] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv)

Per directory, one Markdown row: each method's mean phase-averaged misclassified pixels, the
paired difference of `optimal` against each --against method (default: `optimal-h`) and against
the per-light best single-map baseline (mean ± 95% half-width over the lights, Student t, as a
% of the reference's mean), and the lights on which `optimal` misclassifies more than twice the
best baseline's count plus 50 pixels (issue 25's rule). Bad input: one line, exit status 2.
"""
import csv
import math
import os
import sys

BASELINES = ["focused-tight", "lispsm-tight", "psm-tight", "plane-optimal", "normal"]
# Two-sided 95% Student t quantiles for n - 1 degrees of freedom (n lights), then the normal's.
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 9: 2.262, 19: 2.093, 29: 2.045,
       49: 2.010, 99: 1.984}


def t95(dof):
    best = min(T95, key=lambda d: (abs(d - dof), d))
    return T95[best] if dof < 200 else 1.96


def mean_ci(values):
    n = len(values)
    m = sum(values) / n
    if n < 2:
        return m, float("nan")
    var = sum((v - m) ** 2 for v in values) / (n - 1)
    return m, t95(n - 1) * math.sqrt(var / n)


def fail(message):
    print("fair_table.py: " + message, file=sys.stderr)
    sys.exit(2)


def read_rows(d):
    try:
        with open(os.path.join(d, "lights.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{d}: cannot read lights.csv ({e.strerror})")
    if not rows or "optimal_misclassified_mean" not in rows[0]:
        fail(f"{d}/lights.csv: no lights with optimal's phase-averaged counts "
             "(run the sweep with --method optimal --phases K)")
    return rows


def main(against, dirs):
    for d in dirs:
        rows = read_rows(d)
        methods = [k[: -len("_misclassified_mean")] for k in rows[0]
                   if k.endswith("_misclassified_mean")]
        mean = {m: [float(r[m + "_misclassified_mean"]) for r in rows] for m in methods}
        base = [b for b in BASELINES if b in mean]
        best = [min(mean[b][i] for b in base) for i in range(len(rows))]
        cells = [f"{sum(mean[m]) / len(rows):.0f}" for m in methods]
        out = [os.path.basename(os.path.normpath(d)), str(len(rows))] + cells
        opt = mean["optimal"]
        for m in against or []:
            if m not in mean:
                fail(f"--against {m}: {d}/lights.csv has no such method")
        if against is None:  # the default: optimal-h where the sweep ran it
            against = [m for m in ["optimal-h"] if m in mean]
        for ref in [mean[m] for m in against] + [best]:
            dm, ci = mean_ci([a - b for a, b in zip(opt, ref)])
            refm = sum(ref) / len(ref)
            out.append(f"{100 * dm / refm:+.1f} ± {100 * ci / refm:.1f}%")
        bad = sum(1 for a, b in zip(opt, best) if a > 2 * b + 50)
        out.append(str(bad))
        if d == dirs[0]:
            paired = "".join(f" | optimal − {m}" for m in against)
            print("| set | lights | " + " | ".join(methods) + paired +
                  " | optimal − best baseline (per light) | lights > 2×best+50 |")
            print("| --- | ---: |" + " ---: |" * (len(methods) + len(against) + 2))
        print("| " + " | ".join(out) + " |")


if __name__ == "__main__":
    args = sys.argv[1:]
    against, dirs = [], []
    while args:
        a = args.pop(0)
        if a == "--against":
            if not args:
                fail("--against: needs a method name")
            against.append(args.pop(0))
        elif a.startswith("-"):
            fail(f"{a}: unknown option (usage: fair_table.py [--against METHOD ...] DIR ...)")
        else:
            dirs.append(a)
    if not dirs:
        fail("no sweep directory given (usage: fair_table.py [--against METHOD ...] DIR ...)")
    main(against or None, dirs)
