"""The TurtleBot's commands, bound as ``robot`` in programs.

They read the same whether generated from blocks or written by hand::

    for _ in range(20):
        if robot.obstacle_closer_than(0.4, 'ahead'):
            robot.turn(90, 'left')
        else:
            robot.drive(0.2, 'forward')

Everything goes through the robot's standard topics: ``/cmd_vel`` (geometry_msgs/Twist; a
TurtleBot on ROS 2 Jazzy or newer gets it as the TwistStamped it wants, see ``ros_versions`` in
profile.yaml) moves it, ``/odom`` (nav_msgs/Odometry) says where it is, ``/scan``
(sensor_msgs/LaserScan) what its laser sees and ``/battery_state`` (sensor_msgs/BatteryState)
how full its battery is; a ``bumper`` on ``/sensor_state`` (turtlebot3_msgs/SensorState) ends a
motion as a bump.

``drive``, ``turn`` and ``drive_for`` are closed loops on the odometry: they send velocities
until ``/odom`` says the robot got there, then stop it. Each new velocity is chosen so the
robot does not pass the target before the next odometry message (it slows down for the last
bit), and after stopping they check where the robot really halted and correct the rest. A
pause halts the robot at once; Continue drives (turns, waits) the rest. Times are the robot's
own, read from the odometry's time stamps, so a simulator running faster than the clock
drives the same distances.
"""
import math
import time

from rockly_desktop.sdk import RobotCommandError, RobotCommands, RobotTimeout, nearest_in_scan

from .arena import TEXTS, bumped

CMD_VEL, TWIST = "/cmd_vel", "geometry_msgs/Twist"
ODOM, ODOMETRY = "/odom", "nav_msgs/Odometry"
SCAN, LASER_SCAN = "/scan", "sensor_msgs/LaserScan"
BATTERY, BATTERY_STATE = "/battery_state", "sensor_msgs/BatteryState"
SENSORS, SENSOR_STATE = "/sensor_state", "turtlebot3_msgs/SensorState"
CONTACT = "/sim/contact"       # the simulator's own: the id of what it bumped into (a real TurtleBot has none)

LINEAR_SPEED = 0.15            # m/s for drive()
ANGULAR_SPEED = 0.8            # rad/s for turn()
MAX_SPEED = 0.22               # m/s, the TurtleBot3's top speed: drive_for() refuses more
DISTANCE_TOLERANCE = 0.003     # m: a drive is done this close to its target
ANGLE_TOLERANCE = math.radians(0.5)
TIME_TOLERANCE = 1e-3          # s of robot time, for drive_for()
CORRECTIONS = 10               # at most this many corrections after a motion's stop
SENSOR_TIMEOUT = 3.0           # s without odometry or a scan: the robot is not answering
SETTLE_TIMEOUT = 2.0           # s for the robot to stand still after a stop
STALL_SECONDS = 1.0            # s of robot time without progress while driving: something blocks it
STALL_DISTANCE = 0.001         # m ...
STALL_ANGLE = math.radians(0.25)   # ... or radians that count as progress
STILL_LINEAR = 1e-3            # m/s and
STILL_ANGULAR = 1e-3           # rad/s below which odometry says the robot stands still

DIRECTIONS = {"forward": 1.0, "backward": -1.0}
TURN_DIRECTIONS = {"left": 1.0, "right": -1.0}
SIDES = {"ahead": 0.0, "left": math.pi / 2, "right": -math.pi / 2, "behind": math.pi}


def _wrap(angle):
    """``angle`` (radians) in [-pi, pi]."""
    return math.remainder(angle, math.tau)


def _seconds(stamp):
    """A time stamp (float seconds or ``{"secs": .., "nsecs": ..}``) in seconds; 0 when missing."""
    if isinstance(stamp, dict):
        return float(stamp.get("secs", 0)) + float(stamp.get("nsecs", 0)) * 1e-9
    return float(stamp or 0.0)


class _Pose:
    """What one odometry message says: position, heading, velocities, its time stamp and when it arrived."""

    __slots__ = ("x", "y", "yaw", "linear", "angular", "stamp", "arrival")

    def __init__(self, message):
        pose = (message.get("pose") or {}).get("pose") or {}
        position, q = pose.get("position") or {}, pose.get("orientation") or {}
        twist = (message.get("twist") or {}).get("twist") or {}
        self.x, self.y = float(position.get("x", 0.0)), float(position.get("y", 0.0))
        qx, qy, qz, qw = (float(q.get(axis, 0.0)) for axis in "xyzw")
        self.yaw = math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
        self.linear = float((twist.get("linear") or {}).get("x", 0.0))
        self.angular = float((twist.get("angular") or {}).get("z", 0.0))
        self.stamp = _seconds((message.get("header") or {}).get("stamp"))
        self.arrival = time.monotonic()

    @property
    def still(self):
        return abs(self.linear) < STILL_LINEAR and abs(self.angular) < STILL_ANGULAR


