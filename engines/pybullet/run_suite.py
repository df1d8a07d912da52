"""Run eulerdyn's conformance suite in PyBullet (Bullet Physics) and write each trajectory for `eulerdyn score`.

    python engines/pybullet/run_suite.py --suite DIR [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a Bullet multibody — a free base
(gravity off) for the torque-free scenes, a base fixed at the pivot with a spherical joint for the top, the
torque pulse by applyExternalTorque in world axes — with no damping, steps it at 1/rate s and writes, at the
suite's 60 Hz, DIR/pybullet[_<rate>hz]/NAME.csv with t, q_w..q_z (body -> world) and omega_x..z (body axes).
A full inertia tensor is given to Bullet as its principal moments and the principal frame (numpy's eigh).
`run_scene` also returns the wall time of the `stepSimulation` calls (for the work-precision figure).
"""

import pathlib
import sys
import time

import numpy as np
import pybullet as p

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import suite_io  # noqa: E402  (engines/suite_io.py)

#: The engine variant this adapter writes (no option chooses among variants).
VARIANTS = {None: "pybullet"}


def quat_mul(a, b):
    """The product of quaternions in Bullet's order (x, y, z, w)."""
    return p.multiplyTransforms([0, 0, 0], a, [0, 0, 0], b)[1]


def principal(inertia):
    """Principal moments and the principal frame (x, y, z, w: Bullet's order) of a symmetric tensor."""
    moments, axes = suite_io.principal(inertia)
    w, x, y, z = suite_io.matrix_to_quat(axes)
    return moments, [x, y, z, w]


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


def run_scene(setup, rate, _variant=None):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    if not p.isConnected():
        p.connect(p.DIRECT)
    p.resetSimulation()
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    p.setTimeStep(h)
    p.setGravity(*(setup["gravity_s"] or [0, 0, 0]))
    body, link, frame = build(setup)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    lines = [suite_io.HEADER]
    seconds = 0.0
    for k in range(frames + 1):
        q, w = state(body, link, frame)
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, q[3], q[0], q[1], q[2], *w)))
        if k == frames:
            break
        for n in range(substeps):
            t = k / out_rate + n * h
            if suite_io.torque_on(torque, t):
                value = list(torque["value"])
                flags = p.WORLD_FRAME if torque["frame"] == "space" else p.LINK_FRAME
                p.applyExternalTorque(body, link, value, flags)
            start = time.perf_counter()
            p.stepSimulation()
            seconds += time.perf_counter() - start
    return lines, seconds


if __name__ == "__main__":
    suite_io.main(__doc__, run_scene, VARIANTS)
