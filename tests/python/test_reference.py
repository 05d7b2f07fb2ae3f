"""The README's reference is what scripts/gen_reference.py makes of the registries."""
import importlib.util
import os

import homesh

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def gen_reference():
    path = os.path.join(ROOT, "scripts", "gen_reference.py")
    spec = importlib.util.spec_from_file_location("gen_reference", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_readme_reference_is_up_to_date():
    gen = gen_reference()
    with open(os.path.join(ROOT, "README.md")) as f:
        readme = f.read()
    listed = readme[readme.index(gen.README_START):]
    assert listed == gen.reference(gen.default_binary()) + "\n", (
        "README.md's reference is stale: run "
        "PYTHONPATH=build/python scripts/gen_reference.py --readme README.md")


def test_readme_lists_every_option_with_its_default():
    # Also row by row, so a failure names the option.
    with open(os.path.join(ROOT, "README.md")) as f:
        readme = f.read()
    for s in homesh.stages():
        for name, (default, _) in s["options"].items():
            cell = f"`{default}`".replace("|", "\\|") if default else "—"
            assert f"| `{name}` | {cell} |" in readme, (s["name"], name, default)
