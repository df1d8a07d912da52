"""The module's functions (re-exported by ``eulerdyn``): each calls the extension ``eulerdyn._eulerdyn`` and turns
its plain data into pandas. Kept apart from ``__init__.py`` so that ``dir(eulerdyn)`` shows the module's names only,
not the ones imported here.

Tables (the study's and the sweep's) are typed by column, never by their cells, so that the same column has the same
dtype in every table, with or without empty cells and with no rows at all: counts (``run``, ``steps``, ``rejected``,
``evals``, ``repeats``) are int64 (the tables write every count), names and messages (``method``, ``frame``,
``backend``, ``status``, ``message``) pandas' string dtype (``""`` for an empty cell), every other column float64
(NaN for an empty cell).
"""

from __future__ import annotations

import csv
import io
import math
import os
import tempfile
from typing import Any, Callable, Dict, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import pandas as pd

from . import _eulerdyn

#: A scene: the path of a scene file, or a dict of its keys (nested dicts for its tables, lists of dicts for
#: ``[[effect]]`` and ``[[body.point_mass]]``).
SceneLike = Union[str, "os.PathLike[str]", Mapping[str, Any]]

#: The columns of whole numbers (int64) and of names and messages (str) in the study's table and the sweep's; every
#: other column of theirs is float64.
_STUDY_COUNTS = ("steps", "rejected", "evals", "repeats")
_STUDY_TEXTS = ("method", "frame", "backend", "status")
_SWEEP_COUNTS = ("run", "steps", "evals")
_SWEEP_TEXTS = ("status", "message")


def _scene(scene: Any) -> Any:
    """A scene (or a sweep) as the extension takes it: a path, or plain dicts and lists (any other mapping is
    copied into a dict, a tuple into a list, at every depth)."""
    if isinstance(scene, Mapping):
        return {k: _scene(v) for k, v in scene.items()}
    if isinstance(scene, (list, tuple)):
        return [_scene(v) for v in scene]
    return scene


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
    moment: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
) -> pd.DataFrame:
    """Simulate a scene; its rows as a DataFrame, as ``eulerdyn run SCENE`` writes them as CSV.

    The columns are the CSV's, in its order (``t``, ``q_w`` … ``H_norm``, then the motion's own columns such as
    ``theta`` or ``R_A_s_x``), and every value is the float the CSV holds, bit for bit.

    Args:
        scene: the path of a scene file, or a dict of its keys.
        method: integration method instead of the scene's: ``rk4``, ``dopri5``, ``dop853``, ``split2``,
            ``split4`` or ``exact`` (torque-free only) — the command line's ``--method``.
        frame: form of Euler's equation, ``body`` or ``space`` (``--frame``).
        backend: Runge–Kutta implementation, ``own`` or ``ode_solvers`` (``--backend``).
        rtol: relative tolerance of adaptive methods (``--rtol``).
        atol: absolute tolerance of adaptive methods (``--atol``).
        dt: step of fixed-step methods, s (``--dt``).
        t_end: end time, s (``--t-end``).
        every: time between rows, s (``--every``).
        moment: your own moment law, acting besides the scene's effects: ``moment(t, q, omega_b)`` with ``q`` the
            attitude ``(w, x, y, z)`` (body → space) and ``omega_b`` the angular velocity in body axes (tuples of
            floats) returns 3 numbers, the moment in N·m. Called at every right-hand-side evaluation (a free body,
            rk4/dopri5/dop853 only); ``check`` and the sidecar name it by its ``__name__``.
        moment_frame: the axes of ``moment``'s result, ``body`` (default) or ``space``.
        wheel_torque: your own wheel law: ``wheel_torque(t, q, omega_b, spins)`` with ``spins`` the wheels'
            relative spins (rad/s, one per ``[[body.rotor]]`` in order) returns one commanded motor torque per
            wheel (N·m); each wheel's ``max_torque``, ``max_speed_rpm`` and ``friction`` then apply. A wheel with
            its own driver (``torque``, ``spin_accel``, ``torque_table``, ``mode = "free"``) is a SceneError.

    Returns:
        The rows, one per output time. ``df.attrs["report"]`` holds what the run did: ``rows``, ``steps``,
        ``rejected``, ``evals``, ``wall_seconds``. ``df.attrs["events"]`` holds the scene's ``[[event]]``
        occurrences located between the rows, as :func:`events` returns them (a DataFrame, empty without events).

    Raises:
        SceneError: the scene or an override is not valid (the message names the key, and the keyword argument
            that set it, e.g. ``solver.dt (from dt=)``).
        RunError: the run failed (diverged, the step size collapsed; ``moment`` or ``wheel_torque`` raised, or did
            not return 3 finite numbers or one per wheel: its exception is the ``__cause__``); ``.t`` is the time
            it stopped at.
        KeyboardInterrupt: Ctrl-C during the run.

    Example:
        >>> import eulerdyn
        >>> df = eulerdyn.run("scenarios/tilted_disk.toml", t_end=0.5)
        >>> len(df), df.columns[0]
        (51, 't')
    """
    names, data, report, occurrences = _eulerdyn.run(
        _scene(scene),
        method=method,
        frame=frame,
        backend=backend,
        rtol=rtol,
        atol=atol,
        dt=dt,
        t_end=t_end,
        every=every,
        moment=moment,
        moment_frame=moment_frame,
        wheel_torque=wheel_torque,
    )
    values = np.frombuffer(data, dtype=np.float64).reshape(-1, len(names)).copy()
    df = pd.DataFrame(values, columns=list(names))
    df.attrs["report"] = dict(report)
    df.attrs["events"] = _events_table(occurrences)
    return df


