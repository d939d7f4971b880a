"""``RobotSimulator``: the scaffolding every profile's simulator shares.

A simulator lives in a ``SimWorld`` (``robot/sim/sim_world.py``): it subscribes to the robot's
command topics, serves its services and actions, and publishes what its sensors report
while simulated time runs ``speed`` times as fast as the clock. This base class owns the
parts that are the same for every robot:

* the **lock** (``self.lock``, re-entrant) that guards the robot's state;
* the **outbox**: ``queue(topic, type, message)`` adds a message under the lock and
  ``flush()`` publishes what is queued after the lock is released, in the order it was
  queued. Subscriber callbacks run in the publisher's thread, so publishing while holding
  the lock could deadlock with a program's thread; a flush that a subscriber causes inside
  another flush in the same thread is sent by the outer one, so no two flushes interleave;
* the **clock**: a daemon thread that every ``TICK_SECONDS`` of real time advances simulated
  time by the real time elapsed times ``speed``, calls ``advance(dt)`` and
  ``queue_sensors()`` under the lock, then flushes;
* the **life cycle**: ``start()`` calls ``connect()``, publishes the first sensor messages
  and starts the clock (once only); ``shutdown()`` stops the clock, waits for its thread and
  ends the subscriptions made with ``subscribe()``;
* **stepped time**: ``start(clock=False)`` starts no clock thread; whoever drives the simulator
  (a lesson's check, ``rockly_desktop/lessons/stepping.py``) calls ``step(dt)``, which ticks at
  once and returns when every action goal's thread has looked at the tick (a goal's thread
  follows the simulation with ``next_tick(cancelled)``, never with a fixed sleep), so simulated
  time runs as fast as the machine allows and a goal ends at the tick its task ended.

A subclass overrides the hooks ``connect()``, ``advance(dt)``, ``queue_sensors()``,
``snapshot()``, ``reset()`` and ``place(x, y, theta)`` (a lesson's start pose), and sets ``NAME``,
``TICK_SECONDS`` and ``WORLD_ID`` (the name lessons give its world). A robot with a solid
world declares it as data (``robot/sim/world_map.py``) and lets it stop the robot's motions.
"""
import math
import numbers
import threading
import time

from rockly_desktop.robot.wrappers.velocity_messages import is_velocity_number


def checked_speed(speed) -> float:
    """``speed`` as a float; ValueError unless it is a finite number above zero."""
    if isinstance(speed, bool) or not isinstance(speed, numbers.Real):
        raise ValueError(f"the simulation speed must be a positive number, not {speed!r}")
    if not (math.isfinite(speed) and speed > 0):
        raise ValueError(f"the simulation speed must be positive, not {speed!r}")
    return float(speed)


def twist_velocity(message):
    """``(linear.x, angular.z)`` of a ``geometry_msgs/Twist`` (or ``TwistStamped``) dict (missing parts
    are 0), or None when the message is no Twist or holds a value that is not a finite number.

    A text ("1.0") or a bool is no number here: a real ROS refuses it in a float64 field, so a
    simulated robot must not drive on it either.
    """
    if isinstance(message, dict) and isinstance(message.get("twist"), dict):
        message = message["twist"]
    try:
        linear = (message.get("linear") or {}).get("x", 0.0)
        angular = (message.get("angular") or {}).get("z", 0.0)
    except AttributeError:
        return None
    if not (is_velocity_number(linear) and is_velocity_number(angular)):
        return None
    return (float(linear), float(angular)) if math.isfinite(linear) and math.isfinite(angular) else None


