#!/usr/bin/env python3
"""Checks a lesson's output against the figures its page quotes, so that the text cannot rot.

usage: compare_lesson.py PAGE.md OUTPUT.txt

The page quotes the lesson's line "LESSON n key=value ..." (in a code block). Each quoted
entry must hold in the output's LESSON n line: "key=word" and "key=integer" exactly;
"key=real" to the digits the page shows (half a unit of its last digit); "key<bound" and
"key>bound" as inequalities. Keys the page does not quote are not checked.
"""
import re
import sys


def entries(line):
    return re.findall(r"(\w+)([=<>])(\S+)", line)


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def half_unit_of_last_digit(text):
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def main():
    page, output = open(sys.argv[1]).read(), open(sys.argv[2]).read()
    quoted = re.findall(r"^(LESSON \d+) (.*)$", page, re.M)
    if not quoted:
        print(f"FAILED: {sys.argv[1]} quotes no LESSON line")
        return 1
    failures = 0
    for tag, text in quoted:
        found = re.findall(rf"^{tag} (.*)$", output, re.M)
        if not found:
            print(f"FAILED: the lesson printed no '{tag}' line")
            return 1
        got = {key: value for key, _, value in entries(found[-1])}
        for key, op, want in entries(text):
            if key not in got:
                print(f"FAILED: {tag}: no {key} in the output")
                failures += 1
                continue
            value, have = number(got[key]), got[key]
            if op == "<":
                ok = value is not None and value < float(want)
            elif op == ">":
                ok = value is not None and value > float(want)
            elif number(want) is None or re.fullmatch(r"-?\d+", want):
                ok = have == want
            else:
                ok = value is not None and abs(value - float(want)) <= half_unit_of_last_digit(want) * 1.000001
            print(f"{'ok' if ok else 'FAILED'}: {tag}: {key}{op}{want} (printed {have})")
            failures += not ok
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
