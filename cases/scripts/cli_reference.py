#!/usr/bin/env python3
"""Writes the command-line reference (cases/CLI.md) from `lexel`'s own help, so that it cannot
drift from the flags: `lexel --help`, then `lexel COMMAND --help` for every command in that order.

Usage: cli_reference.py LEXEL            (the reference on stdout)
       cli_reference.py LEXEL --check FILE  (exit 1, naming the command to run, when FILE differs)
Bad input: one line, exit status 2.
"""
import os
import re
import subprocess
import sys

HEADER = """# lexel's command line

Every command and flag as `lexel` itself prints them (`lexel --help`, `lexel COMMAND --help`).
This file is generated: `python3 cases/scripts/cli_reference.py build/cases/lexel >
cases/CLI.md` rewrites it, and `cli_reference_tests` fails when it is stale. What each command
computes, its outputs and the case format: cases/README.md.
"""


def fail(message, status=2):
    print("cli_reference.py: " + message, file=sys.stderr)
    sys.exit(status)


def help_of(lexel, args):
    try:
        done = subprocess.run([lexel, *args, "--help"], capture_output=True, text=True,
                              timeout=60)
    except OSError as e:
        fail(f"{lexel}: cannot run it ({e.strerror})")
    if done.returncode != 0:
        fail(f"{lexel} {' '.join(args)} --help: exit {done.returncode}")
    # The usage line names the binary as it was invoked: the reference names it `lexel`.
    return re.sub(r"^Usage: \S+", "Usage: lexel", done.stdout, flags=re.M).rstrip() + "\n"


def commands(top):
    """The subcommands `lexel --help` lists, in its order."""
    listing = top.split("Subcommands:", 1)
    if len(listing) != 2:
        fail("lexel --help lists no subcommands")
    return [m.group(1) for m in re.finditer(r"^  (\S+) ", listing[1], flags=re.M)]


def reference(lexel):
    top = help_of(lexel, [])
    parts = [HEADER, "## `lexel`\n", "```\n" + top + "```\n"]
    for command in commands(top):
        parts.append(f"## `lexel {command}`\n")
        parts.append("```\n" + help_of(lexel, [command]) + "```\n")
    return "\n".join(parts)


def main(args):
    if len(args) == 1:
        sys.stdout.write(reference(args[0]))
        return
    if len(args) == 3 and args[1] == "--check":
        try:
            with open(args[2], encoding="utf-8") as f:
                written = f.read()
        except OSError as e:
            fail(f"{args[2]}: cannot read it ({e.strerror})")
        if written != reference(args[0]):
            fail(f"{args[2]} is stale: run python3 cases/scripts/cli_reference.py "
                 f"build/cases/lexel > {args[2]}", 1)
        return
    fail("usage: cli_reference.py LEXEL [--check FILE]")


if __name__ == "__main__":
    sys.dont_write_bytecode = True
    main(sys.argv[1:])