def _elapsed(earlier: _Pose, later: _Pose):
    """Robot seconds between two odometry messages: their stamps; the clock when a robot stamps nothing."""
    if earlier.stamp or later.stamp:
        return later.stamp - earlier.stamp
    return later.arrival - earlier.arrival


class _Progress:
    """How far the robot got since ``start``, from the odometry messages given to ``add`` (any thread).

    ``kind`` 'drive': metres along the starting heading; 'turn': radians turned (heading changes
    added up, so more than half a turn is measured right); 'time': robot seconds passed.
    ``state`` is replaced as a whole, so a reader always sees one consistent message.
    """

    def __init__(self, kind, start: _Pose):
        self._kind = kind
        self._start = start
        self._turned = 0.0
        self.state = (0, 0.0, start, None)   # (messages, done, latest pose, seconds between the last two)

    def add(self, message):
        count, _done, last, _step = self.state
        pose = _Pose(message)
        if self._kind == "drive":
            start = self._start
            done = (pose.x - start.x) * math.cos(start.yaw) + (pose.y - start.y) * math.sin(start.yaw)
        elif self._kind == "turn":
            self._turned += _wrap(pose.yaw - last.yaw)
            done = self._turned
        else:
            done = _elapsed(self._start, pose)
        step = _elapsed(last, pose)
        self.state = (count + 1, done, pose, step if step > 0 else None)

    @property
    def count(self):
        return self.state[0]

    @property
    def done(self):
        return self.state[1]


