#!/usr/bin/env python3
"""Checks the size limits of CONTRIBUTING.md: no source file over 1,000 lines, and no function
over 120 lines, outside tests.

The sources are clang-formatted, so a function definition is a line that opens a brace after a
parameter list and whose matching closing brace comes back to the same indentation. Lambdas and
local classes count towards the function that holds them. Exit 1 lists every file or function over
its limit as file:line: message, as a compiler would.
"""

import pathlib
import re
import sys

MAX_FILE_LINES = 1000
MAX_FUNCTION_LINES = 120

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Statements that open a brace after a parenthesis but are not function definitions.
NOT_A_FUNCTION = re.compile(
    r"^\s*(if|else|for|while|switch|catch|do|return|case|namespace|struct|class|enum|union)\b"
)
OPENS_FUNCTION = re.compile(r"\)\s*(const)?\s*(noexcept)?\s*(&&|&)?\s*(override|final)?\s*"
                            r"(->\s*[^{]+)?\{\s*$")


def is_test(path):
    name = path.name
    return name.endswith("_test.cpp") or "tests" in path.parts or "bench" in path.parts


def strip_code(line):
    """The line without string and character literals and // comments (braces there do not
    count)."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return line.split("//", 1)[0]


def signature_start(lines, i):
    """The first line of the signature that ends on line i (a parameter list may wrap)."""
    depth = 0
    j = i
    while j >= 0:
        code = strip_code(lines[j])
        depth += code.count(")") - code.count("(")
        if depth <= 0:
            return j
        j -= 1
    return i


def functions(lines):
    """(first line, line count, name) of each function definition, outermost only."""
    i = 0
    while i < len(lines):
        code = strip_code(lines[i])
        if OPENS_FUNCTION.search(code) and "[" not in code.split("(")[0]:
            start = signature_start(lines, i)
            head = strip_code(lines[start])
            if not NOT_A_FUNCTION.match(head) and "=" not in head.split("(")[0]:
                depth = 0
                j = i
                while j < len(lines):
                    c = strip_code(lines[j])
                    depth += c.count("{") - c.count("}")
                    if depth <= 0:
                        break
                    j += 1
                name = head.split("(")[0].split()[-1] if head.split("(")[0].split() else "?"
                yield start, j - start + 1, name
                i = j + 1
                continue
        i += 1


def main():
    problems = []
    for path in sorted((ROOT / "src").rglob("*")):
        if path.suffix not in (".cpp", ".hpp") or is_test(path):
            continue
        lines = path.read_text(encoding="utf-8").splitlines()
        rel = path.relative_to(ROOT)
        if len(lines) > MAX_FILE_LINES:
            problems.append(f"{rel}:1: file has {len(lines)} lines (limit {MAX_FILE_LINES})")
        for start, count, name in functions(lines):
            if count > MAX_FUNCTION_LINES:
                problems.append(f"{rel}:{start + 1}: function {name} has {count} lines "
                                f"(limit {MAX_FUNCTION_LINES})")
    for p in problems:
        print(p)
    if problems:
        print(f"check_sizes: {len(problems)} over the limits", file=sys.stderr)
        return 1
    print("check_sizes: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
