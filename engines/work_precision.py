"""The engines' work-precision figure: what accuracy costs, as in Erez, Tassa & Todorov (ICRA 2015) — the wall time
per simulated second against the largest attitude error, every engine and eulerdyn's own methods on the same axes,
measured in one run on one scene of the suite.

    python engines/work_precision.py --bin target/release/eulerdyn --suite DIR [--scene full_tensor]

Each engine runs through its adapter (engines/*/run_suite.py, registered in engines/adapters.py) at 60, 120, ... 1920 steps per second with rows at
60 Hz; its cost is the median over REPEATS runs of the wall time of its stepping calls (made from Python, one call
a step: the call's own overhead is part of what a Python user pays), and its error is the largest attitude error
that `eulerdyn score` gives. eulerdyn's methods are timed by `eulerdyn accuracy` on the same scene with rows at
60 Hz (the integration alone, in Rust, median of its repeats; the body form of rk4, split2 and split4 over step
sizes, dop853 over tolerances, the exact flow) and their error is the same largest attitude angle over the rows.
Writes engines/results/work_precision.csv and docs/engines_work_precision.svg.
"""

import argparse
import csv
import json
import math
import pathlib
import statistics
import subprocess

from adapters import ADAPTERS, module

HERE = pathlib.Path(__file__).resolve().parent

RATES = [60, 120, 240, 480, 960, 1920]
REPEATS = 5
COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
          "#17becf", "#393b79", "#637939"]
#: eulerdyn's methods on the figure (body form), from `eulerdyn accuracy`'s table.
OWN = ["rk4", "split2", "split4", "dop853", "exact"]


def score(binary, csv_path, scene):
    """The largest attitude error of `csv_path` against `scene` (rad), from `eulerdyn score --json`."""
    out = subprocess.run([binary, "score", str(csv_path), "--scene", str(scene), "--json"],
                         capture_output=True, text=True)
    if out.returncode not in (0, 1):
        raise SystemExit(f"eulerdyn score {csv_path}: exit {out.returncode}: {out.stderr}")
    return json.loads(out.stdout)["metrics"][0]["largest"]


def engine_points(binary, suite, scene, work):
    """(label, step, rtol, cost, error) for every engine at every rate; cost in seconds per simulated second."""
    setup = json.loads((suite / f"{scene}.json").read_text())
    points = []
    for folder, _, labels in ADAPTERS:
        adapter = module(folder)
        for label, choice in labels.items():
            for rate in RATES:
                points.append(engine_point(binary, suite, scene, work, (adapter, setup, choice, label, rate)))
    return points


def engine_point(binary, suite, scene, work, run):
    """(label, step, rtol, cost, error) of one engine variant at one rate."""
    adapter, setup, choice, label, rate = run
    runs = [adapter.run_scene(setup, rate, choice) for _ in range(REPEATS)]
    lines = runs[0][0]
    csv_path = work / f"{label.replace(' ', '_')}_{rate}.csv"
    csv_path.write_text("\n".join(lines) + "\n")
    cost = statistics.median(seconds for _, seconds in runs) / setup["t_end"]
    return (label, 1.0 / rate, None, cost, score(binary, csv_path, suite / f"{scene}.toml"))


def own_points(binary, suite, scene, work):
    """(label, step, rtol, cost, error) for eulerdyn's methods, from `eulerdyn accuracy` with rows at 60 Hz."""
    text = (suite / f"{scene}.toml").read_text()
    at_60hz = work / f"{scene}_60hz.toml"
    at_60hz.write_text(text.replace("every = 0.05", f"every = {1.0 / 60.0!r}"))
    if at_60hz.read_text() == text:
        raise SystemExit(f"{scene}.toml: no `every = 0.05` to set to 60 Hz")
    table = work / "accuracy.csv"
    subprocess.run([binary, "-q", "accuracy", str(at_60hz), "-o", str(table)], check=True)
    t_end = json.loads((suite / f"{scene}.json").read_text())["t_end"]
    points = []
    with table.open() as f:
        for row in csv.DictReader(f):
            if row["frame"] != "body" or row["method"] not in OWN or row["status"] != "ok":
                continue
            step = float(row["dt"]) if row["dt"] else None
            rtol = float(row["rtol"]) if row["rtol"] else None
            points.append((f"eulerdyn {row['method']}", step, rtol, float(row["wall_s"]) / t_end,
                           float(row["err_attitude"])))
    return points


