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

import argparse
import json
import pathlib
import time

import numpy as np
import rapier3d as r

HEADER = "t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z"
NAMES = {"on": "rapier", "off": "rapier_nogyro", "default": "rapier_default"}


def principal(inertia):
    """Principal moments and the principal frame (w, x, y, z) of a symmetric tensor, the frame right-handed."""
    moments, axes = np.linalg.eigh(np.array(inertia))
    if np.linalg.det(axes) < 0:
        axes[:, 2] *= -1
    return moments, matrix_to_quat(axes)


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


def build(setup, h, gyroscopic):
    """The world of a scene stepping at h s and its body's handle (for the top: jointed to a fixed body)."""
    world = r.PhysicsWorld(gravity=setup["gravity_s"] or [0.0, 0.0, 0.0])
    world.integration_parameters.dt = h
    moments, frame = principal(setup["inertia_c_b"])
    mass = r.MassProperties([0.0, 0.0, 0.0], setup["mass"], list(moments), r.Rotation3(*frame))
    q0 = setup["q0_wxyz"]
    rot0 = quat_to_matrix(q0)
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
    return q, quat_to_matrix(np.array(q) / np.linalg.norm(q)).T @ omega_s


def run_scene(setup, rate, gyroscopic):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    h = 1.0 / (out_rate * substeps)
    world, body = build(setup, h, gyroscopic)
    torque = setup["torque"]
    frames = int(round(setup["t_end"] * out_rate))
    seconds = 0.0
    lines = [HEADER]
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
                if torque["t_on"] <= t < (torque["t_off"] if torque["t_off"] is not None else float("inf")):
                    value = np.array(torque["value"])
                    if torque["frame"] == "body":
                        value = quat_to_matrix(state(world, body)[0]) @ value
                    rb.add_torque(list(value))
            start = time.perf_counter()
            world.step()
            seconds += time.perf_counter() - start
    return lines, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", required=True, type=pathlib.Path)
    parser.add_argument("--gyroscopic", action="append", choices=["on", "off", "default"])
    parser.add_argument("--rate", type=float, default=60.0, help="steps per second (a multiple of 60)")
    parser.add_argument("--scene", action="append", help="only these scenes (default: all)")
    args = parser.parse_args()
    for gyroscopic in args.gyroscopic or ["on", "off", "default"]:
        name = NAMES[gyroscopic] + ("" if args.rate == 60 else f"_{int(args.rate)}hz")
        out = args.suite / name
        out.mkdir(parents=True, exist_ok=True)
        for path in sorted(args.suite.glob("*.json")):
            if args.scene and path.stem not in args.scene:
                continue
            lines, _ = run_scene(json.loads(path.read_text()), args.rate, gyroscopic)
            (out / f"{path.stem}.csv").write_text("\n".join(lines) + "\n")
        print(f"wrote {out}")


if __name__ == "__main__":
    main()