def events(scene: SceneLike, **options: Any) -> pd.DataFrame:
    """Simulate a scene and return only its located events, as ``eulerdyn run SCENE -o FILE`` writes them to
    ``FILE.events.csv``: the same run as :func:`run`, without keeping its rows.

    Args:
        scene: the path of a scene file, or a dict of its keys.
        options: the keywords of :func:`run` (``method``, ``rtol``, ``t_end``, ``moment`` …).

    Returns:
        One row per occurrence in time order, the columns of ``FILE.events.csv``: ``event`` (the ``[[event]]``'s
        name, str), ``t`` (s, float64), ``value`` (the quantity there, float64) and ``direction`` (``up`` or
        ``down`` for a crossing, ``max`` or ``min`` for an extremum, str). No rows for a scene without
        ``[[event]]`` or with none located. ``df.attrs["report"]`` holds what the run did, as for :func:`run`.

    Raises:
        SceneError, RunError, KeyboardInterrupt: as :func:`run` (a bad ``[[event]]`` key is a SceneError naming
            it, e.g. ``event[0].when``).

    Example:
        >>> import eulerdyn
        >>> scene = {"body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]}, "initial": {"omega": [0.0, 0.0, 1.0]},
        ...          "event": [{"name": "half", "when": "q_w", "crosses": 0.0}],
        ...          "solver": {"t_end": 4.0}, "output": {"every": 0.5}}
        >>> list(eulerdyn.events(scene)["event"])
        ['half']
    """
    _, _, report, occurrences = _eulerdyn.run(_scene(scene), rows=False, **options)
    df = _events_table(occurrences)
    df.attrs["report"] = dict(report)
    return df


def _events_table(occurrences: Sequence[Tuple[str, float, float, str]]) -> pd.DataFrame:
    """The located events (``(event, t, value, direction)`` tuples) as a DataFrame with the columns of
    ``FILE.events.csv``: ``event`` and ``direction`` str, ``t`` and ``value`` float64, whatever the rows."""
    return pd.DataFrame(
        {
            "event": pd.Series([o[0] for o in occurrences], dtype=str),
            "t": np.array([o[1] for o in occurrences], dtype=np.float64),
            "value": np.array([o[2] for o in occurrences], dtype=np.float64),
            "direction": pd.Series([o[3] for o in occurrences], dtype=str),
        },
        columns=["event", "t", "value", "direction"],
    )