def svg(points, scene):
    """A log-log figure: cost across, largest attitude error up, one polyline per engine or method."""
    width, height, left, right, top, bottom = 960, 600, 90, 250, 50, 60
    xs = [math.log10(p[3]) for p in points]
    ys = [math.log10(max(p[4], 1e-16)) for p in points]
    x0, x1 = math.floor(min(xs)), math.ceil(max(xs))
    y0, y1 = math.floor(min(ys)), math.ceil(max(ys))
    px = lambda x: left + (x - x0) / (x1 - x0) * (width - left - right)
    py = lambda y: height - bottom - (y - y0) / (y1 - y0) * (height - top - bottom)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="28" font-size="18" text-anchor="middle">What accuracy costs, across engines: '
           f'suite scene {scene}</text>']
    for d in range(x0, x1 + 1):
        out.append(f'<line x1="{px(d)}" y1="{top}" x2="{px(d)}" y2="{height - bottom}" stroke="#ddd"/>')
        out.append(f'<text x="{px(d)}" y="{height - bottom + 18}" font-size="13" text-anchor="middle">1e{d}</text>')
    for d in range(y0, y1 + 1):
        out.append(f'<line x1="{left}" y1="{py(d)}" x2="{width - right}" y2="{py(d)}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{py(d) + 4}" font-size="13" text-anchor="end">1e{d}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 15}" font-size="14" text-anchor="middle">'
               'wall time per simulated second (s)</text>')
    out.append(f'<text x="20" y="{(top + height - bottom) / 2}" font-size="14" text-anchor="middle" '
               f'transform="rotate(-90 20 {(top + height - bottom) / 2})">largest attitude error (rad)</text>')
    names = list(dict.fromkeys(p[0] for p in points))
    for k, name in enumerate(names):
        color = COLORS[k % len(COLORS)]
        dash = ' stroke-dasharray="6 4"' if name.startswith("eulerdyn") else ""
        pts = [(px(math.log10(p[3])), py(math.log10(max(p[4], 1e-16)))) for p in points if p[0] == name]
        out.append(f'<polyline fill="none" stroke="{color}" stroke-width="2"{dash} points="'
                   + " ".join(f"{x:.1f},{y:.1f}" for x, y in pts) + '"/>')
        out.extend(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3.5" fill="{color}"/>' for x, y in pts)
        ly = top + 20 + 22 * k
        out.append(f'<line x1="{width - right + 15}" y1="{ly}" x2="{width - right + 40}" y2="{ly}" stroke="{color}" '
                   f'stroke-width="2"{dash}/>')
        out.append(f'<text x="{width - right + 46}" y="{ly + 4}" font-size="13">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--suite", required=True, type=pathlib.Path)
    parser.add_argument("--scene", default="full_tensor")
    args = parser.parse_args()
    work = args.suite / "work_precision"
    work.mkdir(exist_ok=True)
    points = engine_points(args.bin, args.suite, args.scene, work) + own_points(args.bin, args.suite, args.scene, work)
    blank = lambda v: "" if v is None else repr(v)
    table = ["engine,step_s,rtol,cost_s_per_simulated_s,largest_attitude_error_rad"]
    table += [f"{n},{blank(h)},{blank(r)},{c!r},{e!r}" for n, h, r, c, e in points]
    (HERE / "results" / "work_precision.csv").write_text("\n".join(table) + "\n")
    (HERE.parent / "docs" / "engines_work_precision.svg").write_text(svg(points, args.scene))
    print("\n".join(table))


if __name__ == "__main__":
    main()
