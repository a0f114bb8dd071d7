#!/usr/bin/env python3
"""Summarize phase-averaged `lexel sweep --out DIR` runs with `optimal-oracle`: the share of one
method's gap to the bound that another closes (RESULTS.md, "The bound").

Usage: oracle_table.py [--reference METHOD] [--from METHOD] [--bound METHOD]
                       [--exclude PATTERN:LIGHT ...] [--resamples B] DIR [DIR ...]
       (each DIR a sweep's --out directory, holding lights.csv)

Per DIR (a set of lights), one Markdown row: each method's mean phase-averaged misclassified
pixels; how far the reference (default `optimal`) and the method it is compared with (--from,
default `optimal-h`) lie above the bound (--bound, default `optimal-oracle`), as a % of the
bound's mean; and "closed", the share of --from's gap to the bound that the reference removes,
(from − reference) / (from − bound) over the set's sums, with its 95% bootstrap percentile
interval (B resamples of the set's lights with replacement, default 2000, the share recomputed
from each resample's sums; a fixed seed, so a run repeats its intervals). Then the average of
the sets' shares with its interval (the average over the sets of each resample's shares) and the
share pooled over every light. --exclude drops a light from the DIRs whose name (the last path
component) matches PATTERN (shell-style: '*directional:8' drops light 8 of every directional
set). A share whose gap is 0 is undefined: printed as "—" and left out of the average. Where the
sweep wrote the phase means' standard errors, a set whose gap (Σ from − Σ bound) lies within
1.96 standard errors of it (the phase noise of the two methods' means) is named with its z, and
the average over the other sets is printed beside: such a set's share says nothing (on the
shipped sweeps, a light whose count swings by thousands with the phase decides it). Where the
sweep raised noisy means (`--max-phases`, `<method>_phases` columns), a last line gives the
phases per mean (least, most, average) and how many means are still unsettled: a standard error
above 2% of the mean and above a pixel (`PhaseMeanSettled`). Bad input: one line, exit status 2.
"""
import fnmatch
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_lights import (fail, normal95, optimal_method, oracle_method, parse_args,  # noqa: E402
                          read_rows)

MEAN = "_misclassified_mean"
SE = "_misclassified_se"
PHASES = "_phases"
RESIDUAL, FLOOR = 0.02, 1.0  # PhaseMeanSettled (spatial/harness/sub_texel_phase.h)
SEED = 1  # any fixed seed: the same DIRs give the same intervals on every run


def closed(triples):
    """(from − reference) / (from − bound) over the sums of (reference, from, bound) triples;
    None where the gap is 0."""
    ref = sum(t[0] for t in triples)
    frm = sum(t[1] for t in triples)
    bound = sum(t[2] for t in triples)
    return (frm - ref) / (frm - bound) if frm != bound else None


def percent(x):
    if x is None:
        return "—"
    text = f"{100 * x:.0f}"
    return "0" if text == "-0" else text.replace("-", "−")


def interval(values):
    """The 95% percentile interval of the defined values, or None."""
    v = sorted(x for x in values if x is not None)
    if not v:
        return None
    return v[int(0.025 * len(v))], v[int(0.975 * len(v))]


def read_set(d, names, excluded):
    rows = read_rows(d, names[0])
    for m in names[1:]:
        if m + MEAN not in rows[0]:
            fail(f"{d}/lights.csv: no phase-averaged counts of {m} (run the sweep with "
                 f"--method {m} --phases K)")
    name = os.path.basename(os.path.normpath(d))
    drop = {light for pattern, light in excluded if fnmatch.fnmatchcase(name, pattern)}
    rows = [r for r in rows if r["light"] not in drop]
    if not rows:
        fail(f"{d}/lights.csv: --exclude leaves no light")
    methods = [k[: -len(MEAN)] for k in rows[0] if k.endswith(MEAN)]
    mean = {m: [float(r[m + MEAN]) for r in rows] for m in methods}
    # The gap's noise: the phase means' standard errors, where the sweep wrote them.
    se = {m: [standard_error(r[m + SE]) for r in rows] for m in names[1:] if m + SE in rows[0]}
    se = {m: v for m, v in se.items() if None not in v}  # an empty cell: no z for the set
    # Adaptive phases: per method and light (phases, mean, standard error).
    phases = [(int(r[m + PHASES]), mean[m][i], standard_error(r[m + SE]))
              for m in methods if m + PHASES in rows[0] and m + SE in rows[0]
              for i, r in enumerate(rows)]
    return name, methods, mean, se, phases


