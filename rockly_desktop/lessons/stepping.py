"""Simulated time as fast as the machine allows: the simulator ticks only when the program waits.

A check runs the profile's simulator without its clock thread (``RobotSimulator.start(clock=False)``).
Whenever the program waits (a ``wait`` block, a drive waiting for the odometry, a goal, a message),
``SteppedBackend`` steps the simulator tick by tick (the profile's own ``TICK_SECONDS`` of simulated time
each, as at speed 1) until what it waits for has happened, and each step returns once every action
goal's thread has looked at it (``RobotSimulator.step``): a 20 s drive is 600 steps, done in
milliseconds, and ends at the same simulated moment as in real time. A block the program enters costs
``BLOCK_SECONDS`` of simulated time, so a loop that only reads sensors still lets time pass and meets
the time limit.
"""
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.robot.sim.sim_world import SimBackend

BLOCK_SECONDS = 0.001    # simulated seconds a block costs (a real robot's program takes about that per block)


class SteppedClock:
    """The simulator's time, moved on by ``advance``; ``on_tick()`` after every step, ``on_limit()`` once
    when ``limit`` simulated seconds have passed."""

    def __init__(self, simulator, world, limit: float, on_tick, on_limit):
        self.simulator = simulator
        self.world = world
        self.tick = float(simulator.TICK_SECONDS)
        self.limit = float(limit)
        self.on_tick = on_tick
        self.on_limit = on_limit
        self.reached_limit = False
        self._spent = 0.0

    @property
    def time(self) -> float:
        """Simulated seconds since the start."""
        return self.simulator.time

    def advance(self, dt: float):
        """Let ``dt`` simulated seconds pass (one step of the simulator)."""
        self.simulator.step(dt, self.world.running_goals)
        self.on_tick()
        if not self.reached_limit and self.time >= self.limit:
            self.reached_limit = True
            self.on_limit()

    def spend(self, seconds: float):
        """Count ``seconds`` of the program's own work; a whole tick of it is stepped."""
        self._spent += seconds
        if self._spent >= self.tick:
            self._spent -= self.tick
            self.advance(self.tick)


class SteppedBackend(SimBackend):
    """A SimBackend whose waits step the simulator instead of waiting for the clock."""

    def __init__(self, clock: SteppedClock, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.clock = clock

    def sleep(self, seconds: float) -> None:
        """Let ``seconds`` of simulated time pass; a stop request raises ProgramStopped."""
        clock = self.clock
        end = clock.time + max(0.0, seconds)
        while end - clock.time > 1e-9:
            self.interrupt.check()
            clock.advance(min(clock.tick, end - clock.time))

    def wait_until(self, predicate, timeout: float) -> bool:
        """Step until ``predicate()`` holds (True) or ``timeout`` simulated seconds passed (False)."""
        clock = self.clock
        end = clock.time + timeout
        while True:
            self.interrupt.check()
            if predicate():
                return True
            if clock.time >= end:
                return False
            clock.advance(clock.tick)


class SteppedRobot(SimulatedRobot):
    """The profile's simulator as a robot link whose time is stepped (``clock``, set by ``use_clock``);
    its state store is filled only for a recording (``keep_state``): no state panel watches a check."""

    def __init__(self, profile, tablet=None, keep_state: bool = False):
        super().__init__(profile, tablet=tablet, clock=False)
        if not keep_state:
            self.world.untap(self.state.record)
        self.clock = None

    def use_clock(self, clock: SteppedClock):
        """Step time with ``clock`` from now on."""
        self.clock = clock

    def backend(self, interrupt):
        """A SteppedBackend on the simulated world (as ``SimulatedRobot.backend``, its waits stepped)."""
        return SteppedBackend(self.clock, self.world, interrupt, self._listens, self.profile.ros_types,
                              published=self._published)
