"""Watching an in-process simulated robot from tests: its world's messages, its snapshots, its pauses."""
import threading

TIMEOUT = 20.0  # s, generous: only how long a failing test waits


def eventually_in(world, predicate, timeout=TIMEOUT):
    """Wait until ``predicate()`` holds, checking again at every message the world publishes."""
    assert world.wait_for(predicate, timeout), "the simulated robot never got there"


def later(world, sim, sim_seconds=1.0):
    """The snapshot after ``sim_seconds`` more of simulated time."""
    start = sim.snapshot()["time"]
    eventually_in(world, lambda: sim.snapshot()["time"] >= start + sim_seconds)
    return sim.snapshot()


def pose(snapshot):
    """``(x, y, theta)`` of a snapshot."""
    return snapshot["x"], snapshot["y"], snapshot["theta"]


class HoldWatcher:
    """``control.on_hold`` as the runner sets it, noting the robot's state when a paused command holds."""

    def __init__(self, control, sim):
        self._control, self._sim = control, sim
        self.held = threading.Event()
        self.snapshots = []

    def __call__(self):
        self.snapshots.append(self._sim.snapshot())
        self.held.set()
        self._control.wait_for_release()

    def wait_until_held(self):
        assert self.held.wait(TIMEOUT), "the command never held for the pause"
        return self.snapshots[0]
