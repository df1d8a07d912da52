"""What a Python moment callback costs: the same scene run with the built-in sine torque and with a Python callable
computing that torque (`eulerdyn.run(scene, moment=f)`); the best of 5 runs each, per run and per evaluation.

    python python/bench/moment_cost.py      # with eulerdyn installed (pip install ./python)
"""

import math
import time

import eulerdyn

VALUE, FREQ_HZ, PHASE_DEG = (0.3, -0.2, 0.5), 0.7, 30.0
SCENE = {
    "body": {"mass": 2.0, "inertia": [1.0, 2.0, 3.0]},
    "initial": {"omega": [0.1, 1.5, 0.2]},
    "solver": {"t_end": 100.0},
    "output": {"every": 0.1},
}


def sine(t, q, omega_b):
    factor = math.sin(2.0 * math.pi * FREQ_HZ * t + math.radians(PHASE_DEG))
    return (VALUE[0] * factor, VALUE[1] * factor, VALUE[2] * factor)


def best(run, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        df = run()
        times.append(time.perf_counter() - start)
    return min(times), df.attrs["report"]


def main():
    builtin = dict(SCENE, effect=[{"type": "torque", "profile": "sine", "freq_hz": FREQ_HZ, "phase_deg": PHASE_DEG,
                                   "value": list(VALUE)}])
    t_builtin, r_builtin = best(lambda: eulerdyn.run(builtin))
    t_python, r_python = best(lambda: eulerdyn.run(SCENE, moment=sine))
    calls = r_python["evals"] + r_python["rows"]  # each row's moment columns call it once more
    print(f"built-in sine: {t_builtin * 1e3:8.2f} ms per run, {r_builtin['evals']} evaluations, "
          f"{t_builtin / r_builtin['evals'] * 1e9:6.0f} ns per evaluation")
    print(f"Python sine:   {t_python * 1e3:8.2f} ms per run, {calls} calls, "
          f"{t_python / calls * 1e9:6.0f} ns per call; the callback adds "
          f"{(t_python - t_builtin) / calls * 1e9:6.0f} ns per call ({t_python / t_builtin:.0f} x the run)")


if __name__ == "__main__":
    main()