def check(scene: SceneLike) -> Dict[str, Any]:
    """What a scene will simulate, as ``eulerdyn check SCENE`` prints it, without running it.

    Args:
        scene: the path of a scene file, or a dict of its keys.

    Returns:
        A dict: ``text`` (the printout), ``items`` (each label of the printout with its lines, e.g.
        ``items["method"]``), and the settings as values: ``name``, ``description``, ``motion`` (``free``,
        ``fixed_axis`` or ``hinge``), ``method``, ``frame``, ``backend``, ``rtol``, ``atol``, ``dt``, ``t_end``,
        ``every``, ``rows`` (how many rows :func:`run` returns), ``columns`` (its columns) and ``facts`` (what
        the scene conserves, the closed form that applies, the panels of its runs and, under ``check``, its
        numbers at full precision: as a run's sidecar records them under ``facts``).

    Raises:
        SceneError: the scene is not valid.

    Example:
        >>> import eulerdyn
        >>> eulerdyn.check("scenarios/tilted_disk.toml")["motion"]
        'fixed_axis'
    """
    return dict(_eulerdyn.check(_scene(scene)))


def compare(scene: SceneLike, *, method: Optional[str] = None) -> Dict[str, Any]:
    """Run a scene in both forms of Euler's equation and against its closed form, as ``eulerdyn compare SCENE``.

    Args:
        scene: the path of a scene file, or a dict of its keys.
        method: integration method instead of the scene's (``--method``).

    Returns:
        A dict: ``differences`` (a DataFrame indexed by quantity with the columns ``body vs space``,
        ``body vs exact`` and ``space vs exact``: relative differences, the attitude's in rad; NaN where the closed
        form does not give the quantity), ``passes`` (False where the command exits 1), ``tolerance`` (the scene's
        ``[compare]`` tolerance), ``rows``, ``closed_form`` (its name, or None), ``note`` and ``text`` (what the
        command prints).

    Raises:
        SceneError: the scene or the method is not valid.
        RunError: a run failed.

    Example:
        >>> import eulerdyn
        >>> eulerdyn.compare("scenarios/asymmetric_free.toml")["passes"]
        True
    """
    result = dict(_eulerdyn.compare(_scene(scene), method=method))
    table = result.pop("table")
    differences = pd.DataFrame(
        [row[1:] for row in table],
        index=pd.Index([row[0] for row in table], name="quantity"),
        columns=["body vs space", "body vs exact", "space vs exact"],
        dtype=float,
    )
    return {"differences": differences, **result}


def accuracy(scene: SceneLike, *, quick: bool = False) -> pd.DataFrame:
    """The work-precision study of a scene, as ``eulerdyn accuracy SCENE``: every applicable method over a sweep of
    tolerances or step sizes, its error against the closed form (or a reference run) and its cost.

    Args:
        scene: the path of a scene file, or a dict of its keys.
        quick: the library's quick study (4 tolerances, 4 step sizes, one repeat, own backend, body form) instead
            of the command's full one.

    Returns:
        The command's table, a row per run: ``method``, ``frame``, ``rtol``, ``dt``, ``err_omega``,
        ``err_attitude``, ``energy_drift``, ``H_drift``, ``wall_s``, ``steps``, ``rejected``, ``evals``,
        ``err_H_s``, ``atol``, ``backend``, ``repeats``, ``status``: the counts int64, the names str, the rest
        float64 (NaN where the CSV has an empty cell), whatever the rows.
        ``df.attrs["summary"]`` is the summary the command prints.

    Raises:
        SceneError: the scene is not valid, or the study cannot use it.
        RunError: the reference run failed.
        KeyboardInterrupt: Ctrl-C (the study stops before its next run).

    Example:
        >>> import eulerdyn
        >>> study = eulerdyn.accuracy("scenarios/asymmetric_free.toml", quick=True)
        >>> "dop853" in set(study["method"])
        True
    """
    table, summary = _eulerdyn.accuracy(_scene(scene), quick=quick)
    df = _table(table, _STUDY_COUNTS, _STUDY_TEXTS)
    df.attrs["summary"] = summary
    return df


