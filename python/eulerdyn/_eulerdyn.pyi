"""The extension module (Rust, python/src/): plain Python data; ``eulerdyn`` wraps it in pandas."""

import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

_Scene = Union[str, "os.PathLike[str]", Dict[str, Any]]

__version__: str

class SceneError(ValueError):
    """A scene or an argument that is not valid; the message is the command line's."""

    file: str
    key: Optional[str]
    line: Optional[int]
    column: Optional[int]
    problem: str

class RunError(RuntimeError):
    """A run that failed; the message is the command line's."""

    scene: str
    t: Optional[float]
    reason: str

def run(
    scene: _Scene,
    *,
    method: Optional[str] = None,
    frame: Optional[str] = None,
    backend: Optional[str] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    dt: Optional[float] = None,
    t_end: Optional[float] = None,
    every: Optional[float] = None,
    moment: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float], Tuple[float, ...]], Sequence[float]]] = None,
    rows: bool = True,
) -> Tuple[List[str], bytes, Dict[str, Any], List[Tuple[str, float, float, str]]]:
    """Column names, the rows as native float64 bytes (row-major; empty with ``rows=False``), the run's report, and
    the located events as (event, t, value, direction)."""

def check(scene: _Scene) -> Dict[str, Any]:
    """What ``eulerdyn check`` prints, as a dict."""

def compare(scene: _Scene, *, method: Optional[str] = None) -> Dict[str, Any]:
    """The comparison as a dict; ``table`` is a list of (quantity, body_vs_space, body_vs_exact, space_vs_exact)."""

def accuracy(scene: _Scene, *, quick: bool = False) -> Tuple[str, str]:
    """The study's table (CSV text) and summary."""

def balance(
    scene: _Scene,
    *,
    planes: Tuple[float, float],
    radius: float,
    grade: Optional[float] = None,
    rpm: Optional[float] = None,
    measured: Optional[str] = None,
) -> Dict[str, Any]:
    """The correction masses and the balanced scene, as a dict."""

def score(
    theirs: str,
    scene: _Scene,
    *,
    diagnose: bool = False,
    quaternion: str = "wxyz",
    omega: str = "body",
    map: Optional[Sequence[Tuple[str, str]]] = None,
) -> Dict[str, Any]:
    """The score as ``eulerdyn score --json`` prints it."""

def fit(
    measured: str,
    scene: _Scene,
    *,
    estimate: Sequence[str],
    sigma_omega: Optional[float] = None,
    sigma_attitude: Optional[float] = None,
    quaternion: str = "wxyz",
    omega: str = "body",
    map: Optional[Sequence[Tuple[str, str]]] = None,
    moment: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
) -> Dict[str, Any]:
    """The fit as ``eulerdyn fit --json`` prints it."""

def sweep(
    sweep: _Scene,
    *,
    jobs: Optional[int] = None,
    shard: Optional[str] = None,
    moment: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float], Tuple[float, ...]], Sequence[float]]] = None,
) -> str:
    """The sweep's results table as CSV text."""

def plot(
    csv: str, panels: Optional[str] = None, title: Optional[str] = None, size: Optional[str] = None
) -> str:
    """The figure of a run's CSV as SVG text, as ``eulerdyn plot`` draws it."""

def view(csv: str, out: str) -> Dict[str, Any]:
    """Writes the 3D page of a run's CSV to ``out``; what was drawn, as a dict."""

def run_to_csv(scene: _Scene, csv: str) -> None:
    """Runs the scene and writes its CSV and sidecar, as ``eulerdyn run SCENE -o CSV`` does."""
