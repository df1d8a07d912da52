"""Run eulerdyn's conformance suite in DART (dartpy) and write each trajectory for `eulerdyn score --suite`.

    python engines/dart/run_suite.py --suite DIR [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a DART skeleton of one body node — a
FreeJoint (gravity off) for the torque-free scenes, a BallJoint at the pivot for the top, the torque pulse by
setExtTorque in world or body axes (DART clears it after every step, so it is set again before each) — with no
damping and the world's deactivation (sleeping) off, steps the world at 1/rate s (DART's semi-implicit Euler: ω
from the explicit ω × Iω, then the attitude by the exponential of the new ω) and writes, at the suite's 60 Hz,
DIR/dart[_<rate>hz]/NAME.csv with t, q_w..q_z (body -> world) and omega_x..z (body axes: getAngularVelocity
relative to the world in the body node's coordinates). DART's FreeJoint velocities are the angular then the linear
velocity in world axes, its BallJoint's the angular velocity in the body's; the full inertia tensor (products
included) goes to DART as it is, about C. Where the explicit ω × Iω makes a step diverge (the fast top at 60 Hz),
DART's own guards reset a non-finite pose to the identity and warn on stderr; the CSV keeps what DART reports.
`run_scene` also returns the wall time of the `world.step` calls (for the work-precision figure).
"""

import argparse
import json
import pathlib
import time

import dartpy as dart
import numpy as np

HEADER = "t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z"


def build(setup, timestep):
    """The world of a scene and its body node, whose frame is the scene's body axes, its origin at C or at the pivot."""
    world = dart.simulation.World()
    world.setTimeStep(timestep)
    world.setGravity(np.array(setup["gravity_s"] or [0.0, 0.0, 0.0]))
    # Deactivation puts slow bodies to sleep; it only acts on bodies in contact, but it is switched off all the same.
    options = world.getDeactivationOptions()
    options.mEnabled = False
    world.setDeactivationOptions(options)
    skeleton = dart.dynamics.Skeleton("body")
    pivot = setup["pivot_from_c_b"]
    if pivot is None:
        joint, body = skeleton.createFreeJointAndBodyNodePair()
        com = np.zeros(3)
    else:
        # The joint's frames are the body node's and the world's: the pivot at the world origin.
        joint, body = skeleton.createBallJointAndBodyNodePair()
        com = -np.array(pivot, dtype=float)
    body.setInertia(dart.dynamics.Inertia(setup["mass"], com, np.array(setup["inertia_c_b"], dtype=float)))
    for i in range(joint.getNumDofs()):
        joint.setDampingCoefficient(i, 0.0)
        joint.setSpringStiffness(i, 0.0)
        joint.setCoulombFriction(i, 0.0)
    world.addSkeleton(skeleton)
    rotation_vector = dart.math.quatToExp(dart.math.Quaternion(*setup["q0_wxyz"]))
    omega0_b = np.array(setup["omega0_b"], dtype=float)
    if pivot is None:
        joint.setPositions(np.concatenate([rotation_vector, np.zeros(3)]))
        rot = body.getWorldTransform().rotation()
        joint.setVelocities(np.concatenate([rot @ omega0_b, np.zeros(3)]))
    else:
        joint.setPositions(rotation_vector)
        joint.setVelocities(omega0_b)
    return world, body


def state(body, previous):
    """Attitude (w, x, y, z) of the body axes, the sign of `previous`'s hemisphere, and ω in body axes."""
    q = np.array(body.getWorldTransform().quaternion().wxyz())
    if np.dot(q, previous) < 0:
        q = -q
    return q, body.getAngularVelocity(dart.dynamics.Frame.World(), body)


def run_scene(setup, rate):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    world, body = build(setup, h)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    q = np.array(setup["q0_wxyz"], dtype=float)
    seconds = 0.0
    lines = [HEADER]
    for k in range(frames + 1):
        q, w = state(body, q)
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, *q, *w)))
        if k == frames:
            break
        for n in range(substeps):
            t = k / out_rate + n * h
            if torque is not None and torque["t_on"] <= t < (torque["t_off"] or float("inf")):
                body.setExtTorque(np.array(torque["value"], dtype=float), torque["frame"] == "body")
            start = time.perf_counter()
            world.step()
            seconds += time.perf_counter() - start
    return lines, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", required=True, type=pathlib.Path)
    parser.add_argument("--rate", type=float, default=60.0, help="steps per second (a multiple of 60)")
    parser.add_argument("--scene", action="append", help="only these scenes (default: all)")
    args = parser.parse_args()
    name = "dart" + ("" if args.rate == 60 else f"_{int(args.rate)}hz")
    out = args.suite / name
    out.mkdir(parents=True, exist_ok=True)
    for path in sorted(args.suite.glob("*.json")):
        if args.scene and path.stem not in args.scene:
            continue
        lines, _ = run_scene(json.loads(path.read_text()), args.rate)
        (out / f"{path.stem}.csv").write_text("\n".join(lines) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
