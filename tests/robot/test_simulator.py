"""The simulator base class (rockly_desktop/robot/sim/simulator.py): outbox, clock, life cycle, speed.

Real threads throughout; tests wait on conditions, and the only timing bounds are generous.
"""
import itertools
import math
import threading
import time

import pytest
from waiting import eventually

from rockly_desktop.robot.sim.sim_world import SimWorld
from rockly_desktop.robot.sim.simulator import RobotSimulator, checked_speed, twist_velocity
from rockly_desktop.sdk import RobotSimulator as SdkRobotSimulator

WAIT = 10.0  # s, generous: how long a condition may take to come true


def lock_is_free(lock):
    """True when another thread can take ``lock`` (so no thread holds it for longer than WAIT)."""
    taken = []

    def take():
        if lock.acquire(timeout=WAIT):
            taken.append(True)
            lock.release()

    thread = threading.Thread(target=take)
    thread.start()
    thread.join()
    return taken == [True]


def lock_is_held(lock):
    """True when another thread cannot take ``lock`` right now."""
    result = []

    def try_take():
        got = lock.acquire(blocking=False)
        if got:
            lock.release()
        result.append(not got)

    thread = threading.Thread(target=try_take)
    thread.start()
    thread.join()
    return result == [True]


class Counter(RobotSimulator):
    """A robot whose one sensor counts ticks; it records what the hooks saw."""

    NAME = "simulated counter"
    TICK_SECONDS = 0.01

    def __init__(self, world, tablet=None, speed=1.0):
        super().__init__(world, tablet, speed)
        self.ticks = 0
        self.advanced = 0.0          # the sum of every dt given to advance()
        self.calls = []              # hook names, in order (the first few)
        self.locked_in_advance = None
        self.heard = []

    def connect(self):
        self.calls.append("connect")
        self.subscribe("/counter/say", lambda message: self.heard.append(message["data"]))

    def advance(self, dt):
        if self.locked_in_advance is None:
            self.locked_in_advance = lock_is_held(self.lock)
            self.calls.append("advance")
        self.ticks += 1
        self.advanced += dt

    def queue_sensors(self):
        if len(self.calls) < 4:
            self.calls.append("queue_sensors")
        self.queue("/counter/ticks", "std_msgs/Int32", {"data": self.ticks, "time": self.time})


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def make_counter(world):
    made = []

    def make(**options):
        sim = Counter(world, **options)
        made.append(sim)
        return sim

    yield make
    for sim in made:
        sim.shutdown()


def test_the_sdk_offers_the_base_class():
    assert SdkRobotSimulator is RobotSimulator


# --- speed --------------------------------------------------------------------------------------


@pytest.mark.parametrize("speed", [1, 0.5, 25, 2.0])
def test_a_positive_speed_is_taken_as_a_float(world, speed):
    sim = RobotSimulator(world, speed=speed)
    assert sim.speed == float(speed) and isinstance(sim.speed, float)


@pytest.mark.parametrize("speed", [0, -1, -0.5, math.inf, math.nan])
def test_a_speed_that_is_not_positive_is_refused(world, speed):
    with pytest.raises(ValueError, match=rf"^the simulation speed must be positive, not {speed!r}$"):
        RobotSimulator(world, speed=speed)


@pytest.mark.parametrize("speed", ["fast", None, True, [2]])
def test_a_speed_that_is_not_a_number_is_refused(speed):
    with pytest.raises(ValueError, match=r"^the simulation speed must be a positive number, not "):
        checked_speed(speed)


# --- life cycle ---------------------------------------------------------------------------------


def test_start_connects_publishes_the_first_sensors_then_starts_the_clock(world, make_counter):
    sim = make_counter()
    sim.start()
    assert sim.calls[:2] == ["connect", "queue_sensors"]
    assert world.latest("/counter/ticks") == {"data": 0, "time": 0.0}  # published before start() returned
    eventually(lambda: sim.ticks >= 3)
    assert sim.calls[2:4] == ["advance", "queue_sensors"]
    assert sim.locked_in_advance is True


def test_starting_twice_is_refused(make_counter):
    sim = make_counter()
    sim.start()
    with pytest.raises(RuntimeError, match="^the simulated counter was already started$"):
        sim.start()
    assert sim.calls.count("connect") == 1


def test_shutdown_stops_the_clock_joins_its_thread_and_ends_the_subscriptions(world, make_counter):
    def clocks():
        return [thread for thread in threading.enumerate() if thread.name == "simulated counter"]

    sim = make_counter()
    sim.start()
    assert len(clocks()) == 1 and clocks()[0].daemon
    eventually(lambda: sim.ticks >= 2)
    world.publish("/counter/say", "std_msgs/String", {"data": "before"})
    sim.shutdown()
    assert clocks() == []  # joined: no thread is left that could tick again
    world.publish("/counter/say", "std_msgs/String", {"data": "after"})  # delivered in this thread, if at all
    assert sim.heard == ["before"]
    sim.shutdown()  # a second shutdown is harmless


