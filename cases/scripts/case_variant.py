#!/usr/bin/env python3
"""Write a copy of a 3D case file with its readback, shadow map, sample budget or edge exponent
changed.

Usage: case_variant.py CASE.json OUT.json [--readback W H] [--shadow-map W H]
                       [--max-samples N|all] [--edge-exponent P] [--name NAME]

lexel takes the readback, the map size, the optimizer's sample budget (`optimizer.max_samples`)
and the edge energy's exponent (`optimizer.edge_exponent`, in (0, 4]) from the case file, so a
study of any of them (RESULTS.md,
"What the edge energy misses") runs on a variant of a shipped case. The copy is the case with
those fields replaced, its name suffixed (default: "<name>-readback<W>x<H>"), and every relative
`geometry[].mesh` path made absolute, so the copy may live anywhere. The sweep's record tells the
two apart by the case file's hash. `--max-samples all` removes the budget (Algorithm 1 on every
sample): with `--readback 180 180` it gives a shipped case (720² readback, budget 512) the
report's own 180² set-up. Bad input: one line on stderr, exit status 2, no file written.
"""
import argparse
import json
import os
import sys


def fail(message):
    print("case_variant.py: " + message, file=sys.stderr)
    sys.exit(2)


def resolution(values, flag):
    w, h = values
    if not (1 <= w <= 16384 and 1 <= h <= 16384):
        fail(f"{flag}: width and height must be in [1, 16384], got {w} {h}")
    return {"width": w, "height": h}


def budget(text):
    """--max-samples: an integer in [1, 16384²], or "all" (no budget)."""
    if text == "all":
        return text
    try:
        n = int(text)
    except ValueError:
        fail(f"--max-samples: must be an integer in [1, 16384²] or 'all', got '{text}'")
    if not 1 <= n <= 16384 * 16384:
        fail(f"--max-samples: must be in [1, 16384²], got {n}")
    return n


def exponent(text):
    """--edge-exponent: a number in (0, 4]."""
    try:
        p = float(text)
    except ValueError:
        fail(f"--edge-exponent: must be a number in (0, 4], got '{text}'")
    if not 0 < p <= 4:
        fail(f"--edge-exponent: must be in (0, 4], got {text}")
    return p


class Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse's usage + message, as one line
        fail(message)


def main():
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("case")
    parser.add_argument("out")
    parser.add_argument("--readback", nargs=2, type=int, metavar=("W", "H"))
    parser.add_argument("--shadow-map", nargs=2, type=int, metavar=("W", "H"))
    parser.add_argument("--max-samples", type=budget, metavar="N|all")
    parser.add_argument("--edge-exponent", type=exponent, metavar="P")
    parser.add_argument("--name")
    args = parser.parse_args()
    if (not args.readback and not args.shadow_map and args.max_samples is None
            and args.edge_exponent is None):
        fail("give --readback W H, --shadow-map W H, --max-samples N or --edge-exponent P "
             "(nothing to change)")
    if os.path.abspath(args.out) == os.path.abspath(args.case):
        fail("OUT.json: must not be the case file itself")
    try:
        with open(args.case, encoding="utf-8") as f:
            case = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{args.case}: cannot read a JSON case ({e})")
    if not isinstance(case, dict) or "camera" not in case:
        fail(f"{args.case}: not a 3D case file (no camera)")
    suffix = ""
    if args.readback:
        case["readback"] = resolution(args.readback, "--readback")
        suffix += "-readback{}x{}".format(*args.readback)
    if args.shadow_map:
        case["shadow_map"] = resolution(args.shadow_map, "--shadow-map")
        suffix += "-map{}x{}".format(*args.shadow_map)
    if args.max_samples is not None or args.edge_exponent is not None:
        optimizer = case.get("optimizer", {})
        if not isinstance(optimizer, dict):
            fail(f"{args.case}: /optimizer must be an object")
        if args.max_samples == "all":
            optimizer.pop("max_samples", None)
        elif args.max_samples is not None:
            optimizer["max_samples"] = args.max_samples
        if args.edge_exponent is not None:
            optimizer["edge_exponent"] = args.edge_exponent
        if optimizer:
            case["optimizer"] = optimizer
        else:
            case.pop("optimizer", None)
        if args.max_samples is not None:
            suffix += f"-samples{args.max_samples}"
        if args.edge_exponent is not None:
            suffix += f"-exponent{args.edge_exponent:g}"
    case["name"] = args.name or str(case.get("name", "case")) + suffix
    base = os.path.dirname(os.path.abspath(args.case))
    for item in case.get("geometry", []):
        if isinstance(item, dict) and isinstance(item.get("mesh"), str):
            if not os.path.isabs(item["mesh"]):
                item["mesh"] = os.path.normpath(os.path.join(base, item["mesh"]))
    text = json.dumps(case, indent=1) + "\n"
    try:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text)
    except OSError as e:
        fail(f"{args.out}: cannot write ({e})")


if __name__ == "__main__":
    main()
