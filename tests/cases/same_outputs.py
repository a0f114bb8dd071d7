#!/usr/bin/env python3
"""Checks that two lexel builds write the same results on the shipped cases, times aside.

A refactoring must not change a number. This runs the same commands with both
binaries into WORKDIR/old and WORKDIR/new and compares every file both wrote: PNGs and other
binary files byte for byte; CSV, JSON and Markdown with every time masked (a CSV column, JSON key
or Markdown table column named ms, seconds or a time). Files and JSON keys only the new build
writes are listed, not failed (a change may add outputs); terminal text and index.html, which
repeat those tables around the output directory's name, are not compared.

Usage: tests/cases/same_outputs.py OLD_LEXEL NEW_LEXEL WORKDIR   (exit 1 on a difference)
"""
import csv
import io
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"
TIME_KEY = re.compile(r"(^|_)(ms|seconds|time|elapsed)(_|$)", re.I)

COMMANDS = [
    ["tables", "--out", "{out}/tables"],
    ["run", *sorted(str(p) for p in (CASES / "flatland").glob("*.json")), "--format", "csv",
     "--out", "{out}/run_flatland"],
    ["run", str(CASES / "spatial/walkthrough.json"), "--no-map-truth", "--format", "json",
     "--out", "{out}/run_walkthrough"],
    ["run", str(CASES / "spatial/courtyard.json"), "--no-map-truth", "--out", "{out}/run_courtyard"],
    ["sweep", str(CASES / "spatial/street.json"), "--lights", "8", "--out", "{out}/sweep_street"],
    ["sweep", str(CASES / "spatial/walkthrough.json"), "--lights", "6", "--method", "optimal",
     "--method", "sdsm", "--method", "focused-tight", "--cascades", "2",
     "--out", "{out}/sweep_walkthrough"],
    ["run", str(CASES / "spatial/walkthrough.json"), "--no-map-truth", "--phases", "2",
     "--method", "optimal", "--method", "vsm", "--method", "sdsm", "--format", "csv",
     "--out", "{out}/run_phased"],
    ["sweep", str(CASES / "spatial/courtyard.json"), "--lights", "4", "--phases", "2",
     "--method", "optimal", "--method", "vsm", "--method", "lispsm-tight", "--format", "json",
     "--out", "{out}/sweep_phased"],
    ["storage", "--out", "{out}/storage"],
    ["storage", "--case", str(CASES / "spatial/meshes.json"), "--out", "{out}/storage_case"],
]


def run_all(lexel, out):
    for command in COMMANDS:
        args = [a.format(out=out) for a in command]
        result = subprocess.run([lexel, *args], capture_output=True, text=True)
        (pathlib.Path(out) / (args[0] + "_" + args[-1].split("/")[-1] + ".stdout")).write_text(
            result.stdout)
        if result.returncode != 0:
            sys.exit(f"{lexel} {' '.join(args)}: exit {result.returncode}: {result.stderr}")


def mask_json(value):
    if isinstance(value, dict):
        return {k: ("<time>" if TIME_KEY.search(k) else mask_json(v)) for k, v in value.items()}
    if isinstance(value, list):
        return [mask_json(v) for v in value]
    return value


def mask_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return rows
    timed = [i for i, name in enumerate(rows[0]) if TIME_KEY.search(name)]
    return [[("<time>" if i in timed and r is not rows[0] else c) for i, c in enumerate(r)]
            for r in rows]


def mask_markdown(text):
    """Markdown tables with their time columns masked (a header cell naming ms or seconds)."""
    out, timed = [], []
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")] if line.startswith("|") else None
        if cells is None:
            timed = []
            out.append(line)
        elif not timed and not all(set(c) <= set("-: ") for c in cells):
            timed = [i for i, c in enumerate(cells) if TIME_KEY.search(c.replace(" ", "_"))] or [-1]
            out.append(line)
        else:
            out.append("|".join("<time>" if i in timed else c for i, c in enumerate(cells)))
    return out


def added_keys(old, new, path=""):
    """JSON keys the new document has and the old one lacks (dropped from `new`, listed)."""
    found = []
    if isinstance(old, dict) and isinstance(new, dict):
        for k in list(new):
            if k not in old:
                found.append(path + "/" + k)
                del new[k]
            else:
                found += added_keys(old[k], new[k], path + "/" + k)
    elif isinstance(old, list) and isinstance(new, list) and len(old) == len(new):
        for i, (o, n) in enumerate(zip(old, new)):
            found += added_keys(o, n, path + "/" + str(i))
    return found


ADDED = set()


def same(a, b):
    if a.suffix == ".json":
        old, new = json.loads(a.read_text()), json.loads(b.read_text())
        ADDED.update(re.sub(r"/\d+", "/*", k) for k in added_keys(old, new))
        return mask_json(old) == mask_json(new)
    if a.suffix == ".csv":
        return mask_csv(a.read_text()) == mask_csv(b.read_text())
    if a.suffix == ".md":
        return mask_markdown(a.read_text()) == mask_markdown(b.read_text())
    if a.suffix in (".stdout", ".html"):
        return True
    return a.read_bytes() == b.read_bytes()


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    old, new, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    for name, lexel in (("old", old), ("new", new)):
        (work / name).mkdir(parents=True, exist_ok=True)
        run_all(lexel, work / name)
    oldFiles = {p.relative_to(work / "old") for p in (work / "old").rglob("*") if p.is_file()}
    newFiles = {p.relative_to(work / "new") for p in (work / "new").rglob("*") if p.is_file()}
    differ = sorted(str(f) for f in oldFiles & newFiles
                    if not same(work / "old" / f, work / "new" / f))
    print(f"{len(oldFiles & newFiles)} files in both, {len(differ)} differ")
    for f in sorted(oldFiles - newFiles):
        print(f"only old: {f}")
    for f in sorted(newFiles - oldFiles):
        print(f"only new: {f}")
    for k in sorted(ADDED):
        print(f"JSON key only new: {k}")
    for f in differ:
        print(f"differs: {f}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