class RobotSimulator:
    """A simulated robot in ``world``: lock, ordered outbox, clock thread and life cycle.

    Rockly creates a simulator as ``Class(world, tablet=..., speed=...)``, calls
    ``start()``, then ``snapshot()`` about 30 times a second, and ``shutdown()`` at the end.
    ``tablet`` answers the questions the robot asks a person (``ask``/``notify``; None when
    nobody can answer); ``speed`` makes simulated time run that many times as fast as the
    clock (a positive number).
    """

    NAME = "simulated robot"  # names the clock thread and the simulator in messages
    solid_world = None  # the World (robot/sim/world_map.py) it moves in, if it has a solid one: recordings name it
    TICK_SECONDS = 0.1        # real seconds between two ticks of the clock
    WORLD_ID = "world"      # the name a lesson gives the world it moves in
    FOLLOW_SECONDS = 0.01     # real seconds a goal's thread waits for the next tick at most
    STEP_WAIT_SECONDS = 0.25  # real seconds a step waits at most for the goal threads (a loaded machine's
                              # scheduling; a goal that does not follow with next_tick costs this a tick)

    def __init__(self, world, tablet=None, speed=1.0):
        self.speed = checked_speed(speed)
        self.world = world
        self.tablet = tablet
        self.lock = threading.RLock()
        self._publishing = threading.RLock()
        self._flushing = False   # True while this thread (the one holding _publishing) publishes the outbox
        self._outbox = []
        self._time = 0.0
        self._stopping = threading.Event()
        self._thread = None
        self._unsubscribe = []
        self._ticked = threading.Condition()   # a tick happened; a goal's thread waits for the next
        self._ticks = 0
        self._looking = {}                     # tick number -> goal threads waiting after it

    # --- the hooks a robot overrides ----------------------------------------------------

    def connect(self):
        """Subscribe to the robot's topics and advertise its services and actions (called by ``start()``)."""

    def advance(self, dt):
        """Let ``dt`` simulated seconds pass (called holding the lock; ``self.time`` already includes them)."""

    def queue_sensors(self):
        """Queue what the sensors publish now (called holding the lock, at start and after every tick)."""

    def snapshot(self) -> dict:
        """The robot's state for its view and for tests: a new dict, quick to make."""
        return {"time": self.time}

    def reset(self):
        """Put the robot back as it started: its start pose, standing still, every part (arm, head,
        battery, trail...) as at the start, goals in progress ended; sends the new state at once.

        Called from the window's thread while no program runs; takes the lock itself.
        """
        raise NotImplementedError(f"the {self.NAME} cannot be put back")

    def place(self, x: float, y: float, theta: float):
        """Put the robot at (x, y) (map metres) facing ``theta`` (radians), standing still, before a run
        starts (a lesson's start pose); ValueError when it does not fit there."""
        raise NotImplementedError(f"the {self.NAME} cannot be placed")

    # --- life cycle -------------------------------------------------------------------

    def start(self, clock: bool = True):
        """Connect, publish the first sensor messages, start the clock (none with ``clock=False``:
        simulated time then passes only by ``step(dt)``). A second start is refused."""
        if self._thread is not None:
            raise RuntimeError(f"the {self.NAME} was already started")
        self._thread = threading.Thread(target=self._run, name=self.NAME, daemon=True)
        self.connect()
        with self.lock:
            self.queue_sensors()
        self.flush()
        if clock:
            self._thread.start()

    def shutdown(self):
        """Stop the clock, wait for its thread, and end the subscriptions made with ``subscribe()``."""
        self._stopping.set()
        thread = self._thread
        if thread is not None and thread.is_alive() and thread is not threading.current_thread():
            thread.join()
        unsubscribes, self._unsubscribe = self._unsubscribe, []
        for unsubscribe in unsubscribes:
            unsubscribe()

    def subscribe(self, topic, callback):
        """Call ``callback(message)`` for every message on ``topic`` until ``shutdown()``."""
        unsubscribe = self.world.subscribe(topic, callback)
        self._unsubscribe.append(unsubscribe)
        return unsubscribe

    # --- simulated time -------------------------------------------------------------------

    @property
    def time(self) -> float:
        """Simulated seconds since the start."""
        with self.lock:
            return self._time

    def _run(self):
        last = time.monotonic()
        while not self._stopping.wait(self.TICK_SECONDS):
            now = time.monotonic()
            self._tick((now - last) * self.speed)
            last = now

    def _tick(self, dt):
        with self.lock:
            self._time += dt
            self.advance(dt)
            self.queue_sensors()
        self.flush()
        with self._ticked:
            self._ticks += 1
            self._ticked.notify_all()

    def step(self, dt: float, goals_running=lambda: 0):
        """Let ``dt`` simulated seconds pass now (a simulator started with ``clock=False``), then wait
        until ``goals_running()`` goal threads (SimWorld.running_goals) look at the new state again."""
        self._tick(dt)
        deadline = time.monotonic() + self.STEP_WAIT_SECONDS
        with self._ticked:
            tick = self._ticks
            # goals_running() changes without telling this condition: look again every 0.5 ms
            while self._looking.get(tick, 0) < goals_running() and time.monotonic() < deadline:
                self._ticked.wait(0.0005)

    def next_tick(self, cancelled: threading.Event):
        """For an action goal's thread following the simulation: wait for the next tick (at most
        ``FOLLOW_SECONDS``) or until ``cancelled`` is set. A stepped clock waits for it to get here."""
        with self._ticked:
            tick = self._ticks
            self._looking[tick] = self._looking.get(tick, 0) + 1
            self._ticked.notify_all()
            try:
                self._ticked.wait_for(lambda: self._ticks != tick or cancelled.is_set(), self.FOLLOW_SECONDS)
            finally:
                self._looking[tick] -= 1
                if not self._looking[tick]:
                    del self._looking[tick]

    # --- publishing: queued under the lock, sent outside it, in order -----------------------

    def queue(self, topic, msg_type, message):
        """Queue ``message`` for ``topic``; the next ``flush()`` publishes it, after everything queued before."""
        with self.lock:
            self._outbox.append((topic, msg_type, message))

    def flush(self):
        """Publish everything queued, in order; call it without holding the lock."""
        with self._publishing:
            if self._flushing:   # a subscriber of ours flushed again: the loop below sends its messages
                return
            self._flushing = True
            try:
                while True:
                    with self.lock:
                        messages, self._outbox = self._outbox, []
                    if not messages:
                        return
                    for message in messages:
                        self.world.publish(*message)
            finally:
                self._flushing = False
