"""Shared helpers: the repository's scenarios and the command-line binary the module is compared with.

The binary is ``$EULERDYN_BIN`` or ``target/release/eulerdyn`` (``cargo build --release`` makes it; ``.ci/python-tests`` does).
A missing binary fails the tests that need it: nothing is skipped.
"""

import csv
import io
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SCENARIOS = REPO / "scenarios"


def cli_binary() -> Path:
    path = Path(os.environ.get("EULERDYN_BIN", REPO / "target" / "release" / "eulerdyn"))
    assert path.is_file(), f"{path}: no eulerdyn binary; run `cargo build --release` first (or set EULERDYN_BIN)"
    return path


def run_cli(*args: str, expect: int = 0) -> subprocess.CompletedProcess:
    """Runs `eulerdyn --quiet ARGS`; asserts its exit code."""
    done = subprocess.run(
        [str(cli_binary()), "--quiet", *args], capture_output=True, text=True, timeout=600
    )
    assert done.returncode == expect, f"exit {done.returncode}: {done.stderr}"
    return done


def cli_csv(*args: str):
    """The CSV `eulerdyn run ARGS` writes to stdout: (header, rows of floats parsed by Python's float)."""
    out = run_cli("run", *args).stdout
    reader = csv.reader(io.StringIO(out))
    header = next(reader)
    rows = [[float(v) for v in row] for row in reader]
    return header, rows


def cli_error(*args: str) -> str:
    """The message of a command that fails with bad input (exit 2), without `error: `."""
    stderr = run_cli(*args, expect=2).stderr.strip()
    assert stderr.startswith("error: "), stderr
    return stderr[len("error: "):]


def disk_dict(tilt_deg: float = 30.0):
    """The notes' thin disk (m = 2 kg, R = 0.3 m) spinning at 10 rad/s about a fixed axis through C tilted 30 deg
    from its symmetry axis, as scenarios/tilted_disk.toml has it."""
    return {
        "name": "tilted-disk",
        "body": {"mass": 2.0, "shape": {"type": "thin_disk", "radius": 0.3}},
        "motion": {"type": "fixed_axis", "tilt_deg": tilt_deg, "rate": 10.0},
        "initial": {"attitude": [0.9659258262890683, -0.25881904510252074, 0.0, 0.0]},
        "solver": {"method": "dop853", "frame": "space", "t_end": 1.0},
        "output": {"every": 0.01},
    }


@pytest.fixture
def scenario():
    def path(name: str) -> Path:
        p = SCENARIOS / name
        assert p.is_file(), p
        return p

    return path