def sweep(
    sweep_file: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    *,
    jobs: Optional[int] = None,
    shard: Optional[str] = None,
    moment: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
    moment_frame: Optional[str] = None,
    wheel_torque: Optional[Callable[[float, Tuple[float, ...], Tuple[float, ...], Tuple[float, ...]], Sequence[float]]] = None,
) -> pd.DataFrame:
    """The runs of a sweep, as ``eulerdyn sweep SWEEP.toml``: a base scene run many times with numeric keys set from
    grids (``values``, ``linspace``, ``logspace``) or drawn at random (``normal``, ``uniform``), in parallel, each
    run reduced to one row.

    Args:
        sweep_file: the path of a sweep file (its ``scene`` is relative to it), or a dict of its keys, e.g.
            ``{"scene": disk, "vary": [{"key": "motion.rate", "values": [5.0, 10.0]}]}``, whose ``scene`` is the
            base scene: a dict of its keys, or its path (relative to the working directory).
        jobs: threads (None: all cores).
        shard: ``"K/N"``: only the runs with ``run % N == K - 1`` (for N processes that split a sweep).
        moment: your own moment law f(t, q, omega_b) -> (M_x, M_y, M_z), acting in every run, as for :func:`run`.
        moment_frame: the axes of ``moment``'s result (``"body"`` or ``"space"``), as for :func:`run`.
        wheel_torque: your own wheel law f(t, q, omega_b, spins) -> one torque per wheel, as for :func:`run`.

    Returns:
        The results table, a row per run sorted by ``run``: ``run``, one column per varied key, ``status``
        (``ok``, ``failed``, ``invalid``), ``message``, ``max_M_norm`` (and ``max_F_sup_norm``, ``max_R_A_norm``,
        ``max_R_B_norm`` where the scene has them), ``energy_drift``, ``H_drift``, ``final_omega_b_x/y/z``,
        ``steps``, ``evals``, ``wall_s``, then ``min_X``, ``max_X``, ``final_X`` of each ``[summary]`` column:
        ``run``, ``steps`` and ``evals`` int64, ``status`` and ``message`` str (``""`` for a run that is ok), the
        rest float64, whatever the rows. A failed or invalid run is a row with its message (NaN in its numeric
        columns); nothing is raised for it.

    Raises:
        SceneError: the sweep or its base scene is not valid (unknown key, empty grid, ...), a bad shard, or
            ``jobs=0``. The message names the file, or ``<dict>`` and the key within the dict (``vary[0].key``,
            ``scene.body.mass`` for a base scene given as a dict).
        RunError: ``moment`` or ``wheel_torque`` raised (its exception is the ``__cause__``).
        KeyboardInterrupt: Ctrl-C (the sweep stops between runs).

    Example:
        >>> import eulerdyn
        >>> table = eulerdyn.sweep({"scene": "scenarios/tilted_disk.toml",
        ...                         "vary": [{"key": "motion.rate", "values": [5.0, 10.0]}]}, jobs=1)
        >>> list(table["status"])
        ['ok', 'ok']
    """
    text = _eulerdyn.sweep(
        _scene(sweep_file),
        jobs=jobs,
        shard=shard,
        moment=moment,
        moment_frame=moment_frame,
        wheel_torque=wheel_torque,
    )
    return _sweep_table(text)


def _sweep_table(text: str) -> pd.DataFrame:
    """The sweep's results table (CSV text, as ``eulerdyn sweep`` writes it) as a DataFrame."""
    return _table(text, _SWEEP_COUNTS, _SWEEP_TEXTS)


