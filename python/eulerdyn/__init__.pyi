"""eulerdyn: Euler's equation of rigid-body rotation, M = d/dt(I·ω), for notebooks (see ``__init__.py``)."""

import os
from typing import Any, Callable, Dict, Mapping, Optional, Sequence, Tuple, Union

import pandas as pd

from ._eulerdyn import RunError as RunError
from ._eulerdyn import SceneError as SceneError

__all__ = [
    "RunError",
    "SceneError",
    "SceneLike",
    "Svg",
    "accuracy",
    "balance",
    "check",
    "compare",
    "events",
    "fit",
    "plot",
    "run",
    "score",
    "sweep",
    "view",
]

__version__: str
"""The version of the eulerdyn crate the extension was built from."""

SceneLike = Union[str, "os.PathLike[str]", Mapping[str, Any]]

def run(
    scene: SceneLike,
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
) -> pd.DataFrame:
    """Simulate a scene; its rows as a DataFrame with the CSV's columns, bit for bit (``eulerdyn run``); the located
    events in ``df.attrs["events"]``."""

def events(
    scene: SceneLike,
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
) -> pd.DataFrame:
    """Only the located events of a run (``event``, ``t``, ``value``, ``direction``), as ``FILE.events.csv``."""

def check(scene: SceneLike) -> Dict[str, Any]:
    """What a scene will simulate, as a dict (``eulerdyn check``)."""

def compare(scene: SceneLike, *, method: Optional[str] = None) -> Dict[str, Any]:
    """Both forms against each other and the closed form (``eulerdyn compare``)."""

def accuracy(scene: SceneLike, *, quick: bool = False) -> pd.DataFrame:
    """The work-precision study's table (``eulerdyn accuracy``)."""

def balance(
    scene: SceneLike,
    *,
    planes: Tuple[float, float],
    radius: float,
    grade: Optional[float] = None,
    rpm: Optional[float] = None,
    measured: Optional[Union[str, "os.PathLike[str]"]] = None,
) -> Dict[str, Any]:
    """Two-plane balancing (``eulerdyn balance``)."""

def score(
    theirs: Union[str, "os.PathLike[str]", pd.DataFrame],
    scene: SceneLike,
    *,
    diagnose: bool = False,
    quaternion: str = "wxyz",
    omega: str = "body",
    map: Optional[Mapping[str, str]] = None,
) -> Dict[str, Any]:
    """Another program's trajectory against the referee (``eulerdyn score --json``)."""

def fit(
    measured: Union[str, "os.PathLike[str]", pd.DataFrame],
    scene: SceneLike,
    *,
    estimate: Sequence[str],
    sigma_omega: Optional[float] = None,
    sigma_attitude: Optional[float] = None,
    quaternion: str = "wxyz",
    omega: str = "body",
    map: Optional[Mapping[str, str]] = None,
    moment: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
) -> Dict[str, Any]:
    """A body from its measured motion (``eulerdyn fit --json``)."""

def sweep(
    sweep_file: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    *,
    jobs: Optional[int] = None,
    shard: Optional[str] = None,
    moment: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, float, float, float], Tuple[float, float, float], Tuple[float, ...]], Sequence[float]]] = None,
) -> pd.DataFrame:
    """The results table of a sweep file or a dict of its keys (``eulerdyn sweep``), a row per run."""

RunLike = Union[str, "os.PathLike[str]", Mapping[str, Any], pd.DataFrame]

class Svg:
    """An SVG figure: ``str(svg)`` is its text; Jupyter shows it inline."""

    data: str
    def __init__(self, data: str) -> None: ...
    def _repr_svg_(self) -> str: ...
    def save(self, path: Union[str, "os.PathLike[str]"]) -> None: ...

def plot(
    source: RunLike,
    panels: Optional[Union[str, Sequence[str]]] = None,
    *,
    title: Optional[str] = None,
    size: Optional[str] = None,
) -> Svg:
    """eulerdyn's figure of a run (a CSV path, a scene or a DataFrame), as ``eulerdyn plot`` draws it."""

def view(source: RunLike, path: Union[str, "os.PathLike[str]"]) -> Dict[str, Any]:
    """Writes eulerdyn's 3D page of a run to ``path``, as ``eulerdyn view`` does."""
