"""What every adapter in engines/ shares: the header of the rows it writes, the principal axes of an inertia tensor,
and its command line — `--suite DIR [--rate HZ] [--scene NAME ...]` and a repeatable option choosing the engine's
variants — which runs each scene DIR/NAME.json of the suite and writes DIR/<engine>[_<rate>hz]/NAME.csv."""

import argparse
import json
import pathlib
import sys

import numpy as np

HEADER = "t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z"


def principal(inertia):
    """Principal moments and the principal frame (a right-handed matrix whose columns are the axes) of a
    symmetric tensor (numpy's eigh)."""
    moments, axes = np.linalg.eigh(np.array(inertia, dtype=float))
    if np.linalg.det(axes) < 0:
        axes[:, 2] *= -1
    return moments, axes


def matrix_to_quat(m):
    """The quaternion (w, x, y, z) of a rotation matrix (Shepperd's method: the largest of w, x, y, z first)."""
    trace = np.trace(m)
    k = int(np.argmax([trace, m[0, 0], m[1, 1], m[2, 2]]))
    if k == 0:
        w = np.sqrt(1 + trace) / 2
        return [w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w)]
    i = k - 1
    j, l = (i + 1) % 3, (i + 2) % 3
    v = np.zeros(3)
    v[i] = np.sqrt(1 + m[i, i] - m[j, j] - m[l, l]) / 2
    v[j] = (m[j, i] + m[i, j]) / (4 * v[i])
    v[l] = (m[l, i] + m[i, l]) / (4 * v[i])
    w = (m[l, j] - m[j, l]) / (4 * v[i])
    return [w, v[0], v[1], v[2]]


def quat_to_matrix(q):
    """The rotation matrix of a unit quaternion (w, x, y, z), in double precision."""
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def torque_on(torque, t):
    """Whether the scene's torque pulse acts at time t (on [t_on, t_off); no pulse: never)."""
    if torque is None:
        return False
    t_off = torque["t_off"] if torque["t_off"] is not None else float("inf")
    return torque["t_on"] <= t < t_off


def main(doc, run, variants, option=None):
    """The adapter's command line. `variants` maps each choice of `--OPTION` (repeatable; all by default) to the
    engine's name, a single `{None: name}` when there is no option; `run(setup, rate, choice)` returns the CSV
    lines and the seconds its steps took. A run whose rows end before t_end is said on stderr."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--suite", required=True, type=pathlib.Path)
    if option:
        parser.add_argument(f"--{option}", action="append", choices=list(variants))
    parser.add_argument("--rate", type=float, default=60.0, help="steps per second (a multiple of 60)")
    parser.add_argument("--scene", action="append", help="only these scenes (default: all)")
    args = parser.parse_args()
    for choice in (getattr(args, option) if option else None) or list(variants):
        out = args.suite / (variants[choice] + ("" if args.rate == 60 else f"_{int(args.rate)}hz"))
        out.mkdir(parents=True, exist_ok=True)
        for path in sorted(args.suite.glob("*.json")):
            if args.scene and path.stem not in args.scene:
                continue
            setup = json.loads(path.read_text())
            lines, _ = run(setup, args.rate, choice)
            if len(lines) - 1 < round(setup["t_end"] * setup["rate_hz"]) + 1:
                end = lines[-1].split(",")[0] if len(lines) > 1 else "0"
                print(f"{out.name}/{path.stem}: the rows end at t = {end} s (the engine's state stopped being "
                      "finite, or the engine stopped)", file=sys.stderr)
            (out / f"{path.stem}.csv").write_text("\n".join(lines) + "\n")
        print(f"wrote {out}")
