#!/usr/bin/env python3
"""The code's size limits, held by a test instead of a reviewer (docs/architecture.md):
every C++ file of plugin/ and tests/ at most MAX_LINES lines, and every folder of the
plugin's code at most MAX_FILES files, so that a layer stays one screen of names.

Usage: code_limits.py SOURCE_DIR [--max-lines N] [--max-files N]
Exit status 1, with each breach named, when a limit is exceeded."""
import argparse
import pathlib
import sys

MAX_LINES = 480
MAX_FILES = 40


def breaches(root: pathlib.Path, max_lines: int, max_files: int) -> list[str]:
    found = []
    for folder in ("plugin", "tests"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp") or not path.is_file():
                continue
            with path.open(encoding="utf-8") as text:
                lines = sum(1 for _ in text)
            if lines > max_lines:
                found.append(f"{path.relative_to(root)}: {lines} lines (at most {max_lines}): split it by purpose")
    for folder in sorted(p for p in (root / "plugin").rglob("*") if p.is_dir()):
        files = [p for p in folder.iterdir() if p.is_file()]
        if len(files) > max_files:
            found.append(f"{folder.relative_to(root)}/: {len(files)} files (at most {max_files}): "
                         "move a library that does not need this layer into its own folder")
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source_dir", type=pathlib.Path)
    parser.add_argument("--max-lines", type=int, default=MAX_LINES)
    parser.add_argument("--max-files", type=int, default=MAX_FILES)
    args = parser.parse_args()
    if not (args.source_dir / "plugin" / "core").is_dir():
        print(f"code_limits.py: {args.source_dir} holds no plugin/core/: give the project's root", file=sys.stderr)
        return 2
    found = breaches(args.source_dir, args.max_lines, args.max_files)
    for line in found:
        print(line)
    print(f"code limits: {len(found)} breach(es)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
