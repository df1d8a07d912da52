"""Run eulerdyn's conformance suite in PyBullet (Bullet Physics) and write each trajectory for `eulerdyn score`.

    python engines/pybullet/run_suite.py --suite DIR [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a Bullet multibody — a free base
(gravity off) for the torque-free scenes, a base fixed at the pivot with a spherical joint for the top, the
torque pulse by applyExternalTorque in world axes — with no damping, steps it at 1/rate s and writes, at the
suite's 60 Hz, DIR/pybullet[_<rate>hz]/NAME.csv with t, q_w..q_z (body -> world) and omega_x..z (body axes).
A full inertia tensor is given to Bullet as its principal moments and the principal frame (numpy's eigh).
`run_scene` also returns the wall time of the `stepSimulation` calls (for the work-precision figure).
"""

import argparse
import json
import pathlib
import time

import numpy as np
import pybullet as p

HEADER = "t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z"


def quat_mul(a, b):
    """The product of quaternions in Bullet's order (x, y, z, w)."""
    return p.multiplyTransforms([0, 0, 0], a, [0, 0, 0], b)[1]


def principal(inertia):
    """Principal moments and the principal frame (x, y, z, w) of a symmetric tensor, the frame right-handed."""
    moments, axes = np.linalg.eigh(np.array(inertia))
    if np.linalg.det(axes) < 0:
        axes[:, 2] *= -1
    return moments, matrix_to_quat(axes)


def matrix_to_quat(m):
    """The quaternion (x, y, z, w) of a rotation matrix (Shepperd's method: the largest of w, x, y, z first)."""
    trace = np.trace(m)
    k = int(np.argmax([trace, m[0, 0], m[1, 1], m[2, 2]]))
    if k == 0:
        w = np.sqrt(1 + trace) / 2
        return [(m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w), w]
    i = k - 1
    j, l = (i + 1) % 3, (i + 2) % 3
    v = np.zeros(3)
    v[i] = np.sqrt(1 + m[i, i] - m[j, j] - m[l, l]) / 2
    v[j] = (m[j, i] + m[i, j]) / (4 * v[i])
    v[l] = (m[l, i] + m[i, l]) / (4 * v[i])
    w = (m[l, j] - m[j, l]) / (4 * v[i])
    return [v[0], v[1], v[2], w]


def build(setup):
    """The multibody of a scene and whether it is free (else: one spherical joint at the pivot)."""
    moments, frame = principal(setup["inertia_c_b"])
    w, x, y, z = setup["q0_wxyz"]
    q0 = [x, y, z, w]
    pivot = setup["pivot_from_c_b"]
    if pivot is None:
        body = p.createMultiBody(baseMass=setup["mass"], baseCollisionShapeIndex=-1,
                                 baseInertialFramePosition=[0, 0, 0], baseInertialFrameOrientation=frame,
                                 baseOrientation=q0)
        link = -1
    else:
        c_from_pivot = [-v for v in pivot]
        # Without collision shapes Bullet's spherical joint gives NaN at the first step; two small spheres that
        # never collide (filtered) are enough.
        sphere = p.createCollisionShape(p.GEOM_SPHERE, radius=0.001)
        body = p.createMultiBody(baseMass=0, baseCollisionShapeIndex=sphere, linkMasses=[setup["mass"]],
                                 linkCollisionShapeIndices=[sphere], linkVisualShapeIndices=[-1],
                                 linkPositions=[[0, 0, 0]], linkOrientations=[[0, 0, 0, 1]],
                                 linkInertialFramePositions=[c_from_pivot],
                                 linkInertialFrameOrientations=[frame], linkParentIndices=[0],
                                 linkJointTypes=[p.JOINT_SPHERICAL], linkJointAxis=[[0, 0, 1]])
        link = 0
        p.setCollisionFilterPair(body, body, -1, 0, 0)
    p.changeDynamics(body, link, localInertiaDiagonal=list(moments), linearDamping=0, angularDamping=0,
                     jointDamping=0, maxJointVelocity=10000)
    omega0_s = np.array(p.getMatrixFromQuaternion(q0)).reshape(3, 3) @ np.array(setup["omega0_b"])
    if link == -1:
        p.resetBaseVelocity(body, [0, 0, 0], list(omega0_s))
    else:
        p.resetJointStateMultiDof(body, 0, targetValue=q0, targetVelocity=list(setup["omega0_b"]))
        # A spherical joint has a motor by default: switched off, so that the joint is free.
        p.setJointMotorControlMultiDof(body, 0, p.POSITION_CONTROL, targetPosition=[0, 0, 0, 1], positionGain=0,
                                       velocityGain=0, force=[0, 0, 0])
    return body, link, frame


def state(body, link, frame):
    """Attitude (x, y, z, w) of the body axes and ω in body axes."""
    if link == -1:
        _, q_inertial = p.getBasePositionAndOrientation(body)
        omega_s = p.getBaseVelocity(body)[1]
    else:
        s = p.getLinkState(body, link, computeLinkVelocity=1, computeForwardKinematics=1)
        q_inertial, omega_s = s[1], s[7]
    q = quat_mul(q_inertial, p.invertTransform([0, 0, 0], frame)[1])
    rot = np.array(p.getMatrixFromQuaternion(q)).reshape(3, 3)
    return q, rot.T @ np.array(omega_s)


def run_scene(setup, rate):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    p.resetSimulation()
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    p.setTimeStep(h)
    p.setGravity(*(setup["gravity_s"] or [0, 0, 0]))
    body, link, frame = build(setup)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    lines = [HEADER]
    seconds = 0.0
    for k in range(frames + 1):
        q, w = state(body, link, frame)
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, q[3], q[0], q[1], q[2], *w)))
        if k == frames:
            break
        for n in range(substeps):
            t = k / out_rate + n * h
            if torque is not None and torque["t_on"] <= t < (torque["t_off"] or float("inf")):
                value = list(torque["value"])
                flags = p.WORLD_FRAME if torque["frame"] == "space" else p.LINK_FRAME
                p.applyExternalTorque(body, link, value, flags)
            start = time.perf_counter()
            p.stepSimulation()
            seconds += time.perf_counter() - start
    return lines, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", required=True, type=pathlib.Path)
    parser.add_argument("--rate", type=float, default=60.0, help="steps per second (a multiple of 60)")
    parser.add_argument("--scene", action="append", help="only these scenes (default: all)")
    args = parser.parse_args()
    p.connect(p.DIRECT)
    name = "pybullet" + ("" if args.rate == 60 else f"_{int(args.rate)}hz")
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
