"""Run eulerdyn's conformance suite in MuJoCo and write each trajectory for `eulerdyn score --suite`.

    python engines/mujoco/run_suite.py --suite DIR [--integrator Euler|implicitfast|RK4 ...] [--rate HZ]

For each scene DIR/NAME.json (written by `eulerdyn suite --out DIR`) builds a MuJoCo model — a free body (a
freejoint, gravity off) for the torque-free scenes, a ball joint at the pivot for the top, the torque pulse as
`xfrc_applied` (world axes) — steps it at 1/rate s with the chosen integrator and writes, at the suite's 60 Hz,
DIR/mujoco_<integrator>[_<rate>hz]/NAME.csv with t, q_w..q_z (body -> world) and omega_x..z (body axes: MuJoCo's
qvel of a free or ball joint is the angular velocity in the body's local frame). `implicitfast` is MuJoCo's
recommended integrator (implicit in the velocity-dependent forces, without their Coriolis part's derivative).
`run_scene` also returns the wall time of the `mj_step` calls (for the work-precision figure).
"""

import pathlib
import sys
import time

import mujoco
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import suite_io  # noqa: E402  (engines/suite_io.py)

VARIANTS = {"Euler": "mujoco_euler", "implicitfast": "mujoco_implicitfast", "RK4": "mujoco_rk4"}


def model_xml(setup, timestep, integrator):
    """The MJCF of a scene: one body whose frame is the scene's body axes, its origin at C or at the pivot."""
    inertia = np.array(setup["inertia_c_b"])
    full = " ".join(repr(float(v)) for v in (inertia[0, 0], inertia[1, 1], inertia[2, 2],
                                              inertia[0, 1], inertia[0, 2], inertia[1, 2]))
    gravity = setup["gravity_s"] or [0.0, 0.0, 0.0]
    pivot = setup["pivot_from_c_b"]
    com = " ".join(repr(-float(v)) for v in pivot) if pivot else "0 0 0"
    joint = '<joint name="j" type="ball" pos="0 0 0"/>' if pivot else '<freejoint name="j"/>'
    return f"""
<mujoco>
  <option timestep="{timestep!r}" integrator="{integrator}" gravity="{' '.join(map(repr, gravity))}">
    <flag contact="disable"/>
  </option>
  <worldbody>
    <body name="b" pos="0 0 0">
      {joint}
      <inertial pos="{com}" mass="{setup['mass']!r}" fullinertia="{full}"/>
    </body>
  </worldbody>
</mujoco>"""


def run_scene(setup, rate, integrator):
    """The trajectory of one scene as CSV lines at the suite's rate, and the seconds its steps took."""
    out_rate = setup["rate_hz"]
    substeps = int(round(rate / out_rate))
    model = mujoco.MjModel.from_xml_string(model_xml(setup, 1.0 / (out_rate * substeps), integrator))
    data = mujoco.MjData(model)
    free = setup["pivot_from_c_b"] is None
    q_at, w_at = (3, 3) if free else (0, 0)
    data.qpos[q_at:q_at + 4] = setup["q0_wxyz"]
    data.qvel[w_at:w_at + 3] = setup["omega0_b"]
    torque = setup["torque"]
    body = model.body("b").id
    frames = int(round(setup["t_end"] * out_rate))
    lines = [suite_io.HEADER]
    seconds = 0.0
    for k in range(frames + 1):
        q = data.qpos[q_at:q_at + 4]
        w = data.qvel[w_at:w_at + 3]
        lines.append(",".join(repr(float(v)) for v in (k / out_rate, *q, *w)))
        if k == frames:
            break
        start = time.perf_counter()
        for n in range(substeps):
            # The step's time from its index: data.time sums h and drifts (60 steps of 1/60 s end at
            # 1.0000000000000013, 90 at 1.4999999999999996), which would move the pulse's edges by a step.
            t = k / out_rate + n / (out_rate * substeps)
            data.xfrc_applied[body, 3:6] = applied_torque(torque, t, data, body)
            mujoco.mj_step(model, data)
        seconds += time.perf_counter() - start
    return lines, seconds


def applied_torque(torque, t, data, body):
    """The scene's torque pulse at time t, in world axes (a body-axes torque turned by the attitude)."""
    if not suite_io.torque_on(torque, t):
        return np.zeros(3)
    value = np.array(torque["value"])
    if torque["frame"] == "body":
        value = data.xmat[body].reshape(3, 3) @ value
    return value


if __name__ == "__main__":
    suite_io.main(__doc__, run_scene, VARIANTS, option="integrator")
