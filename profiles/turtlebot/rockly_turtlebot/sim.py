"""The built-in simulated TurtleBot: a differential-drive base with a 360-degree laser, in a room with boxes.

``SimTurtleBot`` serves the robot's ROS interface in a SimWorld exactly as a TurtleBot3's
nodes do: it follows ``/cmd_vel`` (geometry_msgs/Twist) and publishes ``/odom``
(nav_msgs/Odometry), ``/scan`` (sensor_msgs/LaserScan), ``/battery_state``
(sensor_msgs/BatteryState) and ``/sensor_state`` (turtlebot3_msgs/SensorState, whose
``bumper`` is what turtlebot3_core reports) on every tick of its 30 Hz clock. Simulated time runs ``speed``
times as fast as the clock; the messages are stamped with it.

The base moves as a unicycle at the commanded speeds (limited to the TurtleBot3 Burger's
0.22 m/s and 2.84 rad/s) until its round body (radius 0.105 m) touches a wall or a box: then
it stops there and drops the command until the next one; ``/sensor_state`` reports the bump
(``bumper`` 1 forward, 2 backward) in that tick, and the simulator's own ``/sim/contact``
(std_msgs/String) names what was hit by its id.
Odometry is perfect and shares the room's frame (the robot starts at the origin). The laser
sits at the robot's centre: 360 beams counter-clockwise from straight ahead, 0.12-3.5 m,
``inf`` where nothing is in range and ``-inf`` (REP 117) closer than 0.12 m.
"""
import logging
import math
from collections import deque

from rockly_desktop.sdk import RobotSimulator, twist_velocity

from .arena import BOXES, ROOM, Arena

CONTACT_TOPIC = "/sim/contact"
SENSOR_STATE = "/sensor_state", "turtlebot3_msgs/SensorState"
BUMPER_FORWARD, BUMPER_BACKWARD = 1, 2

log = logging.getLogger(__name__)

TICK_SECONDS = 1 / 30
MAX_LINEAR = 0.22             # m/s
MAX_ANGULAR = 2.84            # rad/s
BEAMS = 360
ANGLE_INCREMENT = 2 * math.pi / BEAMS
RANGE_MIN, RANGE_MAX = 0.12, 3.5
BATTERY_DRAIN = 1.0 / 60      # % per simulated second standing still
BATTERY_DRAIN_BUSY = 2.5 / 60     # % per simulated second while the wheels turn
FULL_VOLTS, EMPTY_VOLTS = 12.4, 11.0  # a 3-cell LiPo battery
CAPACITY = 1.8                # Ah
TRAIL_POINTS = 600
TRAIL_SPACING = 0.01          # m between trail points


def _clamp(value, limit):
    return max(-limit, min(limit, value))


def _stamp(seconds):
    secs = math.floor(seconds)
    return {"secs": int(secs), "nsecs": int((seconds - secs) * 1e9)}


