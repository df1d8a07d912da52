"""eulerdyn: Euler's equation of rigid-body rotation, M = d/dt(I·ω), in body and space axes, for notebooks.

Each function mirrors a command of the ``eulerdyn`` command line and calls the same Rust library:

- :func:`run` — a scene's time series as a :class:`pandas.DataFrame` with the CSV's columns (bit for bit), its
  located ``[[event]]``s in ``df.attrs["events"]``;
- :func:`events` — only the located events, as ``FILE.events.csv`` holds them;
- :func:`check` — what a scene will simulate, as a dict;
- :func:`compare` — both forms of Euler's equation against each other and the closed form;
- :func:`accuracy` — the work-precision study, as a DataFrame;
- :func:`balance` — two-plane balancing of a fixed-axis or hinge scene;
- :func:`score` — another program's trajectory of a scene against the referee, and with ``diagnose=True`` the
  engine step it is consistent with;
- :func:`fit` — a body from its measured motion: inertia, ω₀, q₀ and a gyro's bias with their intervals;
- :func:`sweep` — many runs of a scene with keys varied, a row per run;
- :func:`plot` — eulerdyn's figure of a run (SVG, shown inline in a notebook);
- :func:`view` — eulerdyn's 3D page of a run, written to an HTML file.

A scene is the path of a scene file (TOML) or a dict of the same keys, e.g.
``{"body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]}, "solver": {"t_end": 1.0}, "output": {"every": 0.1}}``;
a sweep likewise. Bad input raises :class:`SceneError` (a ``ValueError``) with the command line's message, naming
the file (or ``<dict>``) and the key, and the keyword argument that set it (``solver.dt (from dt=)``); a failed
run raises :class:`RunError` with the time and the reason. Runs release the GIL, and Ctrl-C (KeyboardInterrupt)
stops them. A column has one dtype whatever its cells (the book: Getting started, The first Python call).
``__version__`` is the version of the eulerdyn crate the extension was built from.
"""

from ._api import SceneLike, accuracy, balance, check, compare, events, fit, run, score, sweep
from ._figures import Svg, plot, view
from ._eulerdyn import RunError, SceneError, __version__

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
