#!/usr/bin/env python3
"""Functions in src/ longer than a limit, and files longer than a limit.

A function runs from its `fn` line to the first later line holding only
`}` at the same indentation (rustfmt style); its length counts both.
Run from the repository root: python3 tools/fn_lengths.py [FN_LIMIT [FILE_LIMIT]]
"""

import os
import re
import sys

FN = re.compile(r"^(\s*)(?:pub(?:\([^)]*\))?\s+)?(?:const\s+)?(?:async\s+)?(?:unsafe\s+)?fn\s+(\w+)")


def functions(path):
    lines = open(path).read().splitlines()
    for i, line in enumerate(lines):
        m = FN.match(line)
        if not m:
            continue
        indent = m.group(1)
        for j in range(i, len(lines)):
            if lines[j].rstrip() == indent + "}" or (
                j > i and lines[j].startswith(indent + "}") and lines[j].strip() in ("}", "};", "})")
                and len(lines[j]) - len(lines[j].lstrip()) == len(indent)
            ):
                yield m.group(2), i + 1, j - i + 1
                break
            if j == i and line.rstrip().endswith(";"):
                break  # a declaration without a body


def main():
    fn_limit = int(sys.argv[1]) if len(sys.argv) > 1 else 80
    file_limit = int(sys.argv[2]) if len(sys.argv) > 2 else 500
    long_fns, long_files = [], []
    for root, _, names in os.walk("src"):
        for n in sorted(names):
            if not n.endswith(".rs"):
                continue
            p = os.path.join(root, n)
            count = sum(1 for _ in open(p))
            if count > file_limit:
                long_files.append((count, p))
            for name, line, length in functions(p):
                if length > fn_limit:
                    long_fns.append((length, f"{p}:{line} {name}"))
    print(f"functions over {fn_limit} lines: {len(long_fns)}")
    for length, where in sorted(long_fns, reverse=True):
        print(f"  {length:4d}  {where}")
    print(f"files over {file_limit} lines: {len(long_files)}")
    for count, p in sorted(long_files, reverse=True):
        print(f"  {count:4d}  {p}")


if __name__ == "__main__":
    main()