class SimTurtleBot(RobotSimulator):
    """The simulated TurtleBot in ``world``; ``boxes`` and ``start`` (x, y, theta) change its room.

    ``tablet`` is accepted like every simulator's; a TurtleBot has none.
    """

    NAME = "simulated TurtleBot"
    TICK_SECONDS = TICK_SECONDS
    WORLD_ID = "room"

    def __init__(self, world, tablet=None, speed=1.0, boxes=BOXES, start=(0.0, 0.0, 0.0), room=ROOM):
        super().__init__(world, tablet, speed)
        self._arena = Arena(room, boxes)
        self.solid_world = self._arena
        x, y, theta = (float(value) for value in start)
        if not self._arena.fits(x, y):
            raise ValueError(f"the TurtleBot does not fit at ({x:g}, {y:g}): it would overlap a wall or a box")
        self._start = (x, y, math.remainder(theta, math.tau))
        self._set_start()

    def _set_start(self):
        self._x, self._y, self._theta = self._start
        self._command = (0.0, 0.0)        # what /cmd_vel asks: (linear, angular)
        self._linear = self._angular = 0.0  # what the base really does
        self._bumps = 0
        self._bumper = 0                  # the SensorState bumper bits of this tick
        self._contact = None              # the obstacle it last bumped into
        self._battery = 100.0
        self._trail = deque([(self._x, self._y)], maxlen=TRAIL_POINTS)
        self._scan = self._cast()

    def place(self, x, y, theta):
        """Put the TurtleBot at (x, y) facing ``theta`` (radians), standing still; ValueError where it does not fit."""
        x, y, theta = float(x), float(y), float(theta)
        if not self._arena.fits(x, y):
            raise ValueError(f"the TurtleBot does not fit at ({x:g}, {y:g}): it would overlap a wall or a box")
        with self.lock:
            self._x, self._y, self._theta = x, y, math.remainder(theta, math.tau)
            self._trail = deque([(x, y)], maxlen=TRAIL_POINTS)
            self._scan = self._cast()
            self.queue_sensors()
        self.flush()

    def reset(self):
        """Put the TurtleBot back at its start, standing still, battery full, no trail, no bumps."""
        with self.lock:
            self._set_start()
            self.queue_sensors()
        self.flush()

    # --- life cycle -------------------------------------------------------------------

    def connect(self):
        """Follow /cmd_vel."""
        self.subscribe("/cmd_vel", self._on_velocity)

    def safe_stop(self):
        """Stand still (what a zero /cmd_vel does)."""
        with self.lock:
            self._command = (0.0, 0.0)

    def snapshot(self) -> dict:
        """A copy of the robot's and the room's state, for the simulator view."""
        with self.lock:
            return {
                "x": self._x, "y": self._y, "theta": self._theta, "trail": list(self._trail),
                "linear": self._linear, "angular": self._angular,
                "scan": list(self._scan), "range_min": RANGE_MIN, "range_max": RANGE_MAX,
                "room": self._arena.room, "room_size": self._arena.size, "boxes": list(self._arena.boxes),
                "radius": self._arena.radius, "bumped": self._arena.touching(self._x, self._y) is not None,
                "bumps": self._bumps, "contact": self._contact.id if self._contact else None,
                "battery": self._battery, "voltage": self._volts(), "time": self.time,
            }

    # --- the clock --------------------------------------------------------------------

    def advance(self, dt):
        """Drive ``dt`` simulated seconds on (stopping at whatever it bumps into), drain the battery, scan."""
        linear, angular = self._command
        was_touching = self._arena.touching(self._x, self._y) is not None
        x, y, theta, hit = self._arena.move(self._x, self._y, self._theta, linear, angular, dt)
        blocked = hit is not None
        self._bumper = 0
        if not was_touching and self._arena.touching(x, y) is not None:
            self._bumps += 1   # a new touch: a step may end just at it, blocked only by the next
        if blocked:
            self._command = (0.0, 0.0)      # the bumper stops the wheels
            self._contact = hit
            self._bumper = BUMPER_FORWARD if linear >= 0 else BUMPER_BACKWARD
            self.queue(CONTACT_TOPIC, "std_msgs/String", {"data": hit.id})
            log.info("simulated TurtleBot: bumped into %s at (%.2f, %.2f)", hit.id, x, y)
        self._linear, self._angular = (0.0, 0.0) if blocked else (linear, angular)
        self._x, self._y, self._theta = x, y, theta
        if math.dist(self._trail[-1], (x, y)) >= TRAIL_SPACING:
            self._trail.append((x, y))
        busy = self._linear or self._angular
        self._battery = max(0.0, self._battery - dt * (BATTERY_DRAIN_BUSY if busy else BATTERY_DRAIN))
        self._scan = self._cast()

    def _cast(self):
        """The laser's ranges from the current pose (inf beyond range_max, -inf below range_min)."""
        angles = [self._theta + i * ANGLE_INCREMENT for i in range(BEAMS)]
        ranges = self._arena.cast(self._x, self._y, angles)
        return [math.inf if r > RANGE_MAX else -math.inf if r < RANGE_MIN else float(r) for r in ranges.tolist()]

    def _volts(self):
        return EMPTY_VOLTS + (FULL_VOLTS - EMPTY_VOLTS) * self._battery / 100

    # --- sensors ----------------------------------------------------------------------

    def queue_sensors(self):
        """/odom, /scan, /sensor_state and /battery_state, stamped with the simulated time."""
        stamp = _stamp(self.time)
        theta = self._theta
        self.queue("/odom", "nav_msgs/Odometry", {
            "header": {"stamp": stamp, "frame_id": "odom"}, "child_frame_id": "base_footprint",
            "pose": {"pose": {"position": {"x": self._x, "y": self._y, "z": 0.0},
                              "orientation": {"x": 0.0, "y": 0.0, "z": math.sin(theta / 2), "w": math.cos(theta / 2)}}},
            "twist": {"twist": {"linear": {"x": self._linear, "y": 0.0, "z": 0.0},
                                "angular": {"x": 0.0, "y": 0.0, "z": self._angular}}}})
        self.queue("/scan", "sensor_msgs/LaserScan", {
            "header": {"stamp": stamp, "frame_id": "base_scan"},
            "angle_min": 0.0, "angle_max": (BEAMS - 1) * ANGLE_INCREMENT, "angle_increment": ANGLE_INCREMENT,
            "time_increment": 0.0, "scan_time": TICK_SECONDS, "range_min": RANGE_MIN, "range_max": RANGE_MAX,
            "ranges": list(self._scan), "intensities": []})
        self.queue(*SENSOR_STATE, {"header": {"stamp": stamp, "frame_id": ""}, "bumper": self._bumper,
                                   "torque": True, "battery": self._volts()})
        busy = self._linear or self._angular
        self.queue("/battery_state", "sensor_msgs/BatteryState", {
            "header": {"stamp": stamp, "frame_id": ""}, "voltage": self._volts(),
            "current": -1.2 if busy else -0.4, "charge": CAPACITY * self._battery / 100, "capacity": CAPACITY,
            "design_capacity": CAPACITY, "percentage": self._battery / 100,
            "power_supply_status": 2, "power_supply_health": 1, "power_supply_technology": 3, "present": True})

    # --- /cmd_vel ---------------------------------------------------------------------

    def _on_velocity(self, message):
        velocity = twist_velocity(message)
        if velocity is None:
            log.warning("simulated TurtleBot: ignored a /cmd_vel that is not a Twist: %r", message)
            return
        linear, angular = velocity
        with self.lock:
            self._command = (_clamp(linear, MAX_LINEAR), _clamp(angular, MAX_ANGULAR))
