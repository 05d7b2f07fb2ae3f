#!/usr/bin/python3
"""Markdown reference of homesh's stages, their options and the quality measures.

The README's reference sections are generated, not written: the stages and
options come from the stage registry (`homesh.stages()`, the Python module),
the measures from the measure registry (`homesh --measures`). Regenerate with

  PYTHONPATH=build/python scripts/gen_reference.py > /tmp/reference.md

and paste the sections into README.md.

Usage: gen_reference.py [--homesh build/homesh] [--sections stages,options,measures]
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default_binary = os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")
    parser.add_argument("--homesh", default=os.path.normpath(default_binary),
                        help="the homesh command line (default: beside the Python module)")
    parser.add_argument("--sections", default=",".join(SECTIONS),
                        help="comma-separated, from " + ", ".join(SECTIONS))
    args = parser.parse_args()
    wanted = args.sections.split(",")
    unknown = set(wanted) - set(SECTIONS)
    if unknown:
        parser.error(f"unknown section(s) {', '.join(sorted(unknown))}")

    stages = homesh.stages()
    out = []  # markdown blocks, printed with a blank line between them
    if "stages" in wanted:
        out += ["### Stages", stages_table(stages)]
    if "options" in wanted:
        out += ["### Stage options", options_tables(stages)]
    if "measures" in wanted:
        out += ["### Quality measures",
                "W is the Jacobian of the map from the ideal (unit equilateral) triangle to the "
                "physical one, omega = det W, D = W^T W; every measure is normalised to [0, 1], "
                "1 at the ideal element, 0 where omega <= 0 (invalid).",
                measures_table(measures(args.homesh))]
    print("\n\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
