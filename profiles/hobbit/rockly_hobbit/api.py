"""HOBBIT's commands, bound as ``robot`` in programs.

They read the same whether generated from blocks or written by hand::

    robot.gripper('open')
    robot.move_arm('floor')
    robot.gripper('close')
    robot.move_arm('table')
    robot.gripper('open')

Every command waits until the robot has done it (a drive, an arm motion, a question on
the tablet), except ``show_emotion``, ``look`` and ``show_info``, which return at once.
Their errors are texts of the profile's catalogue (``locale/``), shown in the run's language.
"""
import math
import time

from rockly_desktop.sdk import GoalStatus, RobotCommandError, RobotCommands, RobotTimeout, field_value

from .base import MOVE_SPEED, TURN_SPEED
from .world import CONTACT_TOPIC, TEXTS, WORLD, blocked_on_the_way_text, bump_text, goal_problem_text

HEAD_POSITIONS = (
    "center_center", "up_center", "down_center", "center_right", "center_left", "up_right",
    "up_left", "down_right", "down_left", "littledown_center", "to_grasp", "to_turntable", "search_table",
)
EMOTIONS = ("HAPPY", "VHAPPY", "LTIRED", "VTIRED", "CONCERNED", "SAD", "WONDERING", "NEUTRAL", "SLEEPING")
ARM_POSITIONS = {
    "candle": "MoveToCandle", "home": "MoveToHome", "floor": "MoveToPreGraspFloor",
    "table": "MoveToPreGraspTable", "tray": "MoveToTray",
}
TURNTABLE_ACTIONS = {
    "learn": "MoveToLearning", "store": "StoreTurntable",
    "clockwise": "TurnTurntableCW", "counterclockwise": "TurnTurntableCCW",
}
GRIPPER_ACTIONS = {"open": "OpenGripper", "close": "CloseGripper"}
VOLUME_CHANGES = {"louder": "F_LOUDER", "quieter": "F_QUIETER"}
DIRECTIONS = {"forward": 1.0, "backward": -1.0}
TURN_DIRECTIONS = {"left": 1.0, "right": -1.0}
MESSAGE_TYPES = {"String": "std_msgs/String", "Bool": "std_msgs/Bool", "Float64": "std_msgs/Float64",
                 "Int64": "std_msgs/Int64", "UInt64": "std_msgs/UInt64"}

ARM_ACTION, ARM_ACTION_TYPE = "hobbit_arm", "hobbit_msgs/ArmServerAction"
NAV_ACTION, NAV_ACTION_TYPE = "move_base", "move_base_msgs/MoveBaseAction"
MMUI_SERVICE, MMUI_TYPE = "/MMUI", "hobbit_msgs/Request"
MOTION_COMMAND, MOTION_STATE = "/DiscreteMotionCmd", "/DiscreteMotionState"
MOTION_TIMEOUT = 120.0
STOP_SETTLE_TIMEOUT = 2.0
MOVE_TOLERANCE = 0.005  # metres
TURN_TOLERANCE = 0.5  # degrees
DIALOG_TIMEOUT = 60.0
SENSOR_TIMEOUT = 3.0
APPROACH = 3        # a driven motion covers at most 1/APPROACH of what is left per odometry update
STOPPED = 1e-3      # m/s or °/s the odometry may still report for a base that has stopped
SETTLE_UPDATES = 10  # odometry updates a stopping base may take to report it


