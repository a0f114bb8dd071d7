#!/usr/bin/env python3
"""Join the per-light columns of several `lexel sweep --out DIR` runs of the same lights into one
lights.csv, so that fair_table.py and oracle_table.py compare methods measured in different runs
(cases/history/2026-12-06-edge-exponent.md: `optimal-e1`, `sdsm-optimal-e1`, the p scan).

Usage: join_sweeps.py OUT SOURCE [SOURCE ...]
       SOURCE is DIR (every column of DIR/lights.csv), DIR:METHOD (METHOD's columns, those named
       METHOD_...) or DIR:METHOD=NAME (the same, renamed NAME_...).

The first SOURCE's lights, in its order, are the output's, with its per-light columns (kind,
position, receiver pixels); every other DIR must hold the same lights (by the `light` column) and
agree on those columns where it has them (a per-light column only a later DIR has is not
copied). OUT/lights.csv is written whole or not at all (OUT is created if
missing). A column given twice (the same METHOD from two runs without a new NAME) is an error.
Bad input: one line, exit status 2.
"""
import csv
import os
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_lights import fail  # noqa: E402
from sweep_lights import read_lights as read_csv  # noqa: E402

USAGE = "usage: join_sweeps.py OUT DIR[:METHOD[=NAME]] ..."


def parse_source(arg):
    """(DIR, METHOD or None, NAME or None) of one SOURCE argument."""
    d, sep, method = arg.rpartition(":")
    if not sep or "/" in method or not d:
        return arg, None, None
    method, _, name = method.partition("=")
    if not method or (_ and not name):
        fail(f"{arg}: wanted DIR, DIR:METHOD or DIR:METHOD=NAME")
    return d, method, name or method


def read_lights(d):
    rows = read_csv(d)
    if not rows or "light" not in rows[0]:
        fail(f"{d}/lights.csv: no lights (wanted a `light` column)")
    return rows


def methods_of(rows):
    """The methods of a lights.csv: the prefixes of its misclassified-pixel columns."""
    out = set()
    for k in rows[0]:
        for suffix in ("_misclassified_mean", "_misclassified"):
            if k.endswith(suffix):
                out.add(k[: -len(suffix)])
    return out


def is_light_column(key, methods):
    """A column of the light itself (kind, position, receiver pixels): no method's."""
    return not any(key.startswith(m + "_") for m in methods)


def columns(rows, method, name, d):
    """The (source column, output column) pairs SOURCE contributes."""
    keys = list(rows[0].keys())
    if method is None:
        methods = methods_of(rows)
        return [(k, k) for k in keys if not is_light_column(k, methods)]
    prefix = method + "_"
    picked = [(k, name + "_" + k[len(prefix):]) for k in keys if k.startswith(prefix)]
    if not picked:
        fail(f"{d}/lights.csv: no columns of {method}")
    return picked


def main(out, sources):
    base_rows = None
    header, by_light = ["light"], {}
    order = []
    for arg in sources:
        d, method, name = parse_source(arg)
        rows = read_lights(d)
        methods = methods_of(rows)
        lights = [r["light"] for r in rows]
        if len(set(lights)) != len(lights):
            fail(f"{d}/lights.csv: a light appears twice")
        if base_rows is None:
            base_rows, order = rows, lights
            by_light = {r["light"]: {"light": r["light"]} for r in rows}
            for k in rows[0]:
                if is_light_column(k, methods) and k != "light":
                    header.append(k)
                    for r in rows:
                        by_light[r["light"]][k] = r[k]
        elif sorted(lights) != sorted(order):
            fail(f"{d}/lights.csv: its lights differ from {parse_source(sources[0])[0]}'s")
        for r in rows:
            for k in rows[0]:
                if is_light_column(k, methods) and k in by_light[r["light"]] and \
                        by_light[r["light"]][k] != r[k]:
                    fail(f"{d}/lights.csv: light {r['light']}'s {k} differs from "
                         f"{parse_source(sources[0])[0]}'s (not the same lights)")
        for src, dst in columns(rows, method, name, d):
            if dst in header:
                fail(f"{arg}: column {dst} given twice (rename it: DIR:METHOD=NAME)")
            header.append(dst)
            for r in rows:
                by_light[r["light"]][dst] = r[src]
    try:
        os.makedirs(out, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=out, prefix=".lights.csv.")
    except OSError as e:
        fail(f"{out}: cannot write lights.csv ({e.strerror})")
    try:
        with os.fdopen(fd, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=header)
            w.writeheader()
            for light in order:
                w.writerow(by_light[light])
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # as open() would create it (mkstemp makes it 0600)
        os.replace(tmp, os.path.join(out, "lights.csv"))
    except OSError as e:
        os.unlink(tmp)
        fail(f"{out}: cannot write lights.csv ({e.strerror})")
    print(f"join_sweeps.py: {len(order)} lights, {len(header) - 1} columns to "
          f"{os.path.join(out, 'lights.csv')}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if any(a.startswith("-") for a in args):
        fail(f"{next(a for a in args if a.startswith('-'))}: unknown option ({USAGE})")
    if len(args) < 2:
        fail(f"wanted OUT and at least one sweep directory ({USAGE})")
    main(args[0], args[1:])
