#!/usr/bin/env python3
"""Sampled mutation run: mutants nobody chose. Lines of kernel/ and app/ are drawn at random (seeded), one
mutation rule that fits each is applied, and only the test files that execute the line run against it.
Which test file executes which line comes from a coverage build (build/coverage), cached in
build/coverage/line_tests.json until the sources change. Mutants run in a Release build
(build/mutants-sample); after each one the source and the build's changed files are put back, so the next
mutant recompiles only its own file.

Usage: tests/mutants/sample.py [--seed N] [--mutants N] [--jobs N] [--equivalent FILE] [--list-only]
                               [--mutant ID]
  --seed N          the random.Random seed (default 1)
  --mutants N       how many compiled mutants to make, half from kernel/ and half from app/ (default 60)
  --jobs N          build jobs (default 2)
  --equivalent FILE mutant ids judged equivalent by a person, left out of the score
                    (default tests/mutants/equivalent.toml)
  --list-only       draw and print the mutants without building or running anything
  --mutant ID       run one mutant, by its id file:line:rule:column
"""
import argparse
import fcntl
import hashlib
import json
import os
import pathlib
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import time
import tomllib
from dataclasses import asdict, dataclass, field

ROOT = pathlib.Path(__file__).resolve().parents[2]
COVERAGE = ROOT / "build" / "coverage"
BUILD = ROOT / "build" / "mutants-sample"
PRISTINE = ROOT / "build" / "mutants-sample-pristine"
JOURNAL = BUILD / "sample-applied.json"
LOCK = BUILD / "sample-running.lock"
BASELINE = BUILD / "sample-baseline.json"
TEST_LOG = BUILD / "sample-test.log"
PROGRAMS = ("nome_kernel_tests", "nome_app_tests")
AREAS = ("kernel", "app")
# The page test needs the emscripten build: the only test file of the two programs left out.
EXCLUDED_TESTS = {"app/web_page_test.cpp"}
# NDEBUG and no NOME_ASSERTIONS (a build type of its own), so it compiles the code the Release build does.
COVERAGE_OPTIONS = ["-DCMAKE_BUILD_TYPE=Coverage", "-DCMAKE_UNITY_BUILD=OFF", "-DNOME_BENCH=OFF",
                    "-DNOME_SANITIZE=OFF", "-DCMAKE_CXX_FLAGS=-O0 -DNDEBUG --coverage",
                    "-DCMAKE_C_FLAGS=-O0 -DNDEBUG --coverage", "-DCMAKE_EXE_LINKER_FLAGS=--coverage"]
# A dropped return that lets a function fall off its end is undefined behaviour, not a bug a test can be
# asked to find: -Werror=return-type makes it a mutant that does not compile.
MUTANTS_OPTIONS = ["-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_UNITY_BUILD=OFF", "-DNOME_BENCH=OFF",
                   "-DNOME_SANITIZE=OFF", "-DCMAKE_CXX_FLAGS=-Werror=return-type"]
COVERAGE_TIMEOUT = 3600


def git(*args):
    return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, check=True).stdout


def configure(build_dir, options):
    done = subprocess.run(["cmake", "-G", "Ninja", "-S", str(ROOT), "-B", str(build_dir), *options],
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"sample: cmake failed for {build_dir}:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")


def build(build_dir, targets, jobs):
    return subprocess.run(["cmake", "--build", str(build_dir), "-j", str(jobs), "--target", *targets],
                          capture_output=True, text=True)


def fingerprint():
    """A hash of every file a test result can depend on (the sources, the tests, their data)."""
    names = git("ls-files", "-z", "--cached", "--others", "--exclude-standard").split("\0")
    digest = hashlib.sha256(" ".join(COVERAGE_OPTIONS + MUTANTS_OPTIONS).encode())
    for name in sorted(set(names)):
        path = ROOT / name
        skipped = name.startswith(("docs/", "tests/mutants/")) or name.endswith(".md")
        if not name or skipped or not path.is_file():
            continue
        digest.update(name.encode() + b"\0" + hashlib.sha256(path.read_bytes()).digest())
    return digest.hexdigest()


# Test files and running them -------------------------------------------------------------------------


@dataclass
class TestFile:
    name: str  # the ctest entry: the test file relative to tests/
    program: str
    command: list
    cwd: str
    env: dict
    spec: str  # its -# filter: [#stem]~[.]


def test_files(build_dir):
    shown = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build_dir, capture_output=True, text=True)
    found = []
    for entry in json.loads(shown.stdout)["tests"]:
        command = entry.get("command", [])
        if not command or pathlib.Path(command[0]).name not in PROGRAMS or entry["name"] in EXCLUDED_TESTS:
            continue
        props = {p["name"]: p["value"] for p in entry.get("properties", [])}
        env = dict(v.split("=", 1) for v in props.get("ENVIRONMENT", []))
        found.append(TestFile(entry["name"], pathlib.Path(command[0]).name, command,
                              props.get("WORKING_DIRECTORY", str(build_dir)), env,
                              command[command.index("-#") + 1]))
    return found


