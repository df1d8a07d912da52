"""Runs release the GIL, and Ctrl-C (SIGINT) interrupts a long run with KeyboardInterrupt."""

import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import eulerdyn

# About 5·10⁹ RK4 steps with a row every 10⁵ steps: minutes of computing, far longer than the watchdog below.
LONG = {
    "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
    "initial": {"omega": [0.3, 0.0, 2.0]},
    "solver": {"method": "rk4", "dt": 1e-7, "t_end": 500.0},
    "output": {"every": 0.01},
}

# A full work-precision study of a long torque-free run: hundreds of runs, minutes in all.
STUDY = {
    "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
    "initial": {"omega": [0.3, 0.0, 2.0]},
    "solver": {"t_end": 2000.0},
    "output": {"every": 0.1},
}


def child_code(call: str) -> str:
    return textwrap.dedent(
        f"""
        import sys, eulerdyn
        print("started", flush=True)
        try:
            {call}
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
            sys.exit(3)
        print("finished", flush=True)
        """
    )


@pytest.mark.parametrize(
    "call",
    [
        f"eulerdyn.run({LONG!r})",
        f"eulerdyn.compare({LONG!r})",
        f"eulerdyn.accuracy({STUDY!r})",
    ],
    ids=["run", "compare", "accuracy"],
)
def test_ctrl_c_interrupts_a_long_command(call):
    child = subprocess.Popen(
        [sys.executable, "-c", child_code(call)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert child.stdout.readline().strip() == "started"
        # Let the child get into the run (parsing the scene takes microseconds), then press Ctrl-C.
        time.sleep(1.0)
        child.send_signal(signal.SIGINT)
        # A generous watchdog: the command itself would take minutes.
        out, err = child.communicate(timeout=120)
    finally:
        child.kill()
    assert out.strip() == "KeyboardInterrupt", (out, err)
    assert child.returncode == 3, err


def test_the_gil_is_released_during_a_run():
    """Another Python thread runs while `run` computes: the main thread counts its own steps while the worker is
    inside the run; with the GIL held throughout, it could take none."""
    scene = dict(LONG, solver={"method": "rk4", "dt": 1e-5, "t_end": 20.0}, output={"every": 0.5})
    inside = threading.Event()
    done = threading.Event()

    def worker():
        inside.set()
        eulerdyn.run(scene)
        done.set()

    thread = threading.Thread(target=worker)
    thread.start()
    inside.wait()
    steps_during_run = 0
    while not done.is_set():
        steps_during_run += 1
        time.sleep(0.001)
    thread.join()
    # 2·10⁶ RK4 steps take a good fraction of a second; the main thread wakes every millisecond meanwhile.
    assert steps_during_run > 20, steps_during_run
