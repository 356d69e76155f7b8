#!/usr/bin/env python3
"""Mutation check: applies each mutation below to the source, one at a time, rebuilds the test program
that should notice it, runs the tests named, and reports whether they failed (the mutant is caught).

A mutation whose text is not found, or that does not build, is an error of this script, not a catch.
The source is restored after each mutation, also when the run is interrupted.

Usage: tests/mutants/mutants.py [BUILD_DIR] [NAME...]   (default build/mutants; all mutations)
"""
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]

# name, file, original text, mutated text, test program, Catch test spec (files by their [#name] tags)
MUTATIONS = [
    ("OBJ reader accepts a face of fewer than 3 vertices", "kernel/src/io/obj.cpp",
     "if (fl.token_columns.size() < 3)", "if (fl.token_columns.size() < 1)",
     "nome_app_tests", "[#bad_input_catalogue_test]"),
    ("binary STL reader accepts a non-finite coordinate", "kernel/src/io/stl_read.cpp",
     "        if (!std::isfinite(p[i]))", "        if (false && !std::isfinite(p[i]))",
     "nome_app_tests", "[#bad_input_catalogue_test]"),
    ("topology errors point at the next face line of an OBJ", "kernel/src/io/face_location.cpp",
     "if (count-- == 0)", "if (count-- == 1)",
     "nome_app_tests", "[#bad_input_catalogue_test]"),
    ("offset sheets swapped at a Möbius seam", "kernel/src/ops/offset.cpp",
     "m_.corner_sign(c) > 0 ? 0 : 1", "m_.corner_sign(c) > 0 ? 0 : 0",
     "nome_kernel_tests", "[#offset_geometry_test]"),
    ("vertex normals ignore the Möbius sign", "kernel/src/mesh/normals.cpp",
     "      if (signs[c] > 0)\n        sum += n;", "      if (signs[c] != 0)\n        sum += n;",
     "nome_kernel_tests", "[#normals_test],[#offset_geometry_test]"),
    ("Catmull-Clark edge point weight changed", "kernel/src/ops/refine_positions.cpp",
     "out[nf + e] = (sum + out[fa] + out[fb]) * 0.25;", "out[nf + e] = (sum + out[fa] + out[fb]) * 0.26;",
     "nome_kernel_tests", "[#subdivide_positions_test],[#subdivide_opensubdiv_test]"),
    ("Catmull-Clark face point of a child level off", "kernel/src/ops/refine_child_positions.cpp",
     "        out[c] = sum * 0.25;", "        out[c] = sum * 0.24;",
     "nome_kernel_tests", "[#subdivide_positions_test],[#subdivide_opensubdiv_test]"),
    ("zipper skips a rung", "kernel/src/ops/zipper.cpp",
     "    steps.push_back(s);\n", "    if (i != m / 2 || j == 0) steps.push_back(s);\n",
     "nome_kernel_tests", "[#zipper_test]"),
    ("build_mesh lets an edge take a third face", "kernel/src/mesh/build_mesh.cpp",
     "if (edge.faces[1] != no_index) {", "if (edge.faces[1] == no_index - 1) {",
     "nome_kernel_tests", "[#build_mesh_test]"),
    ("orientability read from the given orientation", "kernel/src/mesh/topology_report.cpp",
     "parts[k].orientable = orientation.component_orientable[k];", "parts[k].orientable = true;",
     "nome_kernel_tests", "[#topology_report_test]"),
    ("genus of a non-orientable part halved", "kernel/src/mesh/topology_report.cpp",
     "part.genus = part.orientable ? handles / 2 : handles;", "part.genus = handles / 2;",
     "nome_kernel_tests", "[#topology_report_test]"),
    ("expression '*' divides", "kernel/src/scene/expression_parser.cpp",
     'const ExprOp op = t.text == "*" ? ExprOp::multiply', 'const ExprOp op = t.text == "*" ? ExprOp::divide',
     "nome_kernel_tests", "[#expression_test]"),
    ("merge misses points exactly at the tolerance", "kernel/src/ops/merge.cpp",
     "d2 <= tolerance2_", "d2 < tolerance2_ * 0.5",
     "nome_kernel_tests", "[#merge_test]"),
    ("atomic save leaves the temporary file unrenamed", "kernel/src/atomic_file.cpp",
     "std::filesystem::rename(tmp, path, ec);", "std::filesystem::copy_file(tmp, path, ec);",
     "nome_kernel_tests", "[#atomic_file_kill_test],[#save_nome_test]"),
]


def run(cmd, **kw):
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, **kw)


def main():
    args = sys.argv[1:]
    build = pathlib.Path(args.pop(0)) if args and not args[0][0].isupper() else ROOT / "build/mutants"
    chosen = [m for m in MUTATIONS if not args or m[0] in args]
    configure = run(["cmake", "-S", ".", "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"])
    if configure.returncode != 0:
        sys.exit("mutants: cmake failed:\n" + configure.stderr)
    for target in sorted({m[4] for m in chosen}):
        built = run(["cmake", "--build", str(build), "-j2", "--target", target])
        if built.returncode != 0:
            sys.exit(f"mutants: the unmutated {target} does not build:\n{built.stdout[-3000:]}")
    results = []
    for name, file, original, mutated, target, spec in chosen:
        path = ROOT / file
        source = path.read_text()
        if source.count(original) != 1:
            sys.exit(f"mutants: '{name}': the text to mutate occurs {source.count(original)} times in {file}")
        start = time.time()
        try:
            path.write_text(source.replace(original, mutated))
            built = run(["cmake", "--build", str(build), "-j2", "--target", target])
            if built.returncode != 0:
                sys.exit(f"mutants: '{name}' does not build:\n{built.stdout[-3000:]}")
            program = build / "tests" / target
            tested = run([str(program), "-#", spec], timeout=900)
            caught = tested.returncode != 0
        finally:
            path.write_text(source)
        results.append((name, caught, time.time() - start))
        print(f"{'caught' if caught else 'MISSED'}  {time.time() - start:6.1f} s  {name}", flush=True)
    for target in sorted({m[4] for m in chosen}):  # leave the build matching the source again
        run(["cmake", "--build", str(build), "-j2", "--target", target])
    missed = [r for r in results if not r[1]]
    print(f"mutants: {len(results) - len(missed)} of {len(results)} caught")
    sys.exit(1 if missed else 0)


if __name__ == "__main__":
    main()