def run_program(command, cwd, env, timeout):
    """(exit status or None when timed out, seconds). The program runs in its own process group, so the
    CLI processes the app tests start are killed with it."""
    environment = {k: v for k, v in os.environ.items() if k != "CI"} | env
    start = time.monotonic()
    with open(TEST_LOG, "w") as log:
        process = subprocess.Popen(command, cwd=cwd, env=environment, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            status = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            status = None
        finally:
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            process.wait()
    return status, time.monotonic() - start


def run_tests(tests, timeout):
    """Runs test files of one program together: (status or None, seconds)."""
    first = tests[0]
    command = [first.command[0], "-#", ",".join(t.spec for t in tests), "--warn", "NoTests"]
    return run_program(command, first.cwd, first.env, timeout)


# The coverage map -------------------------------------------------------------------------------------


def executed_any(gcda):
    """Whether a .gcda (gcc 12's format) counts any executed arc. A program writes one for every object it
    links, run or not: reading only these saves most of gcov's time."""
    data = gcda.read_bytes()
    at = 16  # magic, version, stamp, checksum
    while at + 8 <= len(data):
        tag, length = struct.unpack_from("<Ii", data, at)
        at += 8
        if length < 0:  # counters that are all zero, written without them
            continue
        if tag == 0x01A10000 and any(data[at:at + length]):
            return True
        at += length
    return False


def gcov_lines(jobs):
    """{source relative to ROOT: {line: count}} of kernel/ and app/ from the .gcda files of the coverage
    build that count anything."""
    data = sorted(str(p) for p in COVERAGE.rglob("*.gcda") if executed_any(p))
    chunks = [data[i::jobs] for i in range(jobs)]
    # -r -s ROOT: only the project's own files (not the standard library's or Catch's) are written out.
    running = [subprocess.Popen(["gcov", "--json-format", "--stdout", "-r", "-s", str(ROOT), *chunk],
                                cwd=COVERAGE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
               for chunk in chunks if chunk]
    lines = {}
    for process in running:
        out, _ = process.communicate()
        for document in out.splitlines():
            if not document.startswith("{"):
                continue
            doc = json.loads(document)
            for f in doc["files"]:
                path = pathlib.Path(doc["current_working_directory"], f["file"]).resolve()
                try:
                    name = path.relative_to(ROOT).as_posix()
                except ValueError:
                    continue
                if not name.startswith(("kernel/", "app/")) or not name.endswith((".cpp", ".hpp")):
                    continue
                counts = lines.setdefault(name, {})
                for line in f["lines"]:
                    counts[line["line_number"]] = counts.get(line["line_number"], 0) + line["count"]
    return lines


def coverage_map(jobs, print_fingerprint):
    """The cached map, or a new one when the sources changed: which test files execute which lines."""
    cache = COVERAGE / "line_tests.json"
    if cache.is_file():
        cached = json.loads(cache.read_text())
        if cached.get("fingerprint") == print_fingerprint:
            return cached
    print("sample: building the coverage map (build/coverage) ...", flush=True)
    configure(COVERAGE, COVERAGE_OPTIONS)
    built = build(COVERAGE, [*PROGRAMS, "nome"], jobs)
    if built.returncode != 0:
        sys.exit(f"sample: the coverage build failed:\n{built.stdout[-3000:]}")
    tests = test_files(COVERAGE)
    executed, instrumented, status = {}, {}, {}
    for index, test in enumerate(tests):
        for old in COVERAGE.rglob("*.gcda"):
            old.unlink()
        code, seconds = run_program(test.command, test.cwd, test.env, COVERAGE_TIMEOUT)
        status[test.name] = "passed" if code == 0 else "timed out" if code is None else f"exit {code}"
        for name, counts in gcov_lines(jobs).items():
            instrumented.setdefault(name, set()).update(counts)
            for line, count in counts.items():
                if count:
                    executed.setdefault(name, {}).setdefault(line, []).append(index)
        print(f"sample: coverage {index + 1}/{len(tests)} {test.name} ({status[test.name]}, {seconds:.0f} s)",
              flush=True)
    result = {"fingerprint": print_fingerprint, "tests": [t.name for t in tests], "status": status,
              "executed": {n: {str(k): v for k, v in sorted(lines.items())}
                           for n, lines in sorted(executed.items())},
              "instrumented": {n: sorted(lines) for n, lines in sorted(instrumented.items())}}
    cache.write_text(json.dumps(result))
    return result


def covering_tests(cov, path, lineno, code_lines):
    """Test files that execute the line. A line with no code of its own (the second line of a statement
    broken over several) takes the lines of its statement that have code."""
    instrumented = set(cov["instrumented"].get(path, []))
    executed = cov["executed"].get(path, {})

    def ends_statement(n):
        return code_lines[n - 1].rstrip().endswith((";", "{", "}"))

    lines = [lineno]
    if lineno not in instrumented:
        n = lineno - 1
        while n >= 1 and not ends_statement(n):
            lines.append(n)
            n -= 1
        n = lineno
        while n < len(code_lines) and not ends_statement(n):
            n += 1
            lines.append(n)
    # A function's signature (its default arguments) runs with its body: the body's first line with code.
    if not any(n in instrumented for n in lines) and code_lines[lineno - 1].rstrip().endswith("{"):
        lines += [n for n in range(lineno + 1, min(lineno + 8, len(code_lines) + 1)) if n in instrumented][:1]
    names = cov["tests"]
    found = {names[i] for n in lines for i in executed.get(str(n), [])}
    # A class's default member initialisers run in its constructors, which gcov counts in the .cpp of the
    # header's name: the tests that run any of that file.
    if not found and path.endswith(".hpp") and not any(n in instrumented for n in lines):
        source = path[: -len(".hpp")] + ".cpp"
        found = {names[i] for runs in cov["executed"].get(source, {}).values() for i in runs}
    return sorted(found)


# Reading C++ -------------------------------------------------------------------------------------------


def blank(chars, start, end):
    for k in range(start, end):
        if chars[k] != "\n":
            chars[k] = " "


def strip_code(text):
    """The text with comments, the insides of string and character literals and preprocessor lines
    blanked: same length and lines, so a column in it is a column in the text."""
    chars = list(text)
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            blank(chars, i, end)
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            blank(chars, i, end)
            i = end
        elif c in "\"'":
            word = re.search(r"[\w.']*$", text[max(0, i - 40):i]).group()
            if c == "'" and word[:1].isdigit():  # a digit separator
                i += 1
                continue
            if c == '"' and word in ("R", "u8R", "uR", "UR", "LR"):
                delimiter = text[i + 1:text.index("(", i)]
                close = text.index(")" + delimiter + '"', i) + len(delimiter) + 1
            else:
                close = i + 1
                while close < n and text[close] not in (c, "\n"):
                    close += 2 if text[close] == "\\" else 1
            blank(chars, i + 1, min(close, n))
            i = close + 1
        else:
            i += 1
    lines, originals = "".join(chars).split("\n"), text.split("\n")
    continued = False
    for k, line in enumerate(lines):
        if continued or line.lstrip().startswith("#"):
            continued = originals[k].rstrip().endswith("\\")
            lines[k] = " " * len(line)
    return "\n".join(lines)


DECLARATION, INITIALIZER, CODE = 0, 1, 2


def block_kind(head, outer):
    """What a { opens, from the text before it: a function body or other statements (CODE), a braced
    initializer (INITIALIZER) or a class, namespace or enum (DECLARATION)."""
    h = " ".join(head.split())
    if outer == CODE:
        return CODE
    if outer == INITIALIZER:
        return CODE if h.endswith((")", "]")) else INITIALIZER  # a lambda in a table
    if re.search(r"\b(class|struct|union|enum|namespace)\b[^()=]*$", h) or h.startswith("extern"):
        return DECLARATION
    if h == "" or h.endswith("]") or re.search(r"\)[\s\w:<>&*\->]*$", h):
        return CODE
    return INITIALIZER


def kinds_of(code):
    """For each character of stripped code, the kind of block it is in."""
    kinds = bytearray(len(code))
    stack, head, depth, current = [], 0, 0, DECLARATION
    for i, c in enumerate(code):
        kinds[i] = current
        if c in "([":
            depth += 1
        elif c in ")]":
            depth = max(0, depth - 1)
        elif c == ";" and depth == 0:
            head = i + 1
        elif c == "{":
            stack.append((current, depth))
            current, depth, head = block_kind(code[head:i], current), 0, i + 1
        elif c == "}":
            if stack:
                current, depth = stack.pop()
            head = i + 1
    return kinds


TOKEN = re.compile(r"""
  (?P<num>0[xX][0-9a-fA-F']+(?:\.[0-9a-fA-F']*)?(?:[pP][+-]?\d+)?\w*
        |(?:\d[\d']*\.?[\d']*|\.\d[\d']*)(?:[eE][+-]?\d+)?\w*)
 |(?P<id>[A-Za-z_]\w*)
 |(?P<op><=>|<<=|>>=|->\*|->|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|%=|&=|\|=|\^=|::|\.\.\.|\S)
""", re.X)

ARITHMETIC = {"+": "-", "-": "+", "*": "/", "/": "*", "+=": "-=", "-=": "+=", "*=": "/=", "/=": "*="}
COMPARE = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==", "&&": "||", "||": "&&"}
KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "catch", "decltype", "alignof", "alignas",
            "static_assert", "noexcept", "requires", "operator", "throw", "new", "delete", "typeid"}
# Swapping their arguments changes nothing: such a mutant would only be marked equivalent.
COMMUTATIVE = {"min", "max", "fmin", "fmax", "dot", "distance", "swap", "hypot", "equal", "distance2"}
NOT_STATEMENTS = {"return", "break", "continue", "case", "default", "else", "do", "using", "typedef",
                  "goto", "static_assert", "template", "namespace", "struct", "class", "enum", "union",
                  "public", "private", "protected", "friend", "typename", "co_return", "co_yield"}
DECLARATION_LINE = re.compile(
    r"^(?:(?:static|const|constexpr|thread_local|inline|volatile|mutable|extern|unsigned|signed|long|short)"
    r"\s+)*"
    r"(?:[A-Za-z_][\w:]*(?:\s*<.*?>)?)(?:\s*(?:const|&&|&|\*))*\s+[&*]*[A-Za-z_]\w*\s*(?:=|;|\{|\(|\[|,)")
DECLARATION_KEYWORDS = {"return", "throw", "delete", "new", "co_await", "co_yield", "co_return", "goto",
                        "case", "else", "do", "if", "for", "while", "switch", "sizeof", "using", "typedef"}


@dataclass
class Mutant:
    path: str
    line: int
    rule: str
    column: int  # 1-based, where the mutated text starts
    original: str
    mutated: str
    outcome: str = ""  # caught, survived, not covered, equivalent, not compiled
    caught_by: str = ""
    error: str = ""  # the compiler's first error, for a mutant that does not compile
    tests: list = field(default_factory=list)
    seconds: float = 0.0

    @property
    def id(self):
        return f"{self.path}:{self.line}:{self.rule}:{self.column}"

    @property
    def area(self):
        return self.path.split("/")[0]


def tokens_of(code):
    """(kind, text, start, end, template depth) of each token of a stripped line."""
    found, depth = [], 0
    for m in TOKEN.finditer(code):
        kind = m.lastgroup
        text = m.group()
        spaced = m.start() > 0 and code[m.start() - 1] == " " and code[m.end():m.end() + 1] in (" ", "")
        if kind == "op" and text == "<" and not spaced and found and found[-1][0] == "id":
            depth += 1
        elif kind == "op" and text in (">", ">>") and not spaced and depth:
            depth = max(0, depth - len(text))
        found.append((kind, text, m.start(), m.end(), depth, spaced))
    return found


def closing(tokens, k):
    """The index of the token that closes the bracket at tokens[k], or None on this line."""
    level = 0
    for j in range(k, len(tokens)):
        if tokens[j][1] in "([{" and tokens[j][0] == "op":
            level += 1
        elif tokens[j][1] in ")]}" and tokens[j][0] == "op":
            level -= 1
            if level == 0:
                return j
    return None


def is_declaration(code):
    stripped = code.strip()
    first = re.match(r"[A-Za-z_]\w*", stripped)
    return bool(first and first.group() not in DECLARATION_KEYWORDS and DECLARATION_LINE.match(stripped))


def replaced(line, start, end, text):
    return line[:start] + text + line[end:]


def pure_specifier(tokens, k):
    """Whether the literal is the 0 of `virtual ... = 0;`."""
    return (tokens[k][1] == "0" and k >= 2 and tokens[k - 1][1] == "=" and tokens[-1][1] == ";"
            and tokens[k - 2][1] in (")", "const", "override", "noexcept") and k + 2 == len(tokens))


def constant_changes(text):
    """The literal one more and one less (whole-number steps; a float changes its whole part)."""
    if text.startswith(("0x", "0X")) or "'" in text or re.fullmatch(r"0\d+\w*", text):
        return []
    m = re.fullmatch(r"(\d*)(\.\d*)?([eE][+-]?\d+)?([A-Za-z]*)", text)
    if not m or (m.group(4) and not re.fullmatch(r"[uUlLfF]+", m.group(4))):
        return []
    whole = int(m.group(1) or "0")
    rest = text[len(m.group(1)):]
    changes = [("constant+1", f"{whole + 1}{rest}")]
    if whole > 0:
        changes.append(("constant-1", f"{whole - 1}{rest}"))
    return changes


def line_mutants(path, lineno, line, code, kinds_at, starts_statement):
    """Every mutant of one line. kinds_at(column) is the block kind there."""
    tokens = tokens_of(code)
    if not tokens:
        return []
    first = tokens[0]
    statement = kinds_at(first[2]) == CODE
    if first[1] in ("static_assert", "template"):
        return []
    declaration = is_declaration(code)
    if declaration and not re.search(r"[=({]", code):
        return []  # a declaration without logic
    # Outside function bodies only an initializer's expression is logic.
    assignment = next((t[3] for t in tokens if t[1] == "=" and t[5]), None)

    def expression(t):
        return kinds_at(t[2]) != DECLARATION or (assignment is not None and t[2] >= assignment)

    found = []

    def add(rule, start, end, text):
        mutated = replaced(line, start, end, text)
        if mutated != line:
            found.append(Mutant(path, lineno, rule, start + 1, line, mutated))

    for k, (kind, text, start, end, depth, spaced) in enumerate(tokens):
        if not expression(tokens[k]):
            continue
        if kind == "op" and spaced and depth == 0 and text in ARITHMETIC:
            # A string joined to a string: its minus would not compile.
            beside = {tokens[j][1] for j in (k - 1, k + 1) if 0 <= j < len(tokens)}
            if not (text in ("+", "+=") and '"' in beside):
                add("arithmetic", start, end, ARITHMETIC[text])
        elif kind == "op" and spaced and depth == 0 and text in COMPARE:
            add("compare", start, end, COMPARE[text])
        elif kind == "num" and depth == 0 and not pure_specifier(tokens, k):
            for rule, new in constant_changes(text):
                add(rule, start, end, new)
        elif kind == "id" and text in ("true", "false"):
            add("bool", start, end, "false" if text == "true" else "true")
        elif (kind == "id" and text not in KEYWORDS and k + 1 < len(tokens) and tokens[k + 1][1] == "("
              and tokens[k + 1][2] == end and text not in COMMUTATIVE
              and not (k > 0 and tokens[k - 1][1] == "operator")):
            close = closing(tokens, k + 1)
            if close is None:
                continue
            level, commas = 0, []
            for j in range(k + 2, close):
                t = tokens[j]
                if t[0] == "op" and t[1] in "([{":
                    level += 1
                elif t[0] == "op" and t[1] in ")]}":
                    level -= 1
                elif t[1] == "," and level == 0 and t[4] == depth:
                    commas.append(t[2])
            if len(commas) != 1:
                continue
            a_start, a_end = tokens[k + 1][3], commas[0]
            b_start, b_end = commas[0] + 1, tokens[close][2]
            a, b = line[a_start:a_end].strip(), line[b_start:b_end].strip()
            # A string literal swapped with something else would not compile.
            if not a or not b or a == b or any(is_declaration(x + ";") for x in (a, b)) or (
                    (a[0] == '"') != (b[0] == '"')):
                continue
            a_start += len(line[a_start:a_end]) - len(line[a_start:a_end].lstrip())
            b_start += len(line[b_start:b_end]) - len(line[b_start:b_end].lstrip())
            mutated = line[:a_start] + b + line[a_start + len(a):b_start] + a + line[b_start + len(b):]
            if mutated != line:
                found.append(Mutant(path, lineno, "swap-args", start + 1, line, mutated))

    if not statement:
        return found
    # Negated conditions: if (x) -> if (!(x)), while too; not if constexpr (a compile-time choice).
    for k, t in enumerate(tokens[:-1]):
        if t[1] in ("if", "while") and tokens[k + 1][1] == "(":
            close = closing(tokens, k + 1)
            inside = tokens[k + 2:close] if close else []
            if close and inside and not any(x[1] in (";", "=") for x in inside):
                open_end, close_start = tokens[k + 1][3], tokens[close][2]
                mutated = line[:open_end] + "!(" + line[open_end:close_start] + ")" + line[close_start:]
                found.append(Mutant(path, lineno, "negate", t[2] + 1, line, mutated))
    # Dropped break, continue and return: where a statement starts (a line start, after a condition,
    # else, a case label or an opening brace).
    for m in re.finditer(r"\b(return|break|continue)\b", code):
        before = code[:m.start()].rstrip()
        starts = starts_statement if not before else before.endswith((")", "{", ";", "else")) or (
            before.endswith(":") and not before.endswith("::") and re.match(r"\s*(case|default)\b", code))
        end = code.find(";", m.start())
        if not starts or end < 0 or code.count("(", m.start(), end) != code.count(")", m.start(), end):
            continue
        add("drop-jump", m.start(), end + 1, ";")
    # A dropped statement: a whole statement on its own line, not a declaration.
    text = code.strip()
    if (starts_statement and text.endswith(";") and first[1] not in NOT_STATEMENTS and not declaration
            and all(text.count(a) == text.count(b) for a, b in ("()", "[]", "{}"))
            and (first[0] == "id" or first[1] in ("++", "--", "*", "(", "::"))):
        add("drop-statement", first[2], len(code.rstrip()), ";")
    return found


def file_mutants(path):
    """{line: [mutants]} of one source file."""
    text = (ROOT / path).read_text()
    code = strip_code(text)
    kinds = kinds_of(code)
    lines, code_lines = text.split("\n"), code.split("\n")
    offset, previous, result = 0, "", {}
    for index, (line, code_line) in enumerate(zip(lines, code_lines)):
        if code_line.strip():
            starts = (not previous or previous.endswith((";", "{", "}", ")", "else", "do"))
                      or (previous.endswith(":") and not previous.endswith("::")))
            found = line_mutants(path, index + 1, line, code_line, lambda col, at=offset: kinds[at + col],
                                 starts)
            if found:
                result[index + 1] = found
            previous = code_line.strip()
        offset += len(line) + 1
    return result


def source_files():
    """The kernel/ and app/ sources this build compiles, and their headers."""
    commands = json.loads((BUILD / "compile_commands.json").read_text())
    compiled = {pathlib.Path(c["file"]).resolve() for c in commands}
    files = {area: [] for area in AREAS}
    for name in git("ls-files", "kernel", "app").splitlines():
        if name.endswith(".hpp") or (name.endswith(".cpp") and (ROOT / name).resolve() in compiled):
            files[name.split("/")[0]].append(name)
    return files


def family(rule):
    return "constant" if rule.startswith("constant") else rule


def draw(seed, files):
    """For each area, every line with a mutant in random order, each with one mutant: a rule that fits
    the line first, then one place of it."""
    rng = random.Random(seed)
    streams, candidates = {}, {}
    for area in AREAS:
        lines = [(path, found) for path in sorted(files[area])
                 for _, found in sorted(file_mutants(path).items())]
        candidates[area] = len(lines)
        rng.shuffle(lines)
        stream = []
        for _, found in lines:
            rules = sorted({family(m.rule) for m in found})
            rule = rng.choice(rules)
            stream.append(rng.choice([m for m in found if family(m.rule) == rule]))
        streams[area] = stream
    return streams, candidates


def find_mutant(mutant_id):
    path, line, rule, column = mutant_id.rsplit(":", 3)
    for m in file_mutants(path).get(int(line), []):
        if m.rule == rule and m.column == int(column):
            return m
    sys.exit(f"sample: no mutant {mutant_id} in the current source")


# Mutating the source and putting the build back ------------------------------------------------------


def own_file(relative):
    """Files this script writes into the build folder, never treated as build outputs."""
    return "/" not in relative and relative.startswith(("report-", "sample-"))


def manifest(folder):
    found = {}
    for dirpath, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(dirpath, name)
            relative = os.path.relpath(path, folder)
            if not own_file(relative):
                st = os.lstat(path)
                found[relative] = (st.st_mtime_ns, st.st_size)
    return found


class BuildState:
    """A copy of the unmutated build (build/mutants-sample-pristine). What a mutant's build changed is
    copied back with its old times, and the source gets its old time too, so the build tools see the tree
    they saw before the mutant and recompile nothing for the next one."""

    def __init__(self):
        PRISTINE.mkdir(parents=True, exist_ok=True)
        current, kept = manifest(BUILD), manifest(PRISTINE)
        for relative, stamp in current.items():
            if kept.get(relative) != stamp:
                (PRISTINE / relative).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(BUILD / relative, PRISTINE / relative, follow_symlinks=False)
        for relative in kept.keys() - current.keys():
            (PRISTINE / relative).unlink()
        self.stamps = current

    def changed(self):
        now = manifest(BUILD)
        return sorted(r for r, stamp in now.items() if self.stamps.get(r) != stamp)

    def restore(self, changed):
        for relative in changed:
            if relative in self.stamps:
                shutil.copy2(PRISTINE / relative, BUILD / relative, follow_symlinks=False)
            else:
                (BUILD / relative).unlink(missing_ok=True)


def recover():
    """Puts back a mutation left applied by a run that was killed. The file gets a new time, so whatever
    was built from the mutant is rebuilt."""
    if not JOURNAL.is_file():
        return
    applied = json.loads(JOURNAL.read_text())
    (ROOT / applied["path"]).write_text(applied["text"])
    print(f"sample: restored {applied['path']}, left mutated by an interrupted run", flush=True)
    JOURNAL.unlink()


def require_clean():
    dirty = git("status", "--porcelain", "--untracked-files=no", "--", "kernel", "app")
    if dirty:
        sys.exit("sample: kernel/ or app/ has uncommitted changes; the run edits these files and restores "
                 f"them from their text, so commit first:\n{dirty}")


def apply(mutant):
    path = ROOT / mutant.path
    text = path.read_text()
    JOURNAL.write_text(json.dumps({"path": mutant.path, "text": text}))
    lines = text.split("\n")
    assert lines[mutant.line - 1] == mutant.original, f"{mutant.id}: the source moved"
    lines[mutant.line - 1] = mutant.mutated
    stat = path.stat()
    path.write_text("\n".join(lines))
    return text, stat.st_mtime_ns


def unapply(mutant, text, mtime_ns, state):
    """Restores the source and the build; the journal goes only when both are back, and Ctrl-C waits."""
    held = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        path = ROOT / mutant.path
        path.write_text(text)
        os.utime(path, ns=(mtime_ns, mtime_ns))
        state.restore(state.changed())
        JOURNAL.unlink()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


# Running mutants ---------------------------------------------------------------------------------------


class Baseline:
    """Each test file's time and result in the unmutated build, measured when first needed and kept in
    sample-baseline.json while the sources stay the same."""

    def __init__(self, tests, print_fingerprint):
        self.tests = tests
        self.fingerprint = print_fingerprint
        cached = json.loads(BASELINE.read_text()) if BASELINE.is_file() else {}
        self.results = cached.get("tests", {}) if cached.get("fingerprint") == print_fingerprint else {}

    def measure(self, names):
        for name in names:
            if name not in self.results:
                status, seconds = run_program(self.tests[name].command, self.tests[name].cwd,
                                              self.tests[name].env, COVERAGE_TIMEOUT)
                self.results[name] = {"passed": status == 0, "seconds": seconds}
                BASELINE.write_text(json.dumps({"fingerprint": self.fingerprint, "tests": self.results}))

    def failing(self):
        return sorted(n for n, r in self.results.items() if not r["passed"])


def includer(path):
    """An object file of the build compiled from the file or including it, or None."""
    shown = subprocess.run(["ninja", "-C", str(BUILD), "-t", "deps"], capture_output=True, text=True).stdout
    wanted, current = str(ROOT / path), None
    for line in shown.splitlines():
        if not line.startswith(" "):
            current = line.split(": #deps")[0]
        elif line.strip() == wanted:
            return current
    return None


def run_mutant(m, cov, tests, baseline, state, jobs):
    """Builds and tests one mutant; sets its outcome, the tests run and the time taken."""
    start = time.monotonic()
    code_lines = strip_code((ROOT / m.path).read_text()).split("\n")
    covering = [n for n in covering_tests(cov, m.path, m.line, code_lines) if n in tests]
    baseline.measure(covering)
    usable = [n for n in covering if baseline.results[n]["passed"]]
    by_program = {p: [tests[n] for n in usable if tests[n].program == p] for p in PROGRAMS}
    # A mutant no test runs needs only to compile: one object file tells, where a header would rebuild all
    # that include it.
    needed = [p for p in PROGRAMS if by_program[p]] or [includer(m.path) or PROGRAMS[AREAS.index(m.area)]]
    text, mtime_ns = apply(m)
    try:
        m.outcome = "survived" if usable else "not covered"
        for target in needed:
            built = build(BUILD, [target], jobs)
            if built.returncode != 0:
                m.outcome = "not compiled"
                errors = [line for line in built.stdout.splitlines() if "error:" in line]
                m.error = errors[0].replace(f"{ROOT}/", "") if errors else ""
                break
            if target not in PROGRAMS:
                continue
            m.tests += [t.name for t in by_program[target]]
            timeout = max(60.0, 10 * sum(baseline.results[t.name]["seconds"] for t in by_program[target]))
            status, _ = run_tests(by_program[target], timeout)
            if status != 0:
                m.outcome = "caught"
                m.caught_by = f"{target}: " + ("timed out" if status is None else
                                                f"signal {-status}" if status < 0 else f"exit {status}")
                break
    finally:
        unapply(m, text, mtime_ns, state)
    m.seconds = time.monotonic() - start


# Reporting ---------------------------------------------------------------------------------------------


def load_equivalent(path):
    if not path or not pathlib.Path(path).is_file():
        return set()
    text = pathlib.Path(path).read_text()
    if path.endswith(".toml"):
        return set(tomllib.loads(text).get("equivalent", []))
    return {line.split("#")[0].strip() for line in text.splitlines() if line.split("#")[0].strip()}


def describe(m):
    lines = [f"{m.id}  {m.outcome}{' (' + m.caught_by + ')' if m.caught_by else ''}  {m.seconds:.0f} s",
             f"    tests: {', '.join(m.tests) if m.tests else 'none'}",
             f"    - {m.original.strip()}", f"    + {m.mutated.strip()}"]
    return "\n".join(lines)


def scores(made, discarded):
    result = {}
    for area in AREAS:
        mine = [m for m in made if m.area == area]
        counted = [m for m in mine if m.outcome != "equivalent"]
        caught = sum(m.outcome == "caught" for m in counted)
        result[area] = {"made": len(mine), "equivalent": len(mine) - len(counted), "caught": caught,
                        "survived": sum(m.outcome == "survived" for m in counted),
                        "not covered": sum(m.outcome == "not covered" for m in counted),
                        "not compiled (discarded)": sum(m.area == area for m in discarded),
                        "score": caught / len(counted) if counted else None}
    return result


def previous_outcomes(seed):
    """The outcomes an interrupted run of this seed wrote, by mutant id: only the mutants drawn the same way
    (same source line, same text) are reused."""
    path = BUILD / f"report-seed{seed}.json"
    if not path.is_file():
        return {}
    saved = json.loads(path.read_text())
    return {(m["id"], m["original"], m["mutated"]):
            {k: m[k] for k in ("outcome", "caught_by", "error", "tests", "seconds")}
            for m in saved["mutants"] + saved["discarded"] if m["outcome"] != "equivalent"}


def report(title, made, discarded, failing, seed):
    s = scores(made, discarded)
    out = [title, ""]
    out += [describe(m) for m in made]
    if discarded:
        out += ["", "Discarded (did not compile):"] + [f"  {m.id}: {m.mutated.strip()}\n    {m.error.strip()}"
                                                        for m in discarded]
    if failing:
        out += ["", "Test files failing unmutated (not used): " + ", ".join(failing)]
    out.append("")
    for area, a in s.items():
        score = "n/a" if a["score"] is None else f"{100 * a['score']:.0f} %"
        out.append(f"{area}/: score {score}: {a['caught']} caught of {a['made'] - a['equivalent']} "
                   f"({a['made']} made, {a['equivalent']} marked equivalent); {a['survived']} survived, "
                   f"{a['not covered']} not covered; {a['not compiled (discarded)']} discarded "
                   "(did not compile)")
    if made:
        total = sum(m.seconds for m in made + discarded)
        out.append(f"time: {total / 60:.1f} min for {len(made) + len(discarded)} mutants, "
                   f"{total / (len(made) + len(discarded)):.0f} s each")
    survivors = [m for m in made if m.outcome in ("survived", "not covered")]
    if survivors:
        out += ["", "Survivors:"] + [f"  {m.id} ({m.outcome}): {m.original.strip()}  ->  {m.mutated.strip()}"
                                     for m in survivors]
    text = "\n".join(out) + "\n"
    if seed is not None:
        (BUILD / f"report-seed{seed}.txt").write_text(text)
        (BUILD / f"report-seed{seed}.json").write_text(json.dumps(
            {"seed": seed, "split": "half from kernel/, half from app/", "scores": s,
             "failing_unmutated": failing,
             "mutants": [asdict(m) | {"id": m.id} for m in made],
             "discarded": [asdict(m) | {"id": m.id} for m in discarded]}, indent=1))
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--mutants", type=int, default=60)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--equivalent", default=str(ROOT / "tests" / "mutants" / "equivalent.toml"))
    parser.add_argument("--list-only", action="store_true")
    parser.add_argument("--mutant")
    parser.add_argument("--resume", action="store_true",
                        help="keep the outcomes of this seed's last report and run only the mutants it lacks")
    args = parser.parse_args()
    # A termination request (kill, the end of a CI job) unwinds like Ctrl-C, so the source is restored.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("sample: terminated"))

    BUILD.mkdir(parents=True, exist_ok=True)
    # One run at a time owns the build and the journal; a listing only reads (it must not put back the
    # source of a mutant another run has applied).
    lock = open(LOCK, "w")
    is_alone = True
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        is_alone = False
    if not is_alone and not args.list_only:
        sys.exit("sample: another run is using build/mutants-sample; wait for it to end")
    if is_alone:
        recover()
    if is_alone and (not args.list_only or not (BUILD / "compile_commands.json").is_file()):
        configure(BUILD, MUTANTS_OPTIONS)
    quota = {"kernel": (args.mutants + 1) // 2, "app": args.mutants // 2}
    if args.mutant:
        streams = {m.area: [m] for m in [find_mutant(args.mutant)]}
        quota = {area: int(area in streams) for area in AREAS}
        streams = {area: streams.get(area, []) for area in AREAS}
        title = f"Sampled mutations: one mutant, {args.mutant}"
    else:
        streams, candidates = draw(args.seed, source_files())
        title = (f"Sampled mutations, seed {args.seed}: {args.mutants} mutants, half from kernel/ "
                 f"({candidates['kernel']} lines with a mutant) and half from app/ ({candidates['app']})")
    if args.list_only:
        print(title if args.mutant else
              title + "\n(a mutant that does not compile is replaced by the next of its area)")
        for area in AREAS:
            for m in streams[area][:quota[area]]:
                print(f"{m.id}\n    - {m.original.strip()}\n    + {m.mutated.strip()}")
        return

    require_clean()
    equivalent = load_equivalent(args.equivalent)
    print_fingerprint = fingerprint()
    cov = coverage_map(args.jobs, print_fingerprint)
    built = build(BUILD, [*PROGRAMS, "nome"], args.jobs)
    if built.returncode != 0:
        sys.exit(f"sample: the unmutated build fails:\n{built.stdout[-3000:]}")
    tests = {t.name: t for t in test_files(BUILD)}
    baseline = Baseline(tests, print_fingerprint)
    state = BuildState()
    made, discarded = [], []
    position = {area: 0 for area in AREAS}
    seed = None if args.mutant else args.seed
    done = previous_outcomes(seed) if args.resume and seed is not None else {}
    print(title, flush=True)
    while any(sum(m.area == a for m in made) < quota[a] and position[a] < len(streams[a]) for a in AREAS):
        for area in AREAS:
            if sum(m.area == area for m in made) >= quota[area] or position[area] >= len(streams[area]):
                continue
            m = streams[area][position[area]]
            position[area] += 1
            if m.id in equivalent:  # judged already: it compiled then, and no test can catch it
                m.outcome = "equivalent"
            elif (m.id, m.original, m.mutated) in done:
                for name, value in done[m.id, m.original, m.mutated].items():
                    setattr(m, name, value)
            else:
                run_mutant(m, cov, tests, baseline, state, args.jobs)
            if m.outcome == "not compiled":
                discarded.append(m)
                print(f"sample: {m.id} does not compile, discarded ({m.seconds:.0f} s)", flush=True)
                continue
            made.append(m)
            print(describe(m), flush=True)
            report(title, made, discarded, baseline.failing(), seed)
    print("\n" + report(title, made, discarded, baseline.failing(), seed), end="")
    if not args.mutant:
        print(f"sample: report in {BUILD.relative_to(ROOT)}/report-seed{args.seed}.txt (and .json)")


if __name__ == "__main__":
    main()
