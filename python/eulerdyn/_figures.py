"""eulerdyn's own figure and 3D page in a notebook: :func:`plot` returns the SVG that ``eulerdyn plot`` draws (shown
inline by Jupyter), :func:`view` writes the page that ``eulerdyn view`` writes. Both take a run's CSV (with its
sidecar, as ``eulerdyn run -o`` writes them), a scene (run first, in a temporary directory) or a DataFrame of a
run's columns (written to a temporary CSV: without a sidecar, the figure knows nothing of the scene — its
invariants, rotors or carrier — and the page draws a unit cube; pass the scene for those). Nothing is computed
here: the extension calls the library's ``plot_file`` and ``view_file`` code.
"""

from __future__ import annotations

import os
import tempfile
from typing import Any, Dict, Mapping, Optional, Sequence, Union

import pandas as pd

from . import _eulerdyn
from ._api import _scene

#: What a figure or page is drawn from: a run's CSV path, a scene (a ``.toml`` path or a dict), or a DataFrame.
RunLike = Union[str, "os.PathLike[str]", Mapping[str, Any], pd.DataFrame]


class Svg:
    """An SVG figure: ``str(svg)`` (or ``svg.data``) is its text; Jupyter shows it inline (``_repr_svg_``)."""

    def __init__(self, data: str) -> None:
        self.data = data

    def _repr_svg_(self) -> str:
        return self.data

    def __str__(self) -> str:
        return self.data

    def __repr__(self) -> str:
        return f"<eulerdyn.Svg, {len(self.data)} characters>"

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the SVG text to ``path`` (UTF-8)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.data)


def _with_csv(source: RunLike, work: Any) -> Any:
    """Calls ``work(csv_path)`` with the run's CSV: ``source`` itself when it is a path not ending in ``.toml``,
    else a temporary CSV of the scene's run (with its sidecar) or of the DataFrame's rows."""
    if isinstance(source, pd.DataFrame):
        with tempfile.TemporaryDirectory(prefix="eulerdyn-") as tmp:
            csv = os.path.join(tmp, "run.csv")
            source.to_csv(csv, index=False, float_format="%.17g")
            return work(csv)
    if isinstance(source, Mapping) or str(os.fspath(source)).lower().endswith(".toml"):
        scene = _scene(source) if isinstance(source, Mapping) else os.fspath(source)
        with tempfile.TemporaryDirectory(prefix="eulerdyn-") as tmp:
            csv = os.path.join(tmp, "run.csv")
            _eulerdyn.run_to_csv(scene, csv)
            return work(csv)
    return work(os.fspath(source))


def plot(
    source: RunLike,
    panels: Optional[Union[str, Sequence[str]]] = None,
    *,
    title: Optional[str] = None,
    size: Optional[str] = None,
) -> Svg:
    """eulerdyn's figure of a run, as ``eulerdyn plot RUN.csv -o FIG.svg`` draws it.

    Args:
        source: a run's CSV path (its sidecar ``RUN.csv.meta.json`` read when beside it), a scene (a ``.toml``
            path or a dict: it is run first) or a DataFrame with a run's columns (``eulerdyn.run``'s).
        panels: panel names, as a list or comma-separated (``["h_space", "drift"]``); None: the panels the run
            has (``--panels``).
        title: the figure's title (``""``: none; None: the scene, method and rows).
        size: ``"W,H"`` in centimetres (``--size``).

    Returns:
        The figure (:class:`Svg`): shown inline in a notebook; ``str()`` is the SVG text, ``.save(path)`` writes it.

    Raises:
        SceneError: the scene, the CSV or an option cannot be used (the message names the file, row and column).
        RunError: the scene's run failed, or the figure could not be drawn.

    Example:
        >>> import eulerdyn
        >>> figure = eulerdyn.plot("scenarios/tilted_disk.toml", ["h_space", "drift"])
        >>> str(figure).startswith("<svg")
        True
    """
    if panels is not None and not isinstance(panels, str):
        panels = ",".join(panels)
    return Svg(_with_csv(source, lambda csv: _eulerdyn.plot(csv, panels, title, size)))


def view(source: RunLike, path: Union[str, "os.PathLike[str]"]) -> Dict[str, Any]:
    """Writes eulerdyn's 3D page of a run to ``path`` (an HTML file to open in a browser), as ``eulerdyn view
    RUN.csv -o PAGE.html`` does.

    Args:
        source: as for :func:`plot`; a DataFrame has no sidecar, so its body is drawn as a unit cube.
        path: the page to write (replaced atomically).

    Returns:
        What was drawn: ``rows_in_run``, ``rows_drawn``, ``stride``, ``bytes``, ``notes`` (what could not be drawn).

    Raises:
        SceneError: the scene or the CSV cannot be used, or ``path`` cannot be created.
        RunError: the scene's run failed, or the page could not be written.

    Example:
        >>> import eulerdyn, os, tempfile
        >>> page = os.path.join(tempfile.mkdtemp(), "disk.html")
        >>> drawn = eulerdyn.view("scenarios/tilted_disk.toml", page)
        >>> drawn["rows_drawn"] > 0 and os.path.getsize(page) == drawn["bytes"]
        True
    """
    out = os.fspath(path)
    return dict(_with_csv(source, lambda csv: _eulerdyn.view(csv, out)))
