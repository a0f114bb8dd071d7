#!/usr/bin/env python3
"""Summarize phase-averaged `lexel sweep --out DIR` runs of several methods against one (RESULTS.md,
"What engines ship"; cases/scripts/engine_table.sh runs the sweeps).

Usage: engine_table.py [--reference METHOD] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv, from a lexel sweep --phases K:
       one written before the sweep kept <method>_storage_factor_p99 is refused)

Prints two Markdown tables. Pooled over every light of every DIR, one row per method: its mean
phase-averaged misclassified pixels; the paired difference against the reference (default
`optimal`; per light this − reference, mean ± 95% half-width over the lights, Student t, as a % of
the reference's mean); the % of lights on which it has fewer (won) and more (lost) misclassified
pixels than the reference beyond the noise of the two phase means (|difference| > 1.96 ×
√(se² + se_ref²), as `lexel sweep` counts wins); the median over the lights of the effective
storage factor from each light's worst pixel and from its 99th-percentile pixel; the mean
time per light in ms and as a multiple of the reference's in the same sweeps; where every sweep
ran with --shimmer-poses, its shimmer along the case's camera path (the mean over the lights of
lights.csv's <method>_shimmer, % of stable pixels per step) and its paired difference against the
reference's (as a % of the reference's mean shimmer). Then the
residual noise (the median over lights and methods of a light's standard error over its mean) and
one row per DIR: each method's paired difference against the reference. Bad input: one line, exit
status 2.
"""
import math
import os
import statistics
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_lights import (beyond_noise, fail, optimal_method, paired_ci, parse_args,  # noqa: E402
                          read_rows)

MEAN, SE, MS = "_misclassified_mean", "_misclassified_se", "_ms"
STORAGE, STORAGE99 = "_storage_factor", "_storage_factor_p99"
SHIMMER = "_shimmer"  # only in sweeps run with --shimmer-poses


def read_set(d, reference):
    rows = read_rows(d, reference, needed=(MEAN, SE))
    methods = [k[: -len(MEAN)] for k in rows[0] if k.endswith(MEAN)]

    def column(m, suffix):
        # Only a storage factor may be empty (no pixel measured); it is left out of the median.
        try:
            return [math.nan if r[m + suffix] == "" and suffix in (STORAGE, STORAGE99)
                    else float(r[m + suffix])
                    for r in rows]
        except (KeyError, ValueError):
            fail(f"{d}/lights.csv: {m}{suffix} is missing or not a number")

    def suffixes(m):
        return (MEAN, SE, STORAGE, STORAGE99, MS) + ((SHIMMER,) if m + SHIMMER in rows[0] else ())

    return {m: {s: column(m, s) for s in suffixes(m)} for m in methods}


def paired_percent(ours, ref):
    dm, ci = paired_ci(ours, ref)
    refm = sum(ref) / len(ref)
    if refm == 0:
        return "–"
    return f"{100 * dm / refm:+.1f} ± {100 * ci / refm:.1f}%"


def wins(cells, ref):
    won = lost = 0
    for a, sa, b, sb in zip(cells[MEAN], cells[SE], ref[MEAN], ref[SE]):
        if beyond_noise(a, sa, b, sb):
            won += a < b
            lost += a > b
    n = len(cells[MEAN])
    return f"{100 * won / n:.0f}% / {100 * lost / n:.0f}%"


def median(values):
    finite = [v for v in values if math.isfinite(v)]
    return f"{statistics.median(finite):.3g}" if finite else "–"


def pooled(sets, m, suffix):
    return [v for s in sets for v in s[m][suffix]]


def main(reference, dirs):
    sets = [read_set(d, reference) for d in dirs]
    methods = [m for m in sets[0] if all(m in s for s in sets)]
    with_shimmer = all(SHIMMER in s[m] for s in sets for m in methods)
    lights = sum(len(s[reference][MEAN]) for s in sets)
    head = ["method", "mean misclassified", f"vs {reference}",
            f"lights won / lost vs {reference}", "median storage factor (max, p99)",
            f"ms per light (× {reference})"]
    if with_shimmer:
        head.append("shimmer (%)")
    print(f"Pooled over {len(dirs)} {'set' if len(dirs) == 1 else 'sets'}, {lights} lights:\n")
    print("| " + " | ".join(head) + " |")
    print("| --- |" + " ---: |" * (len(head) - 1))
    ref = {s: pooled(sets, reference, s) for s in (MEAN, SE)}
    ref_ms = sum(pooled(sets, reference, MS)) or math.nan
    for m in methods:
        cells = {s: pooled(sets, m, s) for s in (MEAN, SE, STORAGE, STORAGE99, MS)}
        row = [m, f"{sum(cells[MEAN]) / lights:.0f}",
               "–" if m == reference else paired_percent(cells[MEAN], ref[MEAN]),
               "–" if m == reference else wins(cells, ref),
               f"{median(cells[STORAGE])}, {median(cells[STORAGE99])}",
               f"{sum(cells[MS]) / lights:.2f} ({sum(cells[MS]) / ref_ms:.2g}×)"]
        if with_shimmer:
            shimmer = pooled(sets, m, SHIMMER)
            row.append(f"{sum(shimmer) / lights:.3f}" + (
                "" if m == reference else
                f" ({paired_percent(shimmer, pooled(sets, reference, SHIMMER))})"))
        print("| " + " | ".join(row) + " |")
    noise = [se / mean for s in sets for m in methods
             for mean, se in zip(s[m][MEAN], s[m][SE]) if mean > 0]
    if noise:
        print(f"\nResidual noise (each light's standard error over its mean, median over the "
              f"lights and methods with errors): {100 * statistics.median(noise):.1f}%")
    others = [m for m in methods if m != reference]
    print(f"\nPer set, each method against {reference}:\n")
    print(f"| set | lights | {reference} | " + " | ".join(others) + " |")
    print("| --- | ---: | ---: |" + " ---: |" * len(others))
    for d, s in zip(dirs, sets):
        ref_mean = s[reference][MEAN]
        row = [os.path.basename(os.path.normpath(d)), str(len(ref_mean)),
               f"{sum(ref_mean) / len(ref_mean):.0f}"]
        row += [paired_percent(s[m][MEAN], ref_mean) for m in others]
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    usage = "usage: engine_table.py [--reference METHOD] DIR ..."
    values, dirs = parse_args(sys.argv[1:], {"--reference": "method name"}, usage)
    reference = values["--reference"][-1] if values["--reference"] else optimal_method()
    main(reference, dirs)
