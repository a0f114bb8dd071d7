"""What the table scripts share: reading a sweep's lights.csv, their command lines, one-line
failures, and lexel's own statistics.

The 95% intervals (Student t) and the noise rule (two phase means differ beyond the noise when
|a - b| > 1.96 * sqrt(se_a^2 + se_b^2)) are not written here: they are lexel's (solvers/
statistics.h, the same code `lexel sweep` counts wins with), reached through lexel's Python
module: `import lexel` when it is on PYTHONPATH, else the build tree's build/spatial/python.
"""
import csv
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def fail(message):
    """One line on stderr, named after the script that runs, and exit status 2."""
    print(os.path.basename(sys.argv[0]) + ": " + message, file=sys.stderr)
    sys.exit(2)


def lexel_module():
    """lexel's Python module: from PYTHONPATH, else from the build tree (./bootstrap.sh builds it
    in build/spatial/python); fails in one line when neither has it."""
    try:
        import lexel
        return lexel
    except ImportError:
        pass
    sys.path.insert(0, os.path.join(ROOT, "build", "spatial", "python"))
    try:
        import lexel
        return lexel
    except ImportError as e:
        fail(f"cannot import lexel's Python module ({e}): build it (./bootstrap.sh) or put its "
             f"directory on PYTHONPATH")


def mean_ci(values):
    """(mean, 95% half-width) over the values, Student t (nan for fewer than two)."""
    return lexel_module().mean_interval95(values)


def paired_ci(ours, theirs):
    """(mean, 95% half-width) of ours[i] - theirs[i]."""
    return lexel_module().paired_difference95(ours, theirs)


def beyond_noise(mean_a, se_a, mean_b, se_b):
    """Whether two phase means differ beyond their noise, as `lexel sweep` counts wins."""
    return lexel_module().differ_beyond_noise(mean_a, se_a, mean_b, se_b)


def normal95():
    """The two-sided 95% normal quantile lexel's reports use (lexel.NORMAL95, 1.96)."""
    return lexel_module().NORMAL95


def single_map_baselines():
    """The registry's single-map baselines of the fair comparison (family `baseline` with the
    fair-table trait; `lexel methods` lists them), in the registry's order."""
    return [m["name"] for m in lexel_module().methods()
            if m["family"] == "baseline" and m["traits"]["fair_table"]]


def optimal_method():
    """The fair comparison's reference method, as the registry names it (lexel.OPTIMAL_METHOD)."""
    return lexel_module().OPTIMAL_METHOD


def oracle_method():
    """The measured bound's method, as the registry names it (lexel.ORACLE_METHOD)."""
    return lexel_module().ORACLE_METHOD


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
