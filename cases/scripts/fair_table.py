#!/usr/bin/env python3
"""Summarize phase-averaged `lexel sweep --out DIR` runs of the fair comparison (RESULTS.md).

Usage: fair_table.py [--reference METHOD] [--against METHOD ...] [--baseline METHOD ...]
                     DIR [DIR ...]   (each DIR a sweep's --out directory, holding lights.csv)

Per directory, one Markdown row: each method's mean phase-averaged misclassified pixels, the
paired difference of the reference method (default: `optimal`) against each --against method
(default: `optimal-h`) and, where the sweep ran any of the single-map baselines, against their
per-light best (mean ± 95% half-width over the lights, Student t, as a % of the other's mean),
with the lights on which the reference misclassifies more than twice that best plus 50 pixels
(the 2×best+50 rule). The baselines are the registry's fair single-map ones (`lexel methods`:
family baseline, fair table), or those named by --baseline. Bad input: one line, exit status 2.
"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_lights import (fail, optimal_method, paired_ci, parse_args, read_rows,  # noqa: E402
                          single_map_baselines)


def paired(ours, ref):
    dm, ci = paired_ci(ours, ref)
    refm = sum(ref) / len(ref)
    return f"{100 * dm / refm:+.1f} ± {100 * ci / refm:.1f}%"


def main(reference, against, baselines, dirs):
    """baselines: the names given with --baseline (each must be in every sweep), or None for
    the registry's."""
    registry = single_map_baselines() if baselines is None else None  # asked once
    for d in dirs:
        rows = read_rows(d, reference)
        methods = [k[: -len("_misclassified_mean")] for k in rows[0]
                   if k.endswith("_misclassified_mean")]
        mean = {m: [float(r[m + "_misclassified_mean"]) for r in rows] for m in methods}
        for b in baselines or []:
            if b not in mean:
                fail(f"--baseline {b}: {d}/lights.csv has no such method")
        base = [b for b in baselines or registry if b in mean]
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


if __name__ == "__main__":
    usage = ("usage: fair_table.py [--reference METHOD] [--against METHOD ...] "
             "[--baseline METHOD ...] DIR ...")
    values, dirs = parse_args(sys.argv[1:], {"--against": "method name",
                                             "--reference": "method name",
                                             "--baseline": "method name"}, usage)
    reference = values["--reference"][-1] if values["--reference"] else optimal_method()
    main(reference, values["--against"] or None, values["--baseline"] or None, dirs)