class TurtleBot(RobotCommands):
    """Commands for a TurtleBot: drive and turn, its laser's distances, its battery."""

    # --- driving ------------------------------------------------------------------------

    def drive(self, distance, direction="forward"):
        """Drive ``distance`` metres straight, ``'forward'`` or ``'backward'``, at 0.15 m/s; waits until there.

        Raises a RobotCommandError when the robot bumps into something or something blocks the way
        (the robot is stopped there).
        """
        metres = self.number(distance, TEXTS("the_distance")) * self.choose(direction, DIRECTIONS, TEXTS("direction"))
        self._move("drive", metres)

    def turn(self, angle, direction="left"):
        """Turn on the spot by ``angle`` degrees, ``'left'`` (counter-clockwise) or ``'right'``; waits until done."""
        radians = math.radians(self.number(angle, TEXTS("the_angle")))
        radians *= self.choose(direction, TURN_DIRECTIONS, TEXTS("direction"))
        self._move("turn", radians)

    def drive_for(self, speed, seconds):
        """Drive straight at ``speed`` m/s (-0.22 to 0.22; negative is backward) for ``seconds``, then stop."""
        speed = self.number(speed, TEXTS("the_speed"))
        if abs(speed) > MAX_SPEED + 1e-9:
            raise RobotCommandError(TEXTS("speed_too_high", top=MAX_SPEED, speed=speed))
        left = max(0.0, self.number(seconds, TEXTS("the_time")))
        while left > TIME_TOLERANCE:
            outcome, done = self._timed_run(speed, left)
            left -= done
            if outcome == "bumped":
                raise self._bump_error()
            if outcome == "paused":
                self.backend.hold()

    def stop(self):
        """Stop the wheels at once."""
        self.backend.publish(CMD_VEL, TWIST, {})

    # --- what the robot senses -----------------------------------------------------------

    def distance(self, direction="ahead"):
        """Metres to the nearest thing the laser sees ``'ahead'``, ``'left'``, ``'right'`` or ``'behind'``.

        It looks 15 degrees to each side of that direction and measures from the robot's
        centre. When nothing is in sight (farther than the laser reaches) it is infinity, so
        ``robot.distance('ahead') < 0.5`` is simply false.
        """
        centre = self.choose(direction, SIDES, TEXTS("direction"))
        scan = self._latest(SCAN, LASER_SCAN)
        try:
            return nearest_in_scan(scan, centre)
        except (KeyError, TypeError, ValueError):
            raise RobotCommandError(TEXTS("not_laser_scans", topic=SCAN)) from None

    def obstacle_closer_than(self, metres, direction="ahead") -> bool:
        """True when the laser sees something closer than ``metres`` in that direction (see ``distance``)."""
        limit = self.number(metres, TEXTS("the_distance"))
        if limit < 0:
            raise RobotCommandError(TEXTS("distance_negative", limit=limit))
        return self.distance(direction) < limit

    def battery_level(self) -> float:
        """The battery's charge in percent (0-100)."""
        percentage = self._latest(BATTERY, BATTERY_STATE).get("percentage")
        if not isinstance(percentage, (int, float)) or not math.isfinite(percentage):
            raise RobotCommandError(TEXTS("no_battery_charge"))
        return float(percentage) * 100

    # --- time ----------------------------------------------------------------------------

    def wait(self, seconds):
        """Do nothing for ``seconds`` seconds."""
        self.backend.sleep(max(0.0, self.number(seconds, TEXTS("the_waiting_time"))))

    # --- helpers -------------------------------------------------------------------------

    def _latest(self, topic, msg_type):
        """The newest message on ``topic``, waiting briefly for a first one."""
        message = self.backend.latest(topic, msg_type)
        if message is None:
            message = self.backend.wait_for_message(topic, msg_type, SENSOR_TIMEOUT)
        return message

    def _twist(self, linear=0.0, angular=0.0):
        self.backend.publish(CMD_VEL, TWIST, {"linear": {"x": float(linear)}, "angular": {"z": float(angular)}})

    def _move(self, kind, amount):
        """Drive (metres) or turn (radians) ``amount``, correcting after each stop, holding for pauses."""
        tolerance = DISTANCE_TOLERANCE if kind == "drive" else ANGLE_TOLERANCE
        remaining, done_total, corrections = amount, 0.0, 0
        while abs(remaining) > tolerance and corrections <= CORRECTIONS:
            outcome, done = self._run(kind, remaining, tolerance)
            remaining -= done
            done_total += done
            if outcome == "bumped":
                raise self._bump_error()
            if outcome == "stalled":
                if kind == "drive":
                    raise RobotCommandError(TEXTS("way_blocked", done=abs(done_total), total=abs(amount)))
                raise RobotCommandError(TEXTS("turn_blocked", done=abs(math.degrees(done_total)),
                                              total=abs(math.degrees(amount))))
            if outcome == "paused":
                self.backend.hold()
            else:
                corrections += 1

    def _run(self, kind, target, tolerance):
        """One closed loop toward ``target``: ('reached' | 'paused' | 'stalled', how much was done).

        The robot stands still when it returns (or as still as it got within SETTLE_TIMEOUT).
        """
        top = LINEAR_SPEED if kind == "drive" else ANGULAR_SPEED
        stall_amount = STALL_DISTANCE if kind == "drive" else STALL_ANGLE

        def command(left, step):
            speed = math.copysign(min(top, abs(left) / step) if step else top, left)
            if kind == "drive":
                self._twist(linear=speed)
            else:
                self._twist(angular=speed)

        return self._loop(kind, command, lambda left: abs(left) <= tolerance, target, stall_amount)

    def _timed_run(self, speed, seconds):
        """Drive at ``speed`` for ``seconds`` of robot time: ('reached' | 'paused', seconds driven)."""
        def command(left, step):
            # the last odometry step before the end gets only the fraction of the speed it needs
            self._twist(linear=speed * min(1.0, left / step) if step else speed)

        return self._loop("time", command, lambda left: left <= TIME_TOLERANCE, seconds, None)

    def _bump_error(self):
        """The RobotCommandError for a bump, naming what the simulator says was hit."""
        contact = self.backend.latest(CONTACT, "std_msgs/String")
        return RobotCommandError(bumped(contact["data"] if contact else None))

    def _loop(self, kind, command, arrived, target, stall_amount):
        start = _Pose(self._latest(ODOM, ODOMETRY))
        progress = _Progress(kind, start)
        bumps = []
        unsubscribe = self.backend.subscribe(ODOM, ODOMETRY, progress.add)
        unsubscribe_bumper = self._bumper(bumps)
        try:
            try:
                outcome = self._follow(progress, command, arrived, target, stall_amount, bumps)
            except RobotCommandError:
                self._try_to_stop()
                raise
            driven = progress.done
            self.stop()
            stopped_at = progress.count
            self.backend.wait_until(lambda: progress.count > stopped_at and progress.state[2].still, SETTLE_TIMEOUT)
            # a motion counts where the robot came to rest; time counts only while it was told to drive
            return outcome, driven if kind == "time" else progress.done
        finally:
            unsubscribe()
            unsubscribe_bumper()

    def _bumper(self, bumps):
        """Note each bump on ``bumps``; returns the unsubscribe function. A robot whose middleware lacks
        turtlebot3_msgs (a ROS 2 environment without them) drives without the bumper."""
        try:
            return self.backend.subscribe(
                SENSORS, SENSOR_STATE, lambda message: bumps.append(True) if message.get("bumper") else None)
        except RobotCommandError:
            return lambda: None

    def _follow(self, progress, command, arrived, target, stall_amount, bumps):
        """Send velocities until arrived, paused, bumped or stalled; each new odometry message gets a new one."""
        seen, _, latest, step = progress.state
        command(target, step)
        moved_at, moved_done = latest, 0.0
        while True:
            if not self.backend.wait_until(
                    lambda seen=seen: progress.count > seen or bumps or self.backend.pause_requested(), SENSOR_TIMEOUT):
                raise RobotTimeout(TEXTS("no_odometry", topic=ODOM, timeout=SENSOR_TIMEOUT))
            if bumps:
                return "bumped"
            if self.backend.pause_requested():
                return "paused"
            seen, done, latest, step = progress.state
            left = target - done
            if arrived(left):
                return "reached"
            if stall_amount is not None:
                if abs(done - moved_done) > stall_amount:
                    moved_at, moved_done = latest, done
                elif _elapsed(moved_at, latest) > STALL_SECONDS:
                    return "stalled"
            command(left, step)

    def _try_to_stop(self):
        try:
            self.stop()
        except RobotCommandError:
            pass  # the error being raised says more than this one