def _table(text: str, counts: Tuple[str, ...], texts: Tuple[str, ...]) -> pd.DataFrame:
    """A CSV table as a DataFrame, typed by column whatever its cells: the ``counts`` int64, the ``texts`` str
    (pandas' string dtype, ``""`` for an empty cell), every other column float64, each number read by Python's
    float (correctly rounded: the f64 the table was written from), NaN for an empty cell."""
    reader = csv.reader(io.StringIO(text))
    header = next(reader)
    rows = list(reader)
    columns: Dict[str, Any] = {}
    for k, name in enumerate(header):
        cells = [row[k] for row in rows]
        if name in counts:
            columns[name] = _counts(name, cells)
        elif name in texts:
            columns[name] = pd.Series(cells, dtype=str)
        else:
            columns[name] = np.array([float(c) if c else math.nan for c in cells], dtype=np.float64)
    return pd.DataFrame(columns, columns=header)


def _counts(name: str, cells: "list[str]") -> Any:
    """A column of counts as int64; the tables write every count, so an empty cell is the library's error."""
    if not all(cells):
        raise _eulerdyn.RunError(f"internal error in eulerdyn (please report it): the column `{name}` has an empty count")
    return np.array([int(c) for c in cells], dtype=np.int64)


def score(
    theirs: Union[str, "os.PathLike[str]", pd.DataFrame],
    scene: SceneLike,
    *,
    diagnose: bool = False,
    quaternion: str = "wxyz",
    omega: str = "body",
    map: Optional[Mapping[str, str]] = None,
) -> Dict[str, Any]:
    """Another program's trajectory of a scene against eulerdyn's solution of it, as ``eulerdyn score THEIRS.csv
    --scene SCENE --json`` (with ``--diagnose``, ``--quaternion``, ``--omega`` and ``--map`` for the keywords).

    Args:
        theirs: the path of their CSV, or a DataFrame with its columns (``t``, the attitude as ``q_w..q_z``,
            ``q_0..q_3`` or ``R_11..R_33``, optionally ``omega_x..omega_z``); a DataFrame is written out at full
            precision (17 significant digits) and read as the file would be.
        scene: the path of the scene file their trajectory simulates, or a dict of its keys.
        diagnose: also name the engine model the trajectory is consistent with (``diagnosis``).
        quaternion: the order of the generic columns ``q_0..q_3``, ``"wxyz"`` or ``"xyzw"``.
        omega: the axes of ``omega_x..z``, ``"body"`` or ``"space"``.
        map: eulerdyn's column name → their column name, e.g. ``{"q_w": "qw"}``.

    Returns:
        The score as the command's ``--json`` prints it: ``file`` (``"<DataFrame>"`` for a DataFrame), ``scene``,
        ``rows``, ``t_last``, ``reference``, ``reference_error``, ``referee_adequate``, ``metrics`` (each with
        ``key``, ``name``, ``largest``, ``at``, ``last``, ``threshold``, ``passes``; an event's also
        ``occurrences``, each with ``reference_t``, ``their_t`` and ``error``), ``warnings``, ``hints``,
        ``notes``, ``ends_early`` (their last time, s) when their rows end more than one row before the
        scene's ``t_end`` (not a pass), and, with ``diagnose``, ``diagnosis`` (``closest``, ``distance_rad``,
        ``verdict``, ``candidates``).

    Raises:
        SceneError: bad input, as the command's exit 2 (a missing column, times not on a grid, a quaternion off unit
            norm, a scene the models cannot step with ``diagnose``); the message names the row and column.
        RunError: the referee's own run failed.

    Example:
        >>> import eulerdyn, pandas as pd
        >>> exact = eulerdyn.run("scenarios/tennis_racket.toml", every=1 / 60, t_end=2.0)
        >>> result = eulerdyn.score(exact, "scenarios/tennis_racket.toml")
        >>> all(m["passes"] for m in result["metrics"])
        True
    """
    pairs = sorted((map or {}).items())
    options = dict(diagnose=diagnose, quaternion=quaternion, omega=omega, map=pairs)
    if isinstance(theirs, pd.DataFrame):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "theirs.csv")
            theirs.to_csv(path, index=False, float_format="%.17g")
            result = dict(_eulerdyn.score(path, _scene(scene), **options))
        result["file"] = "<DataFrame>"
        return result
    return dict(_eulerdyn.score(os.fspath(theirs), _scene(scene), **options))



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
    """A body from its measured motion, as ``eulerdyn fit MEASURED.csv --scene SCENE --estimate LIST --json``
    (with ``--sigma-omega``, ``--sigma-attitude``, ``--quaternion``, ``--omega`` and ``--map`` for the keywords).

    Args:
        measured: the path of the measured CSV, or a DataFrame with its columns (``t`` and a gyro's
            ``omega_x..omega_z`` and/or the attitude as ``q_w..q_z``, ``q_0..q_3`` or ``R_11..R_33``; rows at any
            times); a DataFrame is written out at full precision (17 significant digits) and read as the file would be.
        scene: the model and the start of the estimates: the path of a scene file, or a dict of its keys.
        estimate: the parameter groups: ``"inertia"`` (six entries about C) or ``"principal"`` (the principal
            moments, the scene's axes held), ``"omega0"``, ``"attitude0"``, ``"gyro_bias"``.
        sigma_omega: the gyro's noise (rad/s); ``None``: from the residuals.
        sigma_attitude: the attitude's noise (rad); ``None``: from the residuals.
        quaternion: the order of the generic columns ``q_0..q_3``, ``"wxyz"`` or ``"xyzw"``.
        omega: the axes of ``omega_x..z``, ``"body"`` or ``"space"``.
        map: eulerdyn's column name → the file's column name, e.g. ``{"omega_x": "gx"}``.
        moment: a law f(t, q, omega_b) → 3 numbers (N·m) acting on the body, as :func:`run`'s ``moment``: it acts
            in the fit's model as in the run (a known moment also fixes the inertia's scale).
        moment_frame: the axes of ``moment``'s result, ``"body"`` (default) or ``"space"``.
        wheel_torque: a law f(t, q, omega_b, spins) → one torque per wheel, as :func:`run`'s ``wheel_torque``.

    Returns:
        The fit as the command's ``--json`` prints it: ``parameters`` (each ``name``, ``start``, ``estimate``,
        ``std_error``, ``low``, ``high``: the 95 % interval), ``correlation`` (``names``, ``matrix``), ``rms`` and
        ``sigma`` per channel, ``chi2_dof``, ``dof``, ``converged``, ``termination``, ``iterations``,
        ``scale_held``, ``notes``, ``unphysical`` (why the fitted inertia is not a body, else ``None``),
        ``warnings``, and ``file`` (``"<DataFrame>"`` for a DataFrame), ``scene``, ``rows``.

    Raises:
        SceneError: bad input, as the command's exit 2 (a missing column, times not increasing, an unknown
            parameter, one the data cannot determine); the message names it.
        RunError: the model cannot be run at the scene's start.

    Example:
        >>> import eulerdyn
        >>> truth = eulerdyn.run({"body": {"mass": 1.0, "inertia": [1.0, 1.3, 1.6]},
        ...                       "initial": {"omega": [0.4, 0.1, 1.5]},
        ...                       "solver": {"t_end": 10.0}, "output": {"every": 0.1}})
        >>> gyro = truth.rename(columns={"omega_b_x": "omega_x", "omega_b_y": "omega_y", "omega_b_z": "omega_z"})
        >>> start = {"body": {"mass": 1.0, "inertia": [1.1, 1.2, 1.6]}, "initial": {"omega": [0.38, 0.12, 1.52]},
        ...          "solver": {"t_end": 10.0}, "output": {"every": 0.1}}
        >>> result = eulerdyn.fit(gyro[["t", "omega_x", "omega_y", "omega_z"]], start, estimate=["principal", "omega0"])
        >>> round(result["parameters"][0]["estimate"], 6), result["scale_held"]
        (1.0, True)
    """
    options = dict(
        estimate=list(estimate),
        sigma_omega=sigma_omega,
        sigma_attitude=sigma_attitude,
        quaternion=quaternion,
        omega=omega,
        map=sorted((map or {}).items()),
        moment=moment,
        moment_frame=moment_frame,
        wheel_torque=wheel_torque,
    )
    if isinstance(measured, pd.DataFrame):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "measured.csv")
            measured.to_csv(path, index=False, float_format="%.17g")
            result = dict(_eulerdyn.fit(path, _scene(scene), **options))
        result["file"] = "<DataFrame>"
        return result
    return dict(_eulerdyn.fit(os.fspath(measured), _scene(scene), **options))


