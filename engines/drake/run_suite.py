"""Run eulerdyn's conformance suite in Drake (pydrake's MultibodyPlant) and write each trajectory for `eulerdyn score`.

    python engines/drake/run_suite.py --suite DIR [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a discrete MultibodyPlant with
time_step 1/rate s (Drake's default discrete solver, SAP, lagged approximation; no scene graph, no contact) — one
rigid body, its spatial inertia from the full tensor about C, on a QuaternionFloatingJoint for the torque-free
scenes (gravity zero), on a BallRpyJoint at the pivot for the top (Drake has no ball joint without Euler angles: this
one is singular at pitch ±90°, the body's x axis vertical, which the true top stays 70° away from), the torque pulse
as an ExternallyAppliedSpatialForce on the plant's input port in world axes (a body-axes torque turned by the
attitude at each step) — steps it with a Simulator and writes, at the suite's 60 Hz, DIR/drake[_<rate>hz]/NAME.csv
with t, q_w..q_z (body -> world: a free body's state quaternion normalised, as Drake's pose does, for Drake's step
lets it drift off unit norm) and omega_x..z (body axes: Drake's angular velocity is in world axes, turned by R^T).
A trajectory that stops being finite, or that Drake stops (the ball joint's singularity), ends at its last finite
row, with a note on stderr.
"""

import pathlib
import sys
import time

import numpy as np
from pydrake.common.eigen_geometry import Quaternion
from pydrake.math import RollPitchYaw, RotationMatrix
from pydrake.multibody.math import SpatialForce
from pydrake.multibody.plant import ExternallyAppliedSpatialForce, MultibodyPlant
from pydrake.multibody.tree import BallRpyJoint, QuaternionFloatingJoint, RotationalInertia, SpatialInertia
from pydrake.systems.analysis import Simulator

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import suite_io  # noqa: E402  (engines/suite_io.py)

#: The engine variant this adapter writes (no option chooses among variants).
VARIANTS = {None: "drake"}


def build(setup, h):
    """The plant of a scene, its body and joint: the body frame is the scene's body axes, its origin at C or at the
    pivot."""
    plant = MultibodyPlant(time_step=h)
    plant.mutable_gravity_field().set_gravity_vector(setup["gravity_s"] or [0.0, 0.0, 0.0])
    i = np.array(setup["inertia_c_b"], dtype=float)
    inertia_c = RotationalInertia(i[0, 0], i[1, 1], i[2, 2], i[0, 1], i[0, 2], i[1, 2])
    pivot = setup["pivot_from_c_b"]
    c_from_origin = -np.array(pivot, dtype=float) if pivot else np.zeros(3)
    body = plant.AddRigidBody("body", SpatialInertia.MakeFromCentralInertia(setup["mass"], c_from_origin, inertia_c))
    if pivot is None:
        joint = plant.AddJoint(QuaternionFloatingJoint("free", plant.world_frame(), body.body_frame()))
    else:
        joint = plant.AddJoint(BallRpyJoint("ball", plant.world_frame(), body.body_frame()))
    plant.Finalize()
    return plant, body, joint


def set_initial(setup, plant, context, joint):
    """q0 and omega0 into the context (Drake's generalized velocity is ω in world axes for both joints)."""
    q0 = np.array(setup["q0_wxyz"], dtype=float)
    rot = RotationMatrix(Quaternion(q0 / np.linalg.norm(q0)))
    omega0_s = rot.matrix() @ np.array(setup["omega0_b"], dtype=float)
    if isinstance(joint, QuaternionFloatingJoint):
        plant.SetPositions(context, np.concatenate([q0, np.zeros(3)]))
        plant.SetVelocities(context, np.concatenate([omega0_s, np.zeros(3)]))
    else:
        joint.set_angles(context, RollPitchYaw(rot).vector())
        joint.set_angular_velocity(context, omega0_s)


def state(plant, context, body, joint):
    """Attitude (w, x, y, z) of the body axes and ω in body axes: a free body's own quaternion normalised (Drake's
    step does not keep it unit; its pose normalises it), the top's from its pose."""
    rot = plant.EvalBodyPoseInWorld(context, body).rotation()
    if isinstance(joint, QuaternionFloatingJoint):
        q = plant.GetPositions(context)[0:4]
        q = q / np.linalg.norm(q)
    else:
        q = rot.ToQuaternion().wxyz()
    omega_s = plant.EvalBodySpatialVelocityInWorld(context, body).rotational()
    return q, rot.matrix().T @ omega_s


def applied_force(torque, t, plant, context, body):
    """The scene's torque pulse at time t as the plant's applied spatial forces (world axes, a pure couple)."""
    value = np.zeros(3)
    if suite_io.torque_on(torque, t):
        value = np.array(torque["value"], dtype=float)
        if torque["frame"] == "body":
            value = plant.EvalBodyPoseInWorld(context, body).rotation().matrix() @ value
    force = ExternallyAppliedSpatialForce()
    force.body_index = body.index()
    force.p_BoBq_B = np.zeros(3)
    force.F_Bq_W = SpatialForce(tau=value, f=np.zeros(3))
    return [force]


def run_scene(setup, rate, _variant=None):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds spent stepping the engine."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    plant, body, joint = build(setup, h)
    simulator = Simulator(plant)
    context = simulator.get_mutable_context()
    set_initial(setup, plant, context, joint)
    port = plant.get_applied_spatial_force_input_port()
    torque = setup["torque"]
    port.FixValue(context, applied_force(None, 0.0, plant, context, body))
    simulator.Initialize()
    frames = int(round(setup["t_end"] * out_rate))
    seconds = 0.0
    lines = [suite_io.HEADER]
    for k in range(frames + 1):
        q, w = state(plant, context, body, joint)
        if not np.all(np.isfinite(np.concatenate([q, w]))):
            break
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, *q, *w)))
        if k == frames:
            break
        try:
            for n in range(substeps):
                if torque is not None:
                    port.FixValue(context, applied_force(torque, (k * substeps + n) * h, plant, context, body))
                start = time.perf_counter()
                simulator.AdvanceTo((k * substeps + n + 1) * h)
                seconds += time.perf_counter() - start
        except RuntimeError:
            # Drake refuses to go on (the ball joint's pitch at ±90°, or its solver meeting NaN): the file ends here.
            seconds += time.perf_counter() - start
            break
    if len(lines) == frames + 2:
        # The plant's step is a discrete or (as in current Drake) an unrestricted update: one per step either way.
        updates = simulator.get_num_discrete_updates() + simulator.get_num_unrestricted_updates()
        if updates != frames * substeps:
            raise RuntimeError(f"{setup['name']}: {updates} updates of the plant, expected {frames * substeps}")
    return lines, seconds


if __name__ == "__main__":
    suite_io.main(__doc__, run_scene, VARIANTS)
