#!/usr/bin/python3
"""Markdown reference of homesh's stages, their options and the quality measures.

The README's reference sections are generated, not written: the stages and
options come from the stage registry (`homesh.stages()`, the Python module:
each stage's option table, with the defaults of the options structs), the
measures from the measure registry (`homesh --measures`). Regenerate the
README's reference (from its "### Stages" to its end) with

  PYTHONPATH=build/python scripts/gen_reference.py --readme README.md

or print it with no --readme; tests/python/test_reference.py checks that the
README is up to date.

Usage: gen_reference.py [--homesh build/homesh] [--sections stages,options,measures]
                        [--readme README.md]
"""
import argparse
import os
import re
import subprocess
import sys

import homesh

SECTIONS = ("stages", "options", "measures")


def cell(text):
    """Text safe inside a markdown table cell."""
    return text.replace("|", "\\|")


def stages_table(stages):
    rows = ["| stage | what it does | options (default) |", "|---|---|---|"]
    for s in stages:
        options = ", ".join(f"`{name}` ({default or '—'})"
                            for name, (default, _) in s["options"].items())
        rows.append(f"| `{s['name']}` | {cell(s['summary'])} | {cell(options) or '—'} |")
    return "\n".join(rows)


def options_tables(stages):
    parts = []
    for s in stages:
        if not s["options"]:
            continue
        rows = [f"#### `{s['name']}`", "", cell(s["summary"]), "",
                "| option | default | meaning |", "|---|---|---|"]
        rows += [f"| `{name}` | {f'`{cell(default)}`' if default else '—'} | {cell(help_text)} |"
                 for name, (default, help_text) in s["options"].items()]
        parts.append("\n".join(rows))
    return "\n\n".join(parts)


def measures(binary):
    """(id, name, formula, source) per line of `homesh --measures`."""
    out = subprocess.run([binary, "--measures"], check=True, capture_output=True,
                         text=True).stdout
    rows = []
    for line in out.splitlines():
        m = re.match(r"\s*(Q\d+)\s+(.+?)\s{2,}(.+?)\s{3}\[(.+)\]\s*$", line)
        if not m:
            raise ValueError(f"unexpected line in `homesh --measures`: {line!r}")
        rows.append(m.groups())
    return rows


def measures_table(rows):
    table = ["| measure | name | formula | source |", "|---|---|---|---|"]
    table += [f"| {q} | {name} | `{cell(formula)}` | {cell(source)} |"
              for q, name, formula, source in rows]
    return "\n".join(table)


def reference(binary, wanted=SECTIONS):
    """The reference sections in `wanted`, as markdown."""
    stages = homesh.stages()
    out = []  # markdown blocks, joined by a blank line
    if "stages" in wanted:
        out += ["### Stages", stages_table(stages)]
    if "options" in wanted:
        out += ["### Stage options", options_tables(stages)]
    if "measures" in wanted:
        out += ["### Quality measures",
                "W is the Jacobian of the map from the ideal element (the unit equilateral "
                "triangle; for a quadrilateral the unit square, W = J on the reference square "
                "[0, 1]^2) to the physical one, omega = det W, D = W^T W; every measure is "
                "normalised to [0, 1], 1 at the ideal element, 0 where omega <= 0 (invalid).",
                measures_table(measures(binary))]
    return "\n\n".join(out)


README_START = "### Stages\n"


def default_binary():
    """The homesh command line beside the Python module (build/homesh)."""
    return os.path.normpath(os.path.join(os.path.dirname(homesh.__file__), "..", "homesh"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--homesh", default=default_binary(),
                        help="the homesh command line (default: beside the Python module)")
    parser.add_argument("--sections", default=",".join(SECTIONS),
                        help="comma-separated, from " + ", ".join(SECTIONS))
    parser.add_argument("--readme", help="rewrite this README's reference (all sections), "
                        "from its '### Stages' to its end")
    args = parser.parse_args()
    wanted = args.sections.split(",")
    unknown = set(wanted) - set(SECTIONS)
    if unknown:
        parser.error(f"unknown section(s) {', '.join(sorted(unknown))}")
    if args.readme:
        with open(args.readme) as f:
            text = f.read()
        head = text[:text.index(README_START)]
        with open(args.readme, "w") as f:
            f.write(head + reference(args.homesh) + "\n")
        return 0
    print(reference(args.homesh, wanted))
    return 0


if __name__ == "__main__":
    sys.exit(main())