class _Progress:
    """How far the base got during one discrete motion, from the odometry it publishes.

    Moves count the distance along the starting heading; turns add up the heading changes
    (so a turn of more than 180 degrees is measured right).
    """

    def __init__(self, kind):
        self._kind = kind
        self._start = None
        self._last_yaw = None
        self.done = 0.0
        self.updates = 0
        self.speed = 0.0     # m/s or °/s, as the base reports it
        self.commanded = 0.0  # m/s or °/s last sent, for a base whose odometry reports no velocity
        self.period = None   # the longest time one update was seen to cover (s), once the base moved

    def add(self, odometry):
        """Take one odometry message into account."""
        self.updates += 1
        before = self.done
        self._add_pose(odometry)
        velocity = (odometry.get("twist") or {}).get("twist") or {}
        if self._kind == "Move":
            self.speed = (velocity.get("linear") or {}).get("x", 0.0)
        else:
            self.speed = math.degrees((velocity.get("angular") or {}).get("z", 0.0))
        speed = self.speed if abs(self.speed) > STOPPED else self.commanded
        if abs(speed) > STOPPED and self.done != before:
            self.period = max(self.period or 0.0, abs(self.done - before) / abs(speed))

    def _add_pose(self, odometry):
        pose = (odometry.get("pose") or {}).get("pose") or {}
        position, orientation = pose.get("position") or {}, pose.get("orientation") or {}
        x, y = position.get("x", 0.0), position.get("y", 0.0)
        qx, qy, qz, qw = (orientation.get(axis, 0.0) for axis in "xyzw")
        yaw = math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
        if self._start is None:
            self._start, self._last_yaw = (x, y, yaw), yaw
            return
        if self._kind == "Move":
            start_x, start_y, heading = self._start
            self.done = (x - start_x) * math.cos(heading) + (y - start_y) * math.sin(heading)
        else:
            step = (yaw - self._last_yaw + math.pi) % (2 * math.pi) - math.pi
            self.done += math.degrees(step)
            self._last_yaw = yaw


