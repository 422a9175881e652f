#!/usr/bin/env python3
"""The option tables of docs/reference.md, printed from the option registry
(plugin/core/service/options.cpp) by `ffeti-solve --options setup|solve|sensitivity`: rewrites the
blocks between <!-- options:SCOPE begin --> and <!-- options:SCOPE end -->; and the capability
table (plugin/core/constraints/capabilities.cpp) by `ffeti-solve --capabilities`, the block
between <!-- capabilities begin --> and <!-- capabilities end -->. With --check, changes
nothing and fails when the page differs from the registry or the table (ctest docs_option_tables).
Usage: option-tables.py [--check] FFETI_SOLVE [REFERENCE_MD]"""
import argparse
import pathlib
import re
import subprocess
import sys

HEADER = "| option | type | default | accepted values | meaning |\n|---|---|---|---|---|\n"

parser = argparse.ArgumentParser()
parser.add_argument("--check", action="store_true")
parser.add_argument("ffeti_solve")
parser.add_argument("reference", nargs="?",
                    default=str(pathlib.Path(__file__).resolve().parent.parent / "docs" / "reference.md"))
args = parser.parse_args()

page = pathlib.Path(args.reference)
text = page.read_text()
updated = text
for scope in ("setup", "solve", "sensitivity"):
    rows = subprocess.run([args.ffeti_solve, "--options", scope], check=True, capture_output=True, text=True).stdout
    block = re.compile(rf"(<!-- options:{scope} begin -->\n).*?(<!-- options:{scope} end -->)", re.S)
    if not block.search(updated):
        sys.exit(f"{page}: no <!-- options:{scope} begin --> ... end block")
    updated = block.sub(lambda m: m.group(1) + HEADER + rows + m.group(2), updated)


def with_capabilities(page_text):
    """The page with its capability block rewritten from ffeti-solve --capabilities."""
    table = subprocess.run([args.ffeti_solve, "--capabilities"], check=True, capture_output=True, text=True).stdout
    block = re.compile(r"(<!-- capabilities begin -->\n).*?(<!-- capabilities end -->)", re.S)
    if not block.search(page_text):
        sys.exit(f"{page}: no <!-- capabilities begin --> ... end block")
    return block.sub(lambda m: m.group(1) + table + m.group(2), page_text)


updated = with_capabilities(updated)

if updated == text:
    print(f"ok: the option tables of {page} are the registry's")
elif args.check:
    print(f"FAILED: the option or capability tables of {page} differ from the code; run\n"
          f"  scripts/option-tables.py {args.ffeti_solve}")
    sys.exit(1)
else:
    page.write_text(updated)
    print(f"rewrote the option tables of {page}")
