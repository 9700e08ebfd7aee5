#!/usr/bin/env python3
"""Golden cases in the style of LinuxCNC's tests/interp: every folder of
tests/programs/ is one case

    <case>/program.k528        the program
    <case>/args                options of `k528 run` (shell words; '#' starts
                               a comment), e.g. --profile grinder-205; optional
    <case>/expected-run.json   what `k528 run --json [args] program.k528` prints
    <case>/expected-path.json  what `k528 path --json [args-path] program.k528`
                               prints; optional: checked when the file is there
    <case>/args-path           options of `k528 path` (default: none); optional

The run is deterministic (fixed tick, no wall clock), so the whole document
is compared, every field, after parsing (key order kept, so a reordered key
is a change too; only the whitespace of the stored file does not matter).
K528_UPDATE_GOLDEN=1 writes the expected files anew from what k528 prints
(expected-path.json only where it already exists).

usage: golden.py K528 CASES_DIR [CASE...]
"""
import difflib
import json
import os
import shlex
import subprocess
import sys


def read_args(path):
    if not os.path.exists(path):
        return []
    words = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            words += shlex.split(line, comments=True)
    return words


def parse(text):
    # Pairs, not dicts: key order is part of the output.
    return json.loads(text, object_pairs_hook=lambda pairs: pairs)


def pretty(text):
    return json.dumps(json.loads(text), ensure_ascii=False, indent=1) + "\n"


def run_case(k528, case_dir, command, args, expected_file, update):
    # Relative to the case's folder: nothing of the host's paths in the output.
    argv = [k528, command, "--json"] + args + ["program.k528"]
    proc = subprocess.run(argv, capture_output=True, timeout=600, cwd=case_dir)
    out = proc.stdout.decode("utf-8", errors="strict")
    try:
        got = parse(out)
    except ValueError as e:
        return [f"{' '.join(argv)} printed no JSON ({e}); exit {proc.returncode}; "
                f"stderr: {proc.stderr.decode(errors='replace').strip()}"]
    if update:
        with open(expected_file, "w", encoding="utf-8") as f:
            f.write(pretty(out))
        return []
    if not os.path.exists(expected_file):
        return [f"{expected_file} is missing (K528_UPDATE_GOLDEN=1 writes it)"]
    with open(expected_file, encoding="utf-8") as f:
        expected_text = f.read()
    if parse(expected_text) == got:
        return []
    diff = difflib.unified_diff(pretty(expected_text).splitlines(True), pretty(out).splitlines(True),
                                fromfile=expected_file, tofile=" ".join(argv[1:]))
    return ["".join(diff)]


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    k528, cases_dir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    update = os.environ.get("K528_UPDATE_GOLDEN") == "1"
    names = sys.argv[3:] or sorted(d for d in os.listdir(cases_dir)
                                   if os.path.isfile(os.path.join(cases_dir, d, "program.k528")))
    if not names:
        print(f"no cases in {cases_dir}", file=sys.stderr)
        return 2
    failed = 0
    for name in names:
        case_dir = os.path.join(cases_dir, name)
        problems = run_case(k528, case_dir, "run", read_args(os.path.join(case_dir, "args")),
                            os.path.join(case_dir, "expected-run.json"), update)
        path_file = os.path.join(case_dir, "expected-path.json")
        if os.path.exists(path_file):
            problems += run_case(k528, case_dir, "path", read_args(os.path.join(case_dir, "args-path")),
                                 path_file, update)
        status = "FAIL" if problems else ("updated" if update else "ok")
        print(f"{status:8} {name}")
        for p in problems:
            print(p.rstrip("\n"))
        failed += bool(problems)
    print(f"{len(names) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
