#!/usr/bin/env python3
"""Summarize phase-averaged `lexel sweep --out DIR` runs of the fair comparison (RESULTS.md).

Usage: fair_table.py [--reference METHOD] [--against METHOD ...] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv)

Per directory, one Markdown row: each method's mean phase-averaged misclassified pixels, the
paired difference of the reference method (default: `optimal`) against each --against method
(default: `optimal-h`) and, where the sweep ran any of the five single-map baselines, against
their per-light best (mean ± 95% half-width over the lights, Student t, as a % of the other's
mean), with the lights on which the reference misclassifies more than twice that best plus 50
pixels (the 2×best+50 rule). Bad input: one line, exit status 2.
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
    """One line on stderr, named after the script that runs (this one or engine_table.py)."""
    print(os.path.basename(sys.argv[0]) + ": " + message, file=sys.stderr)
    sys.exit(2)


def read_lights(d):
    """The rows of DIR/lights.csv (possibly none); fails when it cannot be read."""
    try:
        with open(os.path.join(d, "lights.csv"), newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        fail(f"{d}: cannot read lights.csv ({e.strerror})")


def read_rows(d, reference, needed=("_misclassified_mean",)):
    """The rows of DIR/lights.csv; fails unless the reference has every `needed` column."""
    rows = read_lights(d)
    if not rows or any(reference + n not in rows[0] for n in needed):
        fail(f"{d}/lights.csv: no lights with {reference}'s phase-averaged counts "
             f"(run the sweep with --method {reference} --phases K)")
    return rows


def paired(ours, ref):
    dm, ci = mean_ci([a - b for a, b in zip(ours, ref)])
    refm = sum(ref) / len(ref)
    return f"{100 * dm / refm:+.1f} ± {100 * ci / refm:.1f}%"


def main(reference, against, dirs):
    for d in dirs:
        rows = read_rows(d, reference)
        methods = [k[: -len("_misclassified_mean")] for k in rows[0]
                   if k.endswith("_misclassified_mean")]
        mean = {m: [float(r[m + "_misclassified_mean"]) for r in rows] for m in methods}
        base = [b for b in BASELINES if b in mean]
        cells = [f"{sum(mean[m]) / len(rows):.0f}" for m in methods]
        out = [os.path.basename(os.path.normpath(d)), str(len(rows))] + cells
        ours = mean[reference]
        for m in against or []:
            if m not in mean:
                fail(f"--against {m}: {d}/lights.csv has no such method")
        if against is None:  # the default: optimal-h where the sweep ran it
            against = [m for m in ["optimal-h"] if m in mean and m != reference]
        out += [paired(ours, mean[m]) for m in against]
        if base:  # the per-light best single-map baseline and the 2×best+50 rule against it
            best = [min(mean[b][i] for b in base) for i in range(len(rows))]
            out.append(paired(ours, best))
            out.append(str(sum(1 for a, b in zip(ours, best) if a > 2 * b + 50)))
        if d == dirs[0]:
            header = "".join(f" | {reference} − {m}" for m in against)
            if base:
                header += (f" | {reference} − best baseline (per light)"
                           " | lights > 2×best+50")
            print("| set | lights | " + " | ".join(methods) + header + " |")
            print("| --- | ---: |" + " ---: |" * (len(out) - 2))
        print("| " + " | ".join(out) + " |")


def parse_args(args, options, usage):
    """The DIR arguments and each option's values in order; `options` maps an option to what its
    value is ("method name"). Fails on an unknown option, a missing value or no DIR."""
    values, dirs, args = {o: [] for o in options}, [], list(args)
    while args:
        a = args.pop(0)
        if a in options:
            if not args:
                fail(f"{a}: needs a {options[a]}")
            values[a].append(args.pop(0))
        elif a.startswith("-"):
            fail(f"{a}: unknown option ({usage})")
        else:
            dirs.append(a)
    if not dirs:
        fail(f"no sweep directory given ({usage})")
    return values, dirs


if __name__ == "__main__":
    usage = "usage: fair_table.py [--reference METHOD] [--against METHOD ...] DIR ..."
    values, dirs = parse_args(sys.argv[1:], {"--against": "method name",
                                             "--reference": "method name"}, usage)
    reference = values["--reference"][-1] if values["--reference"] else "optimal"
    main(reference, values["--against"] or None, dirs)