class Hobbit(RobotCommands):
    """Commands for HOBBIT: drive, head and eyes, arm, gripper, turntable and tablet."""

    # --- base -------------------------------------------------------------------------

    def drive(self, distance, direction="forward"):
        """Drive ``distance`` metres straight, ``'forward'`` or ``'backward'``; waits until done.

        A pause halts the base at once; on Continue it drives the rest of the way.
        """
        metres = self.number(distance, TEXTS("the_distance")) * self.choose(direction, DIRECTIONS, TEXTS("direction"))
        self._motion("Move", metres, MOVE_TOLERANCE)

    def turn(self, angle, direction="left"):
        """Turn on the spot by ``angle`` degrees, ``'left'`` (counter-clockwise) or ``'right'``; waits.

        A pause halts the turn at once; on Continue it turns the rest of the way.
        """
        degrees = self.number(angle, TEXTS("the_angle")) * self.choose(direction, TURN_DIRECTIONS, TEXTS("direction"))
        self._motion("Turn", degrees, TURN_TOLERANCE)

    def navigate_to(self, x, y, heading=0):
        """Drive to the map position (``x``, ``y``) in metres, then face ``heading`` degrees; waits."""
        yaw = math.radians(self.number(heading, TEXTS("the_heading")))
        self.navigate_to_pose(x, y, 0.0, 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))

    def navigate_to_pose(self, x, y, z, qx, qy, qz, qw):
        """Drive to a full pose in the ``map`` frame (position and orientation quaternion); waits.

        move_base drives at HOBBIT's own speed, which Rockly cannot slow down: under a teacher's
        lower speed limit the goal is refused before it is sent.
        """
        values = [self.number(value, TEXTS(name)) for value, name in
                  ((x, "coordinate_x"), (y, "coordinate_y"), (z, "coordinate_z"), (qx, "quaternion_x"),
                   (qy, "quaternion_y"), (qz, "quaternion_z"), (qw, "quaternion_w"))]
        if (self.allowed_speed(MOVE_SPEED) < MOVE_SPEED
                or self.allowed_speed(TURN_SPEED, turning=True) < TURN_SPEED):
            raise RobotCommandError(TEXTS("navigation_too_fast", speed=MOVE_SPEED, turn=math.degrees(TURN_SPEED)))
        pose = {"header": {"frame_id": "map"},
                "pose": {"position": dict(zip("xyz", values[:3])),
                         "orientation": dict(zip("xyzw", values[3:]))}}
        outcome = self.backend.send_goal(NAV_ACTION, NAV_ACTION_TYPE, {"target_pose": pose}).wait(MOTION_TIMEOUT)
        if outcome.status is not GoalStatus.SUCCEEDED:
            reason = self._navigation_reason(values[0], values[1], outcome)
            raise RobotCommandError(TEXTS("goal_not_reached", reason=reason))

    def stop(self):
        """Stop the base at once."""
        self.backend.publish(MOTION_COMMAND, "std_msgs/String", {"data": "Stop"})
        self.backend.publish("/cmd_vel", "geometry_msgs/Twist", {})

    # --- head ---------------------------------------------------------------------------

    def look(self, position):
        """Move the head to a named position, e.g. ``'center_center'`` (straight) or ``'up_left'``."""
        self.choose(position, dict.fromkeys(HEAD_POSITIONS), TEXTS("head_position"))
        self.backend.publish("/head/move", "std_msgs/String", {"data": position})

    def show_emotion(self, emotion):
        """Show an emotion in the eyes: HAPPY, VHAPPY, LTIRED, VTIRED, CONCERNED, SAD, WONDERING, NEUTRAL, SLEEPING."""
        self.choose(emotion, dict.fromkeys(EMOTIONS), TEXTS("emotion"))
        self.backend.publish("/head/emo", "std_msgs/String", {"data": emotion})

    # --- arm ----------------------------------------------------------------------------

    def move_arm(self, position):
        """Move the arm to ``'candle'``, ``'home'``, ``'floor'``, ``'table'`` or ``'tray'``; waits."""
        self._arm(self.choose(position, ARM_POSITIONS, TEXTS("arm_position")))

    def turntable(self, action):
        """Use the turntable: ``'learn'``, ``'store'``, ``'clockwise'`` or ``'counterclockwise'``; waits."""
        self._arm(self.choose(action, TURNTABLE_ACTIONS, TEXTS("turntable_action")))

    def gripper(self, action):
        """``'open'`` or ``'close'`` the gripper; waits."""
        self._arm(self.choose(action, GRIPPER_ACTIONS, TEXTS("gripper_action")))

    def move_arm_to_joints(self, joints):
        """Move the arm to six joint values (degrees as the arm server expects them); waits."""
        values = list(joints) if isinstance(joints, (list, tuple)) else None
        if values is None or len(values) != 6:
            raise RobotCommandError(TEXTS("arm_needs_six", joints=repr(joints)))
        self._arm("MoveToJointValues", [[self.number(v, TEXTS("a_joint_value")) for v in values]])

    # --- tablet -------------------------------------------------------------------------

    def show_info(self, text):
        """Show ``text`` on the tablet (and say it)."""
        self._tablet("D_PLAIN", text)

    def show_info_and_wait(self, text):
        """Show ``text`` and wait until the user confirms it."""
        self._tablet("D_OK", text)

    def ask_yes_no(self, question) -> bool:
        """Ask a yes/no question on the tablet; True when the user answers yes."""
        return self._tablet("D_YES_NO", question).strip().lower() == "yes"

    def ask_text(self, question) -> str:
        """Ask the user to type a text on the tablet; returns what they typed."""
        return self._tablet("D_NAME", question)

    def call_sos(self):
        """Start an emergency (SOS) call."""
        self._tablet_function("F_CALLSOS")

    def change_volume(self, change):
        """Make the voice ``'louder'`` or ``'quieter'`` (10 % a step)."""
        self._tablet_function(self.choose(change, VOLUME_CHANGES, TEXTS("volume_change")))

    # --- what the robot knows ----------------------------------------------------------

    def battery_level(self) -> float:
        """The battery charge in percent (0-100)."""
        return self._latest("/battery_state", "sensor_msgs/BatteryState", "percentage") * 100

    def position(self, coordinate="x"):
        """Where the robot is on its odometry: ``'x'`` or ``'y'`` in metres, ``'heading'`` in degrees."""
        self.choose(coordinate, dict.fromkeys(("x", "y", "heading")), TEXTS("coordinate"))
        pose = self._latest("/odom", "nav_msgs/Odometry", "pose.pose")
        if coordinate == "heading":
            q = pose["orientation"]
            return math.degrees(math.atan2(2 * (q["w"] * q["z"] + q["x"] * q["y"]),
                                           1 - 2 * (q["y"] ** 2 + q["z"] ** 2)))
        return pose["position"][coordinate]

    def head_position(self) -> str:
        """Where the head was last told to look (``'center_center'`` until then)."""
        message = self.backend.latest("/head/move", "std_msgs/String")
        return message["data"] if message else "center_center"

    def emotion(self) -> str:
        """The emotion the eyes were last told to show (``'NEUTRAL'`` until then)."""
        message = self.backend.latest("/head/emo", "std_msgs/String")
        return message["data"] if message else "NEUTRAL"

    def arm_is_moving(self) -> bool:
        """True when the arm's joints move (two joint-state messages differ)."""
        first = self.backend.wait_for_message("/joint_states", "sensor_msgs/JointState", SENSOR_TIMEOUT)
        second = self.backend.wait_for_message("/joint_states", "sensor_msgs/JointState", SENSOR_TIMEOUT)
        # messages from different publishers may list different joints; compare what both have
        return any(abs(a - b) > 1e-4
                   for a, b in zip(first.get("position", [])[:6], second.get("position", [])[:6]))

    def latest_value(self, topic, field):
        """The newest value of ``field`` (e.g. ``pose.pose.position.x``) on any ``topic``."""
        return self._latest(str(topic), None, str(field))

    # --- general ------------------------------------------------------------------------

    def wait(self, seconds):
        """Do nothing for ``seconds`` seconds."""
        self.backend.sleep(max(0.0, self.number(seconds, TEXTS("the_waiting_time"))))

    def publish(self, topic, message_type, value):
        """Publish ``value`` on ``topic`` as a std_msgs type: String, Bool, Float64, Int64 or UInt64."""
        msg_type = self.choose(message_type, MESSAGE_TYPES, TEXTS("message_type"))
        self.backend.publish(str(topic), msg_type, {"data": value})

    def call_service(self, name, service_type, parameters=None, with_parameters=True, timeout=DIALOG_TIMEOUT):
        """Call any service by name and type; ``parameters`` are the request's fields (a mapping
        or JSON text), sent only ``with_parameters``; returns the response dict."""
        request = self.mapping(parameters, TEXTS("service_parameters")) if with_parameters else {}
        return self.backend.call_service(str(name), str(service_type), request, timeout)

    # --- helpers ------------------------------------------------------------------------

    def _latest(self, topic, msg_type, field):
        """A field of the newest message on ``topic``, waiting briefly for a first one."""
        message = self.backend.latest(topic, msg_type)
        if message is None:
            message = self.backend.wait_for_message(topic, msg_type, SENSOR_TIMEOUT)
        try:
            return field_value(message, field)
        except KeyError:
            raise RobotCommandError(TEXTS("no_field", topic=topic, field=field)) from None

    def _motion(self, kind, amount, tolerance):
        """``Move`` metres or ``Turn`` degrees: with the base driver's discrete motion, which goes at
        HOBBIT's own speeds, or, when a teacher's limit is below either, driven with ``/cmd_vel`` at
        the limit (a discrete motion is refused then: the manifest's ``own_speed``)."""
        allowed_move, allowed_turn = self.allowed_speed(MOVE_SPEED), self.allowed_speed(TURN_SPEED, turning=True)
        if allowed_move < MOVE_SPEED or allowed_turn < TURN_SPEED:  # the limits refuse a discrete motion then
            self._driven_motion(kind, amount, tolerance, allowed_move if kind == "Move" else math.degrees(allowed_turn))
        else:
            self._discrete_motion(kind, amount, tolerance)

    def _driven_motion(self, kind, amount, tolerance, top_speed):
        """``Move``/``Turn`` by ``amount`` with velocity commands of at most ``top_speed`` (m/s, °/s),
        measured and stopped by the odometry.

        The base slows down near the end so that no odometry update covers more than a third of
        what is left (however long an update is: a fast simulator's are long), stops well within
        ``tolerance``, and comes back if it overshot. A pause halts it; Continue drives the rest.
        """
        progress, bumps = _Progress(kind), []
        start = self.backend.latest("/odom", "nav_msgs/Odometry")
        if start is not None:
            progress.add(start)
        unsubscribe_odom = self.backend.subscribe("/odom", "nav_msgs/Odometry", progress.add)
        unsubscribe_bumper = self.backend.subscribe(
            "/bumper", "std_msgs/Bool", lambda message: bumps.append(True) if message.get("data") else None)
        try:
            self._drive_until_there(kind, amount, tolerance, top_speed, progress, bumps)
        finally:
            unsubscribe_odom()
            unsubscribe_bumper()

    def _drive_until_there(self, kind, amount, tolerance, top_speed, progress, bumps):
        deadline = time.monotonic() + MOTION_TIMEOUT + abs(amount) / top_speed
        commanded, settling = None, 0
        while True:
            if bumps:
                self.stop()
                raise self._bump_error()
            if self.backend.pause_requested():
                self._velocity(kind, 0.0)
                progress.commanded = 0.0
                seen = progress.updates
                self.backend.wait_until(lambda seen=seen: progress.updates > seen and abs(progress.speed) <= STOPPED,
                                        STOP_SETTLE_TIMEOUT)
                self.backend.hold()
                deadline, commanded = time.monotonic() + MOTION_TIMEOUT + abs(amount) / top_speed, None
                continue
            remaining = amount - progress.done
            if abs(remaining) <= (tolerance if commanded == 0.0 else tolerance / 4):  # aim well inside it
                settling = settling + 1 if commanded == 0.0 else 0
                if commanded == 0.0 and (abs(progress.speed) <= STOPPED or settling > SETTLE_UPDATES):
                    return
                speed = 0.0
            else:
                near = abs(remaining) / (APPROACH * progress.period) if progress.period else top_speed
                speed = math.copysign(min(top_speed, near), remaining)
            self._velocity(kind, speed)
            commanded = progress.commanded = speed
            seen = progress.updates
            if not self.backend.wait_until(
                    lambda seen=seen: progress.updates > seen or bumps or self.backend.pause_requested(),
                    SENSOR_TIMEOUT):
                self.stop()
                raise RobotTimeout(TEXTS("no_odometry_while_driving", timeout=SENSOR_TIMEOUT))
            if time.monotonic() > deadline:
                self.stop()
                raise RobotTimeout(TEXTS("motion_not_finished", command=f"{kind} {amount:g}"))

    def _velocity(self, kind, speed):
        """Drive straight at ``speed`` m/s (``Move``) or turn at ``speed`` °/s (``Turn``)."""
        twist = {"linear": {"x": speed}} if kind == "Move" else {"angular": {"z": math.radians(speed)}}
        self.backend.publish("/cmd_vel", "geometry_msgs/Twist", twist)

    def _discrete_motion(self, kind, amount, tolerance):
        """``Move <metres>`` / ``Turn <degrees>`` with the base driver, waiting for ``Idle``.

        The state topic is listened to before the command goes out, so a fast ``Idle`` is
        never missed. On a pause the base is stopped, the odometry tells how far it got,
        and after Continue the remaining amount is sent.
        """
        remaining = amount
        while abs(remaining) > tolerance:
            states, progress = [], _Progress(kind)
            start = self.backend.latest("/odom", "nav_msgs/Odometry")
            if start is not None:
                progress.add(start)  # where the motion starts
            unsubscribe_state = self.backend.subscribe(
                MOTION_STATE, "std_msgs/String", lambda message, states=states: states.append(message.get("data")))
            unsubscribe_odom = self.backend.subscribe("/odom", "nav_msgs/Odometry", progress.add)
            bumps = []
            unsubscribe_bumper = self.backend.subscribe(
                "/bumper", "std_msgs/Bool",
                lambda message, bumps=bumps: bumps.append(True) if message.get("data") else None)
            try:
                self.backend.publish(MOTION_COMMAND, "std_msgs/String", {"data": f"{kind} {remaining:g}"})
                if not self.backend.wait_until(
                        lambda states=states, bumps=bumps: "Idle" in states or bumps or self.backend.pause_requested(),
                        MOTION_TIMEOUT):
                    raise RobotTimeout(TEXTS("base_timeout", command=f"{kind} {remaining:g}", timeout=MOTION_TIMEOUT))
                if bumps:
                    self.stop()
                    raise self._bump_error()
                if "Idle" in states:
                    return
                self.stop()
                self.backend.wait_until(lambda states=states: states[-1:] == ["Idle"], STOP_SETTLE_TIMEOUT)
                seen = progress.updates  # the odometry after the halt says where the base stopped
                self.backend.wait_until(lambda progress=progress, seen=seen: progress.updates > seen,
                                        STOP_SETTLE_TIMEOUT)
            finally:
                unsubscribe_state()
                unsubscribe_odom()
                unsubscribe_bumper()
            if progress.updates < 2:
                raise RobotCommandError(TEXTS("pause_without_odometry", command=f"{kind} {remaining:g}"))
            remaining -= progress.done
            self.backend.hold()

    def _navigation_reason(self, x, y, outcome):
        """Why move_base ended the goal: the simulator's reasons as texts of the catalogue, else its own words."""
        known = [goal_problem_text(x, y)] + [blocked_on_the_way_text(obstacle.id) for obstacle in WORLD.obstacles]
        for reason in known:
            if reason is not None and str(reason) == outcome.text:
                return reason
        if outcome.text:   # a real move_base's own words (English)
            return outcome.text
        return TEXTS("goal_ended", status=TEXTS(f"status_{outcome.status.value}"))

    def _bump_error(self):
        """The RobotCommandError for a bump, naming what the simulator says was hit."""
        contact = self.backend.latest(CONTACT_TOPIC, "std_msgs/String")
        return RobotCommandError(bump_text(contact["data"] if contact else None))

    def _arm(self, command, joints=()):
        goal = {"command": {"data": command}, "velocity": 0.0,
                "joints": [{"joint_values": vector} for vector in joints]}
        outcome = self.backend.send_goal(ARM_ACTION, ARM_ACTION_TYPE, goal).wait(MOTION_TIMEOUT)
        if outcome.status is not GoalStatus.SUCCEEDED:
            status = TEXTS(f"status_{outcome.status.value}")
            raise RobotCommandError(TEXTS("arm_failed", command=command, status=status))

    def _tablet(self, dialog_type, text, timeout=DIALOG_TIMEOUT):
        params = [{"name": "type", "value": dialog_type}, {"name": "text", "value": str(text)},
                  {"name": "speak", "value": str(text)}, {"name": "Timeout", "value": f"{timeout:g}"}]
        response = self.backend.call_service(
            MMUI_SERVICE, MMUI_TYPE, {"sessionID": "0", "requestText": "", "params": params}, timeout + 5)
        answers = [p.get("value", "") for p in response.get("params", []) if p.get("name") != "type"]
        return answers[0] if answers else ""

    def _tablet_function(self, function_type):
        params = [{"name": "type", "value": function_type}]
        self.backend.call_service(MMUI_SERVICE, MMUI_TYPE, {"sessionID": "0", "requestText": "", "params": params},
                                  DIALOG_TIMEOUT)