def test_shutdown_before_start_is_harmless(make_counter):
    make_counter().shutdown()


def test_the_default_snapshot_is_the_simulated_time(world):
    assert RobotSimulator(world).snapshot() == {"time": 0.0}


# --- simulated time -----------------------------------------------------------------------------


@pytest.mark.parametrize("speed", [1, 20])
def test_simulated_time_runs_speed_times_as_fast_as_the_clock(make_counter, speed):
    sim = make_counter(speed=speed)
    started = time.monotonic()
    sim.start()
    eventually(lambda: sim.ticks >= 30)
    sim.shutdown()
    real = time.monotonic() - started
    assert sim.time == pytest.approx(sim.advanced)   # time is the sum of what advance() was given
    assert 0 < sim.time <= real * speed * 1.01
    assert sim.time >= (real - 0.5) * speed * 0.5    # generous: a loaded machine ticks late, never early


def test_every_tick_publishes_the_advanced_time(world, make_counter):
    messages = []
    world.subscribe("/counter/ticks", messages.append)
    sim = make_counter(speed=5)
    sim.start()
    eventually(lambda: len(messages) >= 10)
    sim.shutdown()
    counts = [message["data"] for message in messages]
    assert counts == list(range(len(counts)))
    times = [message["time"] for message in messages]
    assert times[0] == 0.0 and all(a < b for a, b in itertools.pairwise(times))


# --- the outbox ---------------------------------------------------------------------------------


def test_messages_are_published_outside_the_lock(world, make_counter):
    sim = make_counter()
    free = []
    world.subscribe("/counter/ticks", lambda message: free.append(lock_is_free(sim.lock)) if len(free) < 3 else None)
    sim.start()
    eventually(lambda: len(free) == 3)
    assert free == [True, True, True]


def test_messages_queued_by_many_threads_are_published_in_the_order_they_were_queued(world):
    sim = RobotSimulator(world)
    received = []
    world.subscribe("/numbers", lambda message: received.append(message["n"]))
    numbers = itertools.count()
    threads, per_thread = 6, 200

    def queue_and_flush():
        for _ in range(per_thread):
            with sim.lock:   # take the number and queue it in one step, so numbers are queue order
                sim.queue("/numbers", "std_msgs/Int32", {"n": next(numbers)})
            sim.flush()

    workers = [threading.Thread(target=queue_and_flush) for _ in range(threads)]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join(WAIT)
    assert not any(worker.is_alive() for worker in workers)
    sim.flush()
    assert received == list(range(threads * per_thread))


def test_a_flush_caused_by_a_subscriber_is_sent_after_the_rest_in_order(world):
    sim = RobotSimulator(world)
    received = []

    def on_first(message):
        received.append(message["data"])
        sim.queue("/order", "std_msgs/String", {"data": "caused by first"})
        sim.flush()   # inside the outer flush, in the same thread: no deadlock, nothing overtakes

    world.subscribe("/first", on_first)
    world.subscribe("/order", lambda message: received.append(message["data"]))
    sim.queue("/first", "std_msgs/String", {"data": "first"})
    sim.queue("/order", "std_msgs/String", {"data": "second"})
    done = threading.Thread(target=sim.flush)
    done.start()
    done.join(WAIT)
    assert not done.is_alive()
    assert received == ["first", "second", "caused by first"]


def test_a_flush_with_nothing_queued_publishes_nothing(world):
    sim = RobotSimulator(world)
    sim.flush()
    assert world.topics() == []


@pytest.mark.parametrize("message, velocity", [
    ({"linear": {"x": 0.2}, "angular": {"z": -1}}, (0.2, -1.0)),
    ({}, (0.0, 0.0)),
    ({"linear": None}, (0.0, 0.0)),
    ({"linear": {"x": "fast"}}, None),
    ({"angular": {"z": float("nan")}}, None),
    ({"linear": 3}, None),
    ("stop", None),
    ({"header": {"frame_id": "base_link"}, "twist": {"linear": {"x": 0.1}, "angular": {"z": 0.5}}}, (0.1, 0.5)),
    ({"header": {}, "twist": {}}, (0.0, 0.0)),
    ({"twist": {"linear": {"x": "fast"}}}, None),
])
def test_a_twist_or_a_stamped_twist_gives_its_velocity_or_none(message, velocity):
    assert twist_velocity(message) == velocity