def balance(
    scene: SceneLike,
    *,
    planes: Tuple[float, float],
    radius: float,
    grade: Optional[float] = None,
    rpm: Optional[float] = None,
    measured: Optional[Union[str, "os.PathLike[str]"]] = None,
    service_rpm: Optional[float] = None,
    tolerance_planes: str = "bearings",
    readings: str = "force",
) -> Dict[str, Any]:
    """Two-plane balancing of a fixed-axis or hinge scene, as ``eulerdyn balance SCENE --planes A,B --radius R``
    (with ``--grade``, ``--rpm``, ``--measured`` for the keywords of the same names).

    Args:
        scene: the path of a scene file, or a dict of its keys.
        planes: axial positions (A, B) of the correction planes, m from ``motion.point`` along the axis.
        radius: distance of the correction masses from the axis, m.
        grade: the balance grade G (mm/s, ISO 21940-11) to judge the rotor against.
        rpm: the speed of the measured runs (r/min), for the one-shot coefficients.
        service_rpm: the maximum service speed (r/min) the grade is judged at (default: the scene's rate; with
            ``measured``, a grade judged at the scene's rate is a warning and reads ``unverified``).
        tolerance_planes: ``"bearings"`` (ISO 21940-11's) or ``"correction"``.
        readings: ``"force"`` (bearing forces in N, checked against the model) or ``"other"``.
        measured: the path of a table of measured 1x phasors (``run,trial_plane,trial_mass_g,trial_angle_deg,
            A_amp,A_phase_deg,B_amp,B_phase_deg``): balance by influence coefficients.

    Returns:
        The report of ``eulerdyn balance --json`` as a dict — ``mode`` (``model``, ``measured`` or ``one_shot``),
        ``planes``, ``corrections`` (per plane: ``plane``, ``z``, ``mass`` kg, ``mass_g``, ``angle_deg``, ``at_b``
        — the position in body axes, the scene file's ``at``), ``reference_b`` and ``reference_name`` (the
        direction angles are measured from), ``rate`` (rad/s), ``largest_reaction_before`` and
        ``largest_reaction_after`` (N), ``unbalance_gmm`` (``before``/``after``, per plane ``amp`` g·mm,
        ``phase_deg``, ``re``, ``im``), ``grade`` (None without a speed; ``shares``, ``met_before``, ``met_after``,
        ``target`` with ``u_per_gmm``, ``u_per_planes_gmm``, ``pass_before``, ``pass``) and ``influence`` (None
        without ``measured``; ``table``, ``source``, ``runs``, ``trial_runs``, ``coefficients``,
        ``condition_number``, ``condition_warning``, ``initial_readings``, ``fitted_initial_readings``,
        ``predicted_residual_readings``) — and ``scene`` (the balanced scene as a dict, ready
        for :func:`run`), ``toml`` (it as a scene file) and ``text`` (what the command prints).

    Raises:
        SceneError: the scene is not valid or cannot be balanced (a free body, A = B, radius <= 0), the table
            cannot be used (no initial run, a plane without a trial, a bad cell, a singular system; the message
            names the line), or grade or rpm <= 0.

    Example:
        >>> import eulerdyn
        >>> report = eulerdyn.balance("scenarios/fan_rotor_g63.toml", planes=(-0.1, 0.08), radius=0.25, grade=6.3)
        >>> report["grade"]["target"]["pass"]
        True
    """
    return dict(
        _eulerdyn.balance(
            _scene(scene),
            planes=tuple(planes),
            radius=radius,
            grade=grade,
            rpm=rpm,
            measured=None if measured is None else os.fspath(measured),
            service_rpm=service_rpm,
            tolerance_planes=tolerance_planes,
            readings=readings,
        )
    )
