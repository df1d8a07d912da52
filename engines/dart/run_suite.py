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

import pathlib
import sys
import time

import dartpy as dart
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import suite_io  # noqa: E402  (engines/suite_io.py)

#: The engine variant this adapter writes (no option chooses among variants).
VARIANTS = {None: "dart"}


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


def run_scene(setup, rate, _variant=None):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    world, body = build(setup, h)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    q = np.array(setup["q0_wxyz"], dtype=float)
    seconds = 0.0
    lines = [suite_io.HEADER]
    for k in range(frames + 1):
        q, w = state(body, q)
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, *q, *w)))
        if k == frames:
            break
        for n in range(substeps):
            t = k / out_rate + n * h
            if suite_io.torque_on(torque, t):
                body.setExtTorque(np.array(torque["value"], dtype=float), torque["frame"] == "body")
            start = time.perf_counter()
            world.step()
            seconds += time.perf_counter() - start
    return lines, seconds


if __name__ == "__main__":
    suite_io.main(__doc__, run_scene, VARIANTS)
