"""Run eulerdyn's conformance suite in Rapier and write each trajectory for `eulerdyn score --suite`.

    python engines/rapier/run_suite.py --suite DIR [--gyroscopic on|off|default ...] [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a Rapier world (PyPI `rapier3d`, its
f32 build) — one dynamic rigid body without colliders, its frame the scene's body axes and its origin at C, the
mass properties given as the principal moments and the principal frame (numpy's eigh), no damping, never asleep;
for the top a fixed body and a spherical impulse joint at the pivot; the torque pulse by add_torque in world
axes (Rapier keeps a user torque until reset_torques: it is reset and set afresh before every step) — steps it
at 1/rate s and writes, at the suite's 60 Hz, DIR/rapier[_nogyro|_default][_<rate>hz]/NAME.csv with t, q_w..q_z
(body -> world) and omega_x..z (body axes: Rapier's angvel is in world axes, turned back by the attitude).
`--gyroscopic on` (rapier) and `off` (rapier_nogyro) set the body's gyroscopic forces and allow fast rotation;
`default` (rapier_default) leaves both at the engine's defaults: in rapier3d 0.36 gyroscopic forces on (off up to
0.34) and the rotation in a step capped at pi/4, i.e. |omega| <= 47 rad/s at 60 Hz. `run_scene` also returns
the wall time of the `PhysicsWorld.step` calls (for the work-precision figure).
"""

import pathlib
import sys
import time

import numpy as np
import rapier3d as r

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import suite_io  # noqa: E402  (engines/suite_io.py)

VARIANTS = {"on": "rapier", "default": "rapier_default", "off": "rapier_nogyro"}


def build(setup, h, gyroscopic):
    """The world of a scene stepping at h s and its body's handle (for the top: jointed to a fixed body)."""
    world = r.PhysicsWorld(gravity=setup["gravity_s"] or [0.0, 0.0, 0.0])
    world.integration_parameters.dt = h
    moments, axes = suite_io.principal(setup["inertia_c_b"])
    mass = r.MassProperties([0.0, 0.0, 0.0], setup["mass"], list(moments), r.Rotation3(*suite_io.matrix_to_quat(axes)))
    q0 = setup["q0_wxyz"]
    rot0 = suite_io.quat_to_matrix(q0)
    omega0_s = rot0 @ np.array(setup["omega0_b"])
    pivot = setup["pivot_from_c_b"]
    # C placed so that the pivot is at the world origin, moving with the rigid motion about it.
    c_from_pivot_s = -rot0 @ np.array(pivot) if pivot is not None else np.zeros(3)
    builder = (r.RigidBody.dynamic()
               .position(r.Isometry3(list(c_from_pivot_s), r.Rotation3(*q0)))
               .angvel(list(omega0_s)).linvel(list(np.cross(omega0_s, c_from_pivot_s)))
               .additional_mass_properties(mass)
               .linear_damping(0.0).angular_damping(0.0).can_sleep(False))
    if gyroscopic != "default":
        # Unless allowed to rotate fast, a body's rotation in a step is capped at pi/4 (for CCD).
        builder = builder.gyroscopic_forces(gyroscopic == "on").allow_fast_rotation(True)
    body = world.add_body(builder)
    if pivot is not None:
        base = world.add_body(r.RigidBody.fixed())
        joint = r.SphericalJointBuilder().local_anchor1([0.0, 0.0, 0.0]).local_anchor2(list(pivot)).build()
        world.impulse_joints.insert(base, body, joint)
    return world, body


def state(world, body):
    """Attitude (w, x, y, z) of the body axes and omega in body axes."""
    rb = world.rigid_bodies[body]
    rotation = rb.rotation
    q = (rotation.w, rotation.i, rotation.j, rotation.k)
    omega_s = np.array(rb.angvel.to_tuple())
    return q, suite_io.quat_to_matrix(np.array(q) / np.linalg.norm(q)).T @ omega_s


def run_scene(setup, rate, gyroscopic):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    world, body = build(setup, h, gyroscopic)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    seconds = 0.0
    lines = [suite_io.HEADER]
    for k in range(frames + 1):
        q, w = state(world, body)
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, *q, *w)))
        if k == frames:
            break
        for n in range(substeps):
            t = k / out_rate + n * h
            if torque is not None:
                # User torques persist in Rapier: set the pulse afresh before every step.
                rb = world.rigid_bodies[body]
                rb.reset_torques()
                if suite_io.torque_on(torque, t):
                    value = np.array(torque["value"])
                    if torque["frame"] == "body":
                        value = suite_io.quat_to_matrix(state(world, body)[0]) @ value
                    rb.add_torque(list(value))
            start = time.perf_counter()
            world.step()
            seconds += time.perf_counter() - start
    return lines, seconds


if __name__ == "__main__":
    suite_io.main(__doc__, run_scene, VARIANTS, option="gyroscopic")
