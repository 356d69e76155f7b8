#!/usr/bin/env python3
"""Mutation check: applies each mutation of tests/mutants/*.toml to the source, one at a time, rebuilds the
test program that should notice it, runs the tests named, and reports whether they failed (the mutant is
caught). The source is restored after each mutation, also when the run is interrupted.

Every mutation is checked before anything is built: its original text must occur exactly once in its file
and its tests must name test files that exist. A stale mutation is named and the run stops, so a refactor
that moves a line has to move its mutation too (`--check` does only this; `make test` runs it).

Usage: tests/mutants/mutants.py [--check] [--whole] [--build DIR] [--list FILE.toml]... [NAME...]
  --check       only check that every mutation applies (no build)
  --whole       run the whole kernel test program (then the app test program if the kernel's passed)
                instead of the tests each mutation names: how a bug nobody wrote a mutation for is judged
  --build DIR   the build folder (default build/mutants: a Release build with the tests)
  --list FILE   mutations from FILE instead of tests/mutants/*.toml (may be given more than once)
  NAME          only the mutations with these names
"""
import argparse
import pathlib
import subprocess
import sys
import time
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]
LISTS = ROOT / "tests" / "mutants"
PROGRAMS = ("nome_kernel_tests", "nome_app_tests")
TIMEOUT = 900


def load(files):
    mutations = []
    for file in files:
        with open(file, "rb") as f:
            for m in tomllib.load(f).get("mutation", []):
                m["list"] = pathlib.Path(file).name
                mutations.append(m)
    return mutations


def test_files():
    return {p.stem for p in (ROOT / "tests").rglob("*.cpp")}


def problems_of(m, known_tests):
    """What keeps a mutation from applying, or an empty list."""
    missing = [k for k in ("name", "file", "original", "mutated", "program", "tests") if k not in m]
    if missing:
        return [f"lacks {', '.join(missing)}"]
    found = []
    path = ROOT / m["file"]
    if not path.is_file():
        return [f"{m['file']} does not exist"]
    count = path.read_text().count(m["original"])
    if count != 1:
        found.append(f"its original text occurs {count} times in {m['file']}")
    if m["original"] == m["mutated"]:
        found.append("its mutated text is its original text")
    if m["program"] not in PROGRAMS:
        found.append(f"program {m['program']} is none of {', '.join(PROGRAMS)}")
    for tag in m["tests"].split(","):
        name = tag.strip().removeprefix("[#").removesuffix("]")
        if name not in known_tests:
            found.append(f"no test file {name}.cpp for {tag.strip()}")
    return found


def check(mutations):
    known = test_files()
    names = [m.get("name") for m in mutations]
    stale = 0
    for m in mutations:
        found = problems_of(m, known)
        if names.count(m.get("name")) > 1:
            found.append("its name is used twice")
        for problem in found:
            print(f"mutants: STALE {m['list']}: '{m.get('name')}': {problem}", file=sys.stderr)
        stale += bool(found)
    return stale


def run(cmd, **kw):
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, **kw)


def build(build_dir, target):
    return run(["cmake", "--build", str(build_dir), "-j2", "--target", target])


def run_tests(program, spec):
    """(failed, what): failed when the program reports a failure, crashes or times out."""
    try:
        # `-#` tags each case with its file name; `~[.]` keeps the hidden long runs out of every alternative.
        visible = ["~[.]"] if spec is None else ["-#", ",".join(t.strip() + "~[.]" for t in spec.split(","))]
        tested = run([str(program)] + visible, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return True, "timed out"
    return tested.returncode != 0, f"exit {tested.returncode}"


def main():
    parser = argparse.ArgumentParser(add_help=True)
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--whole", action="store_true")
    parser.add_argument("--build", default=str(ROOT / "build" / "mutants"))
    parser.add_argument("--list", action="append")
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()

    files = args.list or sorted(LISTS.glob("*.toml"))
    mutations = load(files)
    chosen = [m for m in mutations if not args.names or m.get("name") in args.names]
    unknown = set(args.names) - {m.get("name") for m in mutations}
    if unknown:
        sys.exit(f"mutants: no mutation named {', '.join(sorted(unknown))}")
    stale = check(chosen)
    if stale:
        sys.exit(f"mutants: {stale} of {len(chosen)} mutations no longer apply (named above); nothing was run")
    if args.check:
        print(f"mutants: all {len(chosen)} mutations apply ({len(files)} lists)")
        return

    build_dir = pathlib.Path(args.build)
    configure = run(["cmake", "-S", ".", "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release"])
    if configure.returncode != 0:
        sys.exit("mutants: cmake failed:\n" + configure.stderr)
    targets = PROGRAMS if args.whole else sorted({m["program"] for m in chosen})
    for target in targets:
        built = build(build_dir, target)
        if built.returncode != 0:
            sys.exit(f"mutants: the unmutated {target} does not build:\n{built.stdout[-3000:]}")

    results = []
    for m in chosen:
        path = ROOT / m["file"]
        source = path.read_text()
        start = time.time()
        try:
            path.write_text(source.replace(m["original"], m["mutated"]))
            outcome, what = None, ""
            for target in targets if args.whole else [m["program"]]:
                built = build(build_dir, target)
                if built.returncode != 0:
                    outcome, what = "ERROR", "does not build: " + built.stdout[-1500:]
                    break
                caught, what = run_tests(build_dir / "tests" / target, None if args.whole else m["tests"])
                if caught:
                    outcome, what = "caught", f"{target} {what}"
                    break
            outcome = outcome or "MISSED"
        finally:
            path.write_text(source)
        seconds = time.time() - start
        results.append((m, outcome, seconds))
        by = "whole programs" if args.whole else m["tests"]
        print(f"{outcome:6}  {seconds:6.1f} s  {m['name']}  ({by}; {what})", flush=True)

    for target in targets:  # leave the build matching the source again
        build(build_dir, target)
    bad = [r for r in results if r[1] != "caught"]
    print(f"mutants: {len(results) - len(bad)} of {len(results)} caught")
    for m, outcome, _ in bad:
        print(f"mutants: {outcome}: {m['name']} ({m['list']})")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