def standard_error(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def gap_z(mean, se, frm, bound):
    """(Σ from − Σ bound) over its standard error (independent phase means), or None."""
    if frm not in se or bound not in se:
        return None
    noise = math.sqrt(sum(x * x for x in se[frm]) + sum(x * x for x in se[bound]))
    gap = sum(mean[frm]) - sum(mean[bound])
    return gap / noise if noise > 0 else None


def average_line(shares, boots, chosen, resamples):
    """The average of the chosen sets' shares and its percentile interval, as text."""
    average = sum(shares[i] for i in chosen) / len(chosen)
    per_resample = []
    for k in range(resamples):
        v = [boots[i][k] for i in chosen]
        per_resample.append(None if None in v else sum(v) / len(v))
    ci = interval(per_resample)
    return f"{percent(average)}%" + (f" ({percent(ci[0])} to {percent(ci[1])}%)" if ci else "")


def main(names, excluded, resamples, dirs):
    reference, frm, bound = names
    rng = random.Random(SEED)
    shares, boots, pooled, lines, zs = [], [], [], [], []
    sets = [read_set(d, names, excluded) for d in dirs]  # every input checked before any output
    for name, methods, mean, se, _ in sets:
        zs.append(gap_z(mean, se, frm, bound))
        triples = list(zip(mean[reference], mean[frm], mean[bound]))
        share = closed(triples)
        boot = [closed([rng.choice(triples) for _ in triples]) for _ in range(resamples)]
        ci = interval(boot)
        shares.append(share)
        boots.append(boot)
        pooled += triples
        n = len(triples)
        b = sum(mean[bound]) / n
        above = [f"{100 * (sum(mean[m]) / n / b - 1):+.1f}%".replace("-", "−") if b > 0 else "—"
                 for m in (reference, frm)]
        share_cell = percent(share) + ("%" if share is not None else "")
        if ci:
            share_cell += f" ({percent(ci[0])} to {percent(ci[1])})"
        if not lines:
            lines.append("| set | lights | " + " | ".join(methods) + f" | {reference} above "
                         f"{bound} | {frm} above {bound} | closed |")
            lines.append("| --- | ---: |" + " ---: |" * (len(methods) + 3))
        cells = [f"{sum(mean[m]) / n:.0f}" for m in methods]
        lines.append(f"| {name} | {n} | " + " | ".join(cells + above + [share_cell]) + " |")
    print("\n".join(lines))
    defined = [i for i, s in enumerate(shares) if s is not None]
    if defined:
        text = average_line(shares, boots, defined, resamples)
        print(f"\nAverage over the {plural(len(defined), 'set')}: {reference} closes {text} of "
              f"{frm}'s gap to {bound}; pooled over the {len(pooled)} lights: "
              f"{percent(closed(pooled))}%.")
    # A set whose gap is within its phase noise has a share that says nothing (its interval
    # spans hundreds of %): named, and the average over the others given beside.
    noisy = [i for i in defined if zs[i] is not None and abs(zs[i]) < normal95()]
    if noisy:
        names_text = ", ".join(f"{sets[i][0]} (z {zs[i]:.1f})".replace("-", "−") for i in noisy)
        rest = [i for i in defined if i not in noisy]
        line = (f"Gap to {bound} within its phase noise (|gap| < 1.96 standard errors): "
                f"{names_text}.")
        if rest:
            line += (f" Average over the other {plural(len(rest), 'set')}: "
                     f"{average_line(shares, boots, rest, resamples)}.")
        print(line)
    cells = [c for s in sets for c in s[4]]
    if cells:
        counts = [c[0] for c in cells]
        unsettled = sum(1 for _, m, e in cells if e is not None and e > max(RESIDUAL * m, FLOOR))
        print(f"Phases per mean: {min(counts)} to {max(counts)}, "
              f"{sum(counts) / len(counts):.1f} on average; {unsettled} of {len(cells)} means "
              f"with a standard error above 2% of the mean and above a pixel.")


def plural(n, word):
    return f"{n} {word}" + ("s" if n != 1 else "")


def parse_exclusions(values):
    excluded = []
    for v in values:
        pattern, sep, light = v.rpartition(":")
        if not sep or not pattern or not light.isdigit():
            fail(f"--exclude {v}: wanted PATTERN:LIGHT, e.g. '*directional:8'")
        excluded.append((pattern, light))
    return excluded


if __name__ == "__main__":
    usage = ("usage: oracle_table.py [--reference METHOD] [--from METHOD] [--bound METHOD] "
             "[--exclude PATTERN:LIGHT ...] [--resamples B] DIR ...")
    values, dirs = parse_args(sys.argv[1:], {"--reference": "method name",
                                             "--from": "method name",
                                             "--bound": "method name",
                                             "--exclude": "PATTERN:LIGHT",
                                             "--resamples": "count"}, usage)
    names = tuple(values[o][-1] if values[o] else default for o, default in
                  (("--reference", optimal_method()), ("--from", "optimal-h"),
                   ("--bound", oracle_method())))
    if len(set(names)) < 3:
        fail(f"--reference, --from and --bound: wanted three methods, got {', '.join(names)}")
    resamples = values["--resamples"][-1] if values["--resamples"] else "2000"
    if not resamples.isdigit() or not 1 <= int(resamples) <= 1000000:
        fail(f"--resamples {resamples}: wanted a whole number from 1 to 1000000")
    main(names, parse_exclusions(values["--exclude"]), int(resamples), dirs)
