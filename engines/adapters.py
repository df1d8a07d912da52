"""The engine adapters, registered: one line each — its folder (engines/<folder>/run_suite.py, whose `VARIANTS` name
the engine variants it writes), the PyPI package it needs, and the work-precision figure's label of each variant it
draws, with that variant's choice. `.ci/engines`, `make_results.sh` and `work_precision.py` read this list: an
adapter is its folder plus its line here (and its row in README.md's table).

    python3 engines/adapters.py packages          # the PyPI packages, on one line
    python3 engines/adapters.py adapters          # the adapters' folders, one a line
    VENV/bin/python engines/adapters.py engines   # the engine variants they write, one a line (imports them)
"""

import importlib.util
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent

#: (folder, PyPI package, {figure label: the variant's choice, None where the adapter has one variant})
ADAPTERS = [
    ("mujoco", "mujoco", {"MuJoCo Euler": "Euler", "MuJoCo implicitfast": "implicitfast", "MuJoCo RK4": "RK4"}),
    ("pybullet", "pybullet", {"PyBullet": None}),
    ("drake", "drake", {"Drake": None}),
    ("dart", "dartpy", {"DART": None}),
    ("rapier", "rapier3d", {"Rapier": "on"}),
]


def module(folder):
    """The adapter module engines/<folder>/run_suite.py (its engine imported)."""
    spec = importlib.util.spec_from_file_location(f"{folder}_run_suite", HERE / folder / "run_suite.py")
    loaded = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(loaded)
    return loaded


def main(what):
    if what == "packages":
        print(" ".join(package for _, package, _ in ADAPTERS))
    elif what == "adapters":
        print("\n".join(folder for folder, _, _ in ADAPTERS))
    elif what == "engines":
        for folder, _, _ in ADAPTERS:
            print("\n".join(module(folder).VARIANTS.values()))
    else:
        raise SystemExit(f"adapters.py: expected packages, adapters or engines, got {what!r}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) == 2 else "")
