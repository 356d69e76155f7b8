#!/usr/bin/env python3
"""Re-runs, with an empty shared folder, the test cases that read ../shared in the run before.

A clone without ../shared must pass `make test`: every case that reads the shared examples must then skip
its shared part and pass the rest. The test programs write each such case to shared_use.log (program, tab,
case name); this runs only those cases again with NOME_SHARED_DIR pointed at an empty folder and skips
allowed (CI unset), so the check costs seconds, not a second run of the suite.

usage: without_shared.py BUILD_DIR
"""
import collections
import os
import subprocess
import sys
import tempfile


def escaped(name):
    """A Catch test spec matching exactly this name: its special characters escaped."""
    return "".join("\\" + c if c in '\\,[]"~*' else c for c in name)


def listed(program, spec_file, env):
    out = subprocess.run([program, "-f", spec_file, "--list-test-names-only"], env=env,
                         capture_output=True, text=True, check=False).stdout
    return {line for line in out.splitlines() if line.strip()}


def main():
    build = sys.argv[1]
    use_log = os.path.join(build, "shared_use.log")
    skip_log = os.path.join(build, "skipped_without_shared.log")
    if not os.path.exists(use_log):
        # With the shared folder beside the checkout, some cases read it: a missing log means they no
        # longer say so, and this check would pass without checking anything.
        shared = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "examples")
        if os.path.isdir(shared):
            print(f"Without ../shared: no test case logged reading it ({use_log} is missing)")
            return 1
        print("Without ../shared: no test case read the shared folder in the last run")
        return 0
    cases = collections.defaultdict(set)
    with open(use_log, encoding="utf-8") as log:
        for line in log:
            program, _, name = line.rstrip("\n").partition("\t")
            if name:
                cases[program].add(name)
    if os.path.exists(skip_log):
        os.remove(skip_log)
    env = dict(os.environ)
    env.pop("CI", None)
    env.pop("NOME_SHARED_USE_LOG", None)
    env["NOME_SKIP_LOG"] = skip_log
    failed = False
    with tempfile.TemporaryDirectory(prefix="nome-no-shared-") as empty:
        env["NOME_SHARED_DIR"] = empty
        runs = []
        for program, names in sorted(cases.items()):
            spec_file = os.path.join(empty, os.path.basename(program) + ".specs")
            with open(spec_file, "w", encoding="utf-8") as specs:
                specs.write("".join(escaped(n) + "\n" for n in sorted(names)))
            matched = listed(program, spec_file, env)
            if matched != names:
                print(f"{program}: the specs match {len(matched)} cases, not the {len(names)} logged: "
                      f"{sorted(names ^ matched)[:5]}")
                failed = True
                continue
            runs.append((program, len(names),
                         subprocess.Popen([program, "-f", spec_file], env=env, stdout=subprocess.PIPE,
                                          stderr=subprocess.STDOUT, text=True)))
        for program, count, run in runs:
            output, _ = run.communicate()
            if run.returncode != 0:
                print(output)
                print(f"{program}: {count} cases re-run without ../shared, exit {run.returncode}")
                failed = True
    skipped = []
    if os.path.exists(skip_log):
        with open(skip_log, encoding="utf-8") as log:
            skipped = sorted(set(log.read().splitlines()))
    total = sum(len(n) for n in cases.values())
    if failed:
        print(f"Without ../shared: FAILED ({total} cases that read it re-run)")
        return 1
    print(f"Without ../shared: {total} test cases that read it re-run with an empty one, all pass; "
          f"{len(skipped)} skip the shared part:")
    for line in skipped:
        print("  " + line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
