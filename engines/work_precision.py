"""The engines' work-precision figure: step size against attitude error, every engine and eulerdyn's own
fixed-step methods on the same axes, scored by `eulerdyn score` on one scene of the suite.

    python engines/work_precision.py --bin target/release/eulerdyn --suite DIR [--scene full_tensor]

Runs MuJoCo (Euler, RK4) and PyBullet through their adapters at 60, 120, ... 1920 steps per second (rows at
60 Hz), and `eulerdyn run --method rk4|split2|split4 --dt h`; scores each; writes engines/results/work_precision.csv
and docs/engines_work_precision.svg.
"""

import argparse
import json
import math
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path[:0] = [str(HERE / "mujoco"), str(HERE / "pybullet")]

RATES = [60, 120, 240, 480, 960, 1920]
COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]


def score(binary, csv, scene, extra=()):
    """The largest attitude error of `csv` against `scene` (rad), from `eulerdyn score --json`."""
    out = subprocess.run([binary, "score", str(csv), "--scene", str(scene), "--json", *extra],
                         capture_output=True, text=True)
    if out.returncode not in (0, 1):
        raise SystemExit(f"eulerdyn score {csv}: exit {out.returncode}: {out.stderr}")
    return json.loads(out.stdout)["metrics"][0]["largest"]


def engine_points(binary, suite, scene, work):
    """(engine, step, error) for the engines' adapters."""
    import run_suite as mujoco_adapter  # engines/mujoco/run_suite.py
    sys.path.remove(str(HERE / "mujoco"))
    del sys.modules["run_suite"]
    import run_suite as bullet_adapter  # engines/pybullet/run_suite.py
    bullet_adapter.p.connect(bullet_adapter.p.DIRECT)
    setup = json.loads((suite / f"{scene}.json").read_text())
    runs = [("MuJoCo Euler", lambda r: mujoco_adapter.run_scene(setup, r, "Euler")),
            ("MuJoCo RK4", lambda r: mujoco_adapter.run_scene(setup, r, "RK4")),
            ("PyBullet", lambda r: bullet_adapter.run_scene(setup, r))]
    points = []
    for name, run in runs:
        for rate in RATES:
            csv = work / f"{name.replace(' ', '_')}_{rate}.csv"
            csv.write_text("\n".join(run(rate)) + "\n")
            points.append((name, 1.0 / rate, score(binary, csv, suite / f"{scene}.toml")))
    return points


def own_points(binary, suite, scene, work):
    """(method, step, error) for eulerdyn's own fixed-step methods, scored like an engine."""
    points = []
    columns = [f"--map=omega_{a}=omega_b_{a}" for a in "xyz"]
    for method in ["rk4", "split2", "split4"]:
        for rate in RATES:
            csv = work / f"eulerdyn_{method}_{rate}.csv"
            subprocess.run([binary, "-q", "run", str(suite / f"{scene}.toml"), "--method", method,
                            "--dt", repr(1.0 / rate), "--every", repr(1.0 / 60), "-o", str(csv)], check=True)
            points.append((f"eulerdyn {method}", 1.0 / rate, score(binary, csv, suite / f"{scene}.toml", columns)))
    return points


def svg(points, scene):
    """A log-log figure: step (s) across, largest attitude error (rad) up, one polyline per engine."""
    width, height, left, right, top, bottom = 900, 560, 90, 230, 50, 60
    xs = [math.log10(p[1]) for p in points]
    ys = [math.log10(max(p[2], 1e-16)) for p in points]
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
               'step size (s)</text>')
    out.append(f'<text x="20" y="{(top + height - bottom) / 2}" font-size="14" text-anchor="middle" '
               f'transform="rotate(-90 20 {(top + height - bottom) / 2})">largest attitude error (rad)</text>')
    names = list(dict.fromkeys(p[0] for p in points))
    for k, name in enumerate(names):
        color = COLORS[k % len(COLORS)]
        dash = ' stroke-dasharray="6 4"' if name.startswith("eulerdyn") else ""
        pts = [(px(math.log10(p[1])), py(math.log10(max(p[2], 1e-16)))) for p in points if p[0] == name]
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
    table = ["engine,step_s,largest_attitude_error_rad"] + [f"{n},{h!r},{e!r}" for n, h, e in points]
    (HERE / "results" / "work_precision.csv").write_text("\n".join(table) + "\n")
    (HERE.parent / "docs" / "engines_work_precision.svg").write_text(svg(points, args.scene))
    print("\n".join(table))


if __name__ == "__main__":
    main()
