#!/usr/bin/env python3
"""Validate case files against lexel's case format, cases/case.schema.json (JSON Schema 2020-12).

Usage: check_case_schema.py CASE.json [CASE.json ...]

The schema holds each object's keys, types and static ranges (an editor with JSON Schema support
completes and checks a case as it is written); the loader checks the rest when lexel reads the
case. Prints one line per invalid file, FILE: /json/pointer: why, and exits 1 when any is
invalid, 0 when all are valid. Bad input (a file that cannot be read or is not JSON, NaN or
Infinity included; no jsonschema module): one line, exit status 2. Needs Debian's
python3-jsonschema (./bootstrap.sh installs it).
"""
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCHEMA = os.path.join(ROOT, "cases", "case.schema.json")
MAX_BYTES = 64 << 20  # a case file is small; this bounds what a mistaken argument reads


def fail(message):
    print("check_case_schema.py: " + message, file=sys.stderr)
    sys.exit(2)


def not_json(constant):
    raise ValueError(f"{constant} is not a JSON number")


def load(path):
    """The JSON document of `path`, read as a regular file of at most MAX_BYTES."""
    try:
        if not os.path.isfile(path) or os.path.islink(path):
            fail(f"{path}: not a regular file")
        with open(path, "rb") as f:
            data = f.read(MAX_BYTES + 1)
    except OSError as e:
        fail(f"{path}: cannot be read ({e.strerror})")
    if len(data) > MAX_BYTES:
        fail(f"{path}: larger than {MAX_BYTES} bytes")
    try:
        return json.loads(data.decode("utf-8-sig"), parse_constant=not_json)
    except (UnicodeDecodeError, ValueError) as e:
        fail(f"{path}: not JSON ({e})")


def pointer(path):
    return "/" + "/".join(str(p) for p in path)


def main(paths):
    try:
        import jsonschema
    except ImportError:
        fail("needs the jsonschema module (Debian 12: apt-get install python3-jsonschema)")
    validator = jsonschema.Draft202012Validator(load(SCHEMA))
    invalid = 0
    for path in paths:
        error = jsonschema.exceptions.best_match(validator.iter_errors(load(path)))
        if error is not None:
            invalid += 1
            print(f"{path}: {pointer(error.absolute_path)}: {error.message}")
    return 1 if invalid else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        fail("usage: check_case_schema.py CASE.json [CASE.json ...]")
    sys.exit(main(sys.argv[1:]))
