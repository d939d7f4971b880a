"""The built-in simulated HOBBIT: base, head and eyes, arm, gripper, turntable, battery, tablet.

``SimHobbit`` serves HOBBIT's real ROS interface (the topics, the ``hobbit_arm`` and
``move_base`` actions and the ``/MMUI`` service, with the names and values of the robot's
reference) in a SimWorld, so HOBBIT's commands drive it unchanged. Its tables are taken
from the reference, not from the commands, so a command that sends a wrong value is
caught here. Simulated time runs ``speed`` times as fast as the clock.

The house is solid (``world.yaml``, the same data the view draws): a motion that would take
HOBBIT's base into a wall or a piece of furniture stops where it touches; ``/bumper`` says
true at that moment (before the base reports Idle), and the simulator's own ``/sim/contact``
names what was hit. A navigation goal outside the house or where the base does not fit is aborted at once,
one that bumps on the way when it bumps (move_base's ABORTED, with the reason as its text).
"""
import logging
import math
from collections import deque
from dataclasses import dataclass

from rockly_desktop.sdk import GoalStatus, RobotCommandError, RobotSimulator, TabletQuestion, twist_velocity

from .base import MOVE_SPEED, TURN_SPEED
from .world import CONTACT_TOPIC, TEXTS, WORLD, blocked_on_the_way, goal_problem

log = logging.getLogger(__name__)

TICK_SECONDS = 1 / 30
LINEAR_SPEED = MOVE_SPEED     # m/s, for discrete motions and navigation
ANGULAR_SPEED = TURN_SPEED    # rad/s
ARRIVED = 0.001              # m: a navigation goal closer than this is reached
BATTERY_DRAIN = 1.0 / 60     # % per simulated second while standing still
BATTERY_DRAIN_BUSY = 3.0 / 60      # % per simulated second while the base or the arm moves
TRAIL_POINTS = 500
TRAIL_SPACING = 0.01         # m between trail points
NOTICES_KEPT = 20
VOLUME_STEP = 10
TURNTABLE_STEP = 30.0        # degrees per turntable turn
DIALOG_TIMEOUT = 60.0        # s, when a request has no usable Timeout param

ARM_ACTION = "hobbit_arm"
NAV_ACTION = "move_base"
MOTION_STATE = ("/DiscreteMotionState", "std_msgs/String")
MOTION_STATES = {"moving": "Moving", "turning": "Turning"}

HEAD_POSITIONS = frozenset((
    "center_center", "up_center", "down_center", "center_right", "center_left", "up_right", "up_left",
    "down_right", "down_left", "littledown_center", "to_grasp", "to_turntable", "search_table",
))
EMOTIONS = frozenset(("HAPPY", "VHAPPY", "LTIRED", "VTIRED", "CONCERNED", "SAD", "WONDERING", "NEUTRAL", "SLEEPING"))
# HOBBIT's /MMUI dialog types, as the questions Rockly's tablet port asks
DIALOGS = {"D_OK": TabletQuestion.OK, "D_YES_NO": TabletQuestion.YES_NO, "D_NAME": TabletQuestion.TEXT}


@dataclass(frozen=True)
class ArmCommand:
    """What one arm server command does: how long it takes and what it changes when done.

    ``joints`` is None, ``'one'`` (exactly one joint vector) or ``'many'`` (a trajectory,
    ``seconds`` per vector).
    """

    seconds: float
    pose: str = None
    gripper: str = None
    turntable: str = None
    turn: float = 0.0
    joints: str = None


ARM_COMMANDS = {
    "MoveToCandle": ArmCommand(4.0, pose="candle"),
    "MoveToHome": ArmCommand(4.0, pose="home"),
    "MoveToPreGraspFloor": ArmCommand(5.0, pose="floor"),
    "MoveToPreGraspTable": ArmCommand(4.0, pose="table"),
    "MoveToTray": ArmCommand(3.5, pose="tray"),
    "MoveToLearning": ArmCommand(5.0, pose="learning", turntable="out"),
    "StoreTurntable": ArmCommand(5.0, pose="home", turntable="stored"),
    "TurnTurntableCW": ArmCommand(2.0, turn=-TURNTABLE_STEP),
    "TurnTurntableCCW": ArmCommand(2.0, turn=TURNTABLE_STEP),
    "OpenGripper": ArmCommand(1.0, gripper="open"),
    "CloseGripper": ArmCommand(1.0, gripper="closed"),
    "MoveToJointValues": ArmCommand(4.0, pose="joints", joints="one"),
    "MoveAlongTrajectory": ArmCommand(2.5, pose="joints", joints="many"),
}


# --- what the base can be doing ---------------------------------------------------------


def _wrap(angle):
    """``angle`` in radians, brought into [-pi, pi]."""
    return math.remainder(angle, math.tau)


def _turn(theta, target, dt):
    """Turn from ``theta`` toward ``target`` for ``dt`` s: (new theta, angular velocity, arrived)."""
    error = _wrap(target - theta)
    step = min(ANGULAR_SPEED * dt, abs(error))
    return _wrap(theta + math.copysign(step, error)), math.copysign(ANGULAR_SPEED, error), step == abs(error)


class _Velocity:
    """Driving at a fixed velocity, as ``/cmd_vel`` asks (zero: standing still). Never done."""

    done = False

    def __init__(self, linear=0.0, angular=0.0):
        self.linear = linear
        self.angular = angular
        self.motion = "moving" if linear else "turning" if angular else "idle"

    def step(self, x, y, theta, dt):
        """Unicycle kinematics, integrated exactly over ``dt``."""
        v, w = self.linear, self.angular
        if abs(w) < 1e-9:
            return x + v * dt * math.cos(theta), y + v * dt * math.sin(theta), theta, v, w
        end = theta + w * dt
        return (x + v / w * (math.sin(end) - math.sin(theta)), y - v / w * (math.cos(end) - math.cos(theta)),
                _wrap(end), v, w)


class _DiscreteMotion:
    """A ``Move <metres>`` or ``Turn <degrees>`` of the base driver, at a fixed speed."""

    def __init__(self, motion, amount):
        self.motion = motion  # 'moving' (amount in metres) or 'turning' (radians)
        self.remaining = amount
        self.stepped = False

    @property
    def done(self):
        """True once the whole distance or angle is covered (a zero one after one step)."""
        return self.stepped and self.remaining == 0

    def step(self, x, y, theta, dt):
        """Cover as much of the rest as ``dt`` allows."""
        self.stepped = True
        speed = LINEAR_SPEED if self.motion == "moving" else ANGULAR_SPEED
        step = math.copysign(min(speed * dt, abs(self.remaining)), self.remaining)
        self.remaining -= step
        if self.motion == "moving":
            return x + step * math.cos(theta), y + step * math.sin(theta), theta, math.copysign(speed, step), 0.0
        return x, y, _wrap(theta + step), 0.0, math.copysign(speed, step)


class _Navigation:
    """Driving to a map pose as move_base does: turn toward it, drive there, turn to its heading."""

    motion = "navigating"

    def __init__(self, x, y, yaw):
        self.x, self.y, self.yaw = x, y, yaw
        self.phase = "aim"
        self.done = False
        self.bumped = None      # what stopped it on the way

    def step(self, x, y, theta, dt):
        """Advance the current phase by ``dt``."""
        dx, dy = self.x - x, self.y - y
        distance = math.hypot(dx, dy)
        if self.phase == "aim":
            if distance > ARRIVED:
                theta, angular, aimed = _turn(theta, math.atan2(dy, dx), dt)
                self.phase = "drive" if aimed else "aim"
                return x, y, theta, 0.0, angular
            self.phase = "face"
        if self.phase == "drive":
            travel = min(LINEAR_SPEED * dt, distance)
            if travel == distance:
                self.phase = "face"
                return self.x, self.y, theta, LINEAR_SPEED, 0.0
            return x + travel * dx / distance, y + travel * dy / distance, theta, LINEAR_SPEED, 0.0
        theta, angular, self.done = _turn(theta, self.yaw, dt)
        return x, y, theta, 0.0, angular


def _target_of(pose_stamped):
    """(x, y, yaw) of a PoseStamped dict; ValueError when its orientation is not a quaternion."""
    pose = pose_stamped.get("pose") or {}
    position, orientation = pose.get("position") or {}, pose.get("orientation") or {}
    x, y = float(position.get("x", 0.0)), float(position.get("y", 0.0))
    qx, qy, qz, qw = (float(orientation.get(axis, 0.0)) for axis in "xyzw")
    if not all(map(math.isfinite, (x, y, qx, qy, qz, qw))) or math.hypot(qx, qy, qz, qw) < 1e-6:
        raise ValueError(f"not a valid goal pose: {pose!r}")
    return x, y, math.atan2(2 * (qw * qz + qx * qy), qw * qw + qx * qx - qy * qy - qz * qz)


def _pose(x, y, theta):
    """A geometry_msgs/Pose dict for a pose on the floor."""
    return {"position": {"x": x, "y": y, "z": 0.0},
            "orientation": {"x": 0.0, "y": 0.0, "z": math.sin(theta / 2), "w": math.cos(theta / 2)}}


# --- the arm ----------------------------------------------------------------------------------


class _ArmTask:
    """One arm server command being carried out."""

    def __init__(self, name, command: ArmCommand, seconds, start_angle):
        self.name = name
        self.command = command
        self.seconds = seconds
        self.start_angle = start_angle
        self.progress = 0.0
        self.done = False


def _is_joint_vector(values):
    return (isinstance(values, (list, tuple)) and len(values) == 6
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in values))


def _arm_task_for(goal, turntable_angle):
    """The _ArmTask an ``hobbit_arm`` goal asks for, or None (logged) when the arm server would refuse it."""
    name = (goal.get("command") or {}).get("data")
    command = ARM_COMMANDS.get(name)
    if command is None:
        log.warning("simulated HOBBIT: unknown arm command %r", name)
        return None
    seconds = command.seconds
    if command.joints:
        vectors = [entry.get("joint_values") for entry in goal.get("joints") or []]
        count_ok = len(vectors) == 1 if command.joints == "one" else len(vectors) >= 1
        if not count_ok or not all(map(_is_joint_vector, vectors)):
            wanted = "exactly one" if command.joints == "one" else "at least one"
            log.warning("simulated HOBBIT: %s needs %s vector of 6 joint values, got %r", name, wanted, vectors)
            return None
        seconds *= len(vectors)
    return _ArmTask(name, command, seconds, turntable_angle)


# --- the robot --------------------------------------------------------------------------------


# Joint angles (radians) of the arm's named poses, for /joint_states; illustrative, not HOBBIT's calibration.
ARM_JOINT_NAMES = ("arm_joint_1", "arm_joint_2", "arm_joint_3", "arm_joint_4", "arm_joint_5", "arm_joint_6", "gripper")
ARM_JOINTS = {
    "home": (0.0, -1.4, 2.6, 0.0, 0.4, 0.0),
    "candle": (0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    "floor": (0.3, 0.9, 0.6, 0.0, 1.2, 0.0),
    "table": (0.3, 0.2, 0.9, 0.0, 0.8, 0.0),
    "tray": (1.6, -0.6, 2.0, 0.0, 0.9, 0.0),
    "learning": (0.8, 0.4, 0.8, 0.0, 1.0, 0.0),
}
GRIPPER_OPENING = {"open": 0.08, "closed": 0.0}


class SimHobbit(RobotSimulator):
    """A simulated HOBBIT in a SimWorld, moving in simulated time ``speed`` times as fast as real time.

    ``tablet`` answers dialogs: ``ask(question, text, timeout, interrupt) -> str`` (blocking,
    ``question`` a TabletQuestion) and ``notify(text)``. Call ``start()`` to bring the robot up and ``shutdown()``
    to stop its clock.
    """

    NAME = "simulated HOBBIT"
    solid_world = WORLD
    TICK_SECONDS = TICK_SECONDS
    WORLD_ID = "house"

    def __init__(self, world, tablet=None, speed=1.0):
        super().__init__(world, tablet, speed)
        self._set_start()

    def reset(self):
        """Put HOBBIT back: at the origin, standing still, arm home, head straight, battery full, no trail."""
        with self.lock:
            self._set_start()
            self.queue(*MOTION_STATE, {"data": "Idle"})
            self.queue_sensors()
        self.flush()
        self.world.cancel_goals(ARM_ACTION)
        self.world.cancel_goals(NAV_ACTION)

    def place(self, x, y, theta):
        """Put HOBBIT at (x, y) facing ``theta`` (radians), standing still; ValueError where it does not fit."""
        x, y, theta = float(x), float(y), float(theta)
        if not (WORLD.in_area(x, y) and WORLD.fits(x, y)):
            raise ValueError(f"HOBBIT does not fit at ({x:g}, {y:g})")
        with self.lock:
            self._x, self._y, self._theta = x, y, math.remainder(theta, math.tau)
            self._trail = deque([(x, y)], maxlen=TRAIL_POINTS)
            self.queue_sensors()
        self.flush()

    def _set_start(self):
        self._x = self._y = self._theta = 0.0
        self._linear = self._angular = 0.0
        self._base = _Velocity()
        self._trail = deque([(0.0, 0.0)], maxlen=TRAIL_POINTS)
        self._head, self._emotion = "center_center", "NEUTRAL"
        self._arm, self._arm_task = "home", None
        self._last_joints = list(ARM_JOINTS["home"])
        self._gripper, self._turntable, self._turntable_angle = "closed", "stored", 0.0
        self._battery, self._volume = 100.0, 50
        self._shown, self._notices = None, deque(maxlen=NOTICES_KEPT)
        self._bumps = 0
        self._contact = None        # the obstacle the base last bumped into, or None

    # --- life cycle -------------------------------------------------------------------

    def connect(self):
        """Subscribe and advertise HOBBIT's interface; the base motion starts Idle."""
        self.subscribe("/cmd_vel", self._on_velocity)
        self.subscribe("/DiscreteMotionCmd", self._on_discrete_motion)
        self.subscribe("/move_base_simple/goal", self._on_simple_goal)
        self.subscribe("/head/move", self._on_head)
        self.subscribe("/head/emo", self._on_emotion)
        self.world.advertise_action(ARM_ACTION, self._serve_arm)
        self.world.advertise_action(NAV_ACTION, self._serve_navigation)
        self.world.advertise_service("/MMUI", self._serve_mmui)
        self.queue(*MOTION_STATE, {"data": "Idle"})

    def safe_stop(self):
        """Stand still: zero velocity, no discrete motion, arm and navigation goals cancelled."""
        with self.lock:
            self._replace_base(_Velocity())
            self._halt_arm()
        self.flush()
        self.world.cancel_goals(ARM_ACTION)
        self.world.cancel_goals(NAV_ACTION)

    def snapshot(self) -> dict:
        """A copy of the robot's state for the simulator view."""
        with self.lock:
            task = self._arm_task
            return {
                "x": self._x, "y": self._y, "theta": self._theta, "trail": list(self._trail),
                "linear": self._linear, "angular": self._angular, "motion": self._base.motion,
                "nav_goal": (self._base.x, self._base.y) if isinstance(self._base, _Navigation) else None,
                "head": self._head, "emotion": self._emotion,
                "arm": self._arm, "arm_target": task.command.pose if task else None,
                "arm_progress": task.progress if task else 0.0,
                "gripper": self._gripper, "turntable": self._turntable, "turntable_angle": self._turntable_angle,
                "battery": self._battery, "volume": self._volume,
                "tablet": dict(self._shown) if self._shown else None, "notices": list(self._notices),
                "bumped": self._contact.id if self._contact else None, "bumps": self._bumps, "time": self.time,
            }

    # --- the clock --------------------------------------------------------------------

    def advance(self, dt):
        """Move the base and the arm ``dt`` simulated seconds on and drain the battery (under the lock)."""
        # a task found done now ended on the previous tick: its end is reported one control cycle after
        # its last step, so even a zero-length motion reports Idle a whole tick after it was commanded
        if self._base.done:
            self._replace_base(_Velocity())
        x, y, self._theta, self._linear, self._angular = self._base.step(self._x, self._y, self._theta, dt)
        self._move_to(x, y)
        if math.dist(self._trail[-1], (self._x, self._y)) >= TRAIL_SPACING:
            self._trail.append((self._x, self._y))
        self._advance_arm(dt)
        busy = self._linear or self._angular or self._arm_task
        self._battery = max(0.0, self._battery - dt * (BATTERY_DRAIN_BUSY if busy else BATTERY_DRAIN))

    def _move_to(self, x, y):
        """Slide the base straight to (x, y), stopping where it touches something: the bumper reports it."""
        distance = math.dist((self._x, self._y), (x, y))
        hit = None
        if distance > 0:
            stop_x, stop_y, _, hit = WORLD.move(self._x, self._y, math.atan2(y - self._y, x - self._x), distance, 0, 1)
            if hit is not None:   # else (x, y) as the motion says, without the sweep's rounding
                x, y = stop_x, stop_y
        if distance > 0 and self._contact is not None and WORLD.touching(x, y) is None:
            self._contact = None       # moved off what it had bumped into
        self._x, self._y = x, y
        if hit is not None:
            self._contact, self._bumps = hit, self._bumps + 1
            if isinstance(self._base, _Navigation):
                self._base.bumped = hit
            # what was hit and the bumper first, then the base's stop (Idle): a command sees the cause first
            self.queue(CONTACT_TOPIC, "std_msgs/String", {"data": hit.id})
            self.queue("/bumper", "std_msgs/Bool", {"data": True})
            self._replace_base(_Velocity())
            log.info("simulated HOBBIT: bumped into %s at (%.2f, %.2f)", hit.id, x, y)

    def _advance_arm(self, dt):
        task = self._arm_task
        if task is None:
            return
        task.progress = min(1.0, task.progress + dt / task.seconds)
        self._turntable_angle = (task.start_angle + task.command.turn * task.progress) % 360
        if task.progress == 1.0:
            command = task.command
            self._arm = command.pose or self._arm
            self._gripper = command.gripper or self._gripper
            self._turntable = command.turntable or self._turntable
            task.done = True
            self._arm_task = None

    def queue_sensors(self):
        """Odometry, battery, bumper and joint states, as HOBBIT publishes them every control cycle."""
        self.queue("/odom", "nav_msgs/Odometry", {
            "header": {"frame_id": "odom"}, "child_frame_id": "base_link",
            "pose": {"pose": _pose(self._x, self._y, self._theta)},
            "twist": {"twist": {"linear": {"x": self._linear, "y": 0.0, "z": 0.0},
                                "angular": {"x": 0.0, "y": 0.0, "z": self._angular}}}})
        self.queue("/battery_state", "sensor_msgs/BatteryState", {"percentage": self._battery / 100, "present": True})
        self.queue("/bumper", "std_msgs/Bool", {"data": False})   # a stopped base presses nothing
        self.queue("/joint_states", "sensor_msgs/JointState",
                   {"header": {"frame_id": "base_link"}, "name": list(ARM_JOINT_NAMES),
                    "position": self._joint_positions()})

    def _joint_positions(self):
        """The arm's six joints (radians) and the gripper opening, following the arm's motion."""
        here = ARM_JOINTS.get(self._arm, self._last_joints)
        task = self._arm_task
        there = ARM_JOINTS.get(task.command.pose, here) if task is not None and task.command.pose else here
        fraction = task.progress if task is not None else 0.0
        self._last_joints = [a + (b - a) * fraction for a, b in zip(here, there)]
        return self._last_joints + [GRIPPER_OPENING[self._gripper]]

    # --- base -------------------------------------------------------------------------

    def _replace_base(self, task):
        """Make ``task`` what the base does; the newest base command always wins."""
        old, self._base = self._base, task
        self._linear = self._angular = 0.0
        if isinstance(task, _DiscreteMotion):
            self.queue(*MOTION_STATE, {"data": MOTION_STATES[task.motion]})
        elif isinstance(old, _DiscreteMotion):
            self.queue(*MOTION_STATE, {"data": "Idle"})

    def _command_base(self, task):
        with self.lock:
            self._replace_base(task)
        self.flush()

    def _on_velocity(self, message):
        velocity = twist_velocity(message)
        if velocity is None:
            log.warning("simulated HOBBIT: ignored a /cmd_vel that is not a Twist: %r", message)
            return
        self._command_base(_Velocity(*velocity))

    def _on_discrete_motion(self, message):
        words = str(message.get("data", "")).split()
        if words == ["Stop"]:
            self._command_base(_Velocity())
            return
        try:
            kind, amount = words
            amount = float(amount)
        except ValueError:
            kind, amount = None, math.nan
        if kind not in ("Move", "Turn") or not math.isfinite(amount):
            log.warning("simulated HOBBIT: ignored the discrete motion %r", message.get("data"))
            return
        if kind == "Move":
            self._command_base(_DiscreteMotion("moving", amount))
        else:
            self._command_base(_DiscreteMotion("turning", math.radians(amount)))

    def _on_simple_goal(self, message):
        try:
            self._command_base(_Navigation(*_target_of(message)))
        except (AttributeError, TypeError, ValueError) as error:
            log.warning("simulated HOBBIT: ignored the navigation goal: %s", error)

    def _serve_navigation(self, goal, feedback, cancelled):
        try:
            task = _Navigation(*_target_of(goal.get("target_pose") or {}))
        except (AttributeError, TypeError, ValueError) as error:
            log.warning("simulated HOBBIT: aborted the navigation goal: %s", error)
            return GoalStatus.ABORTED, {}, str(error)
        problem = goal_problem(task.x, task.y)
        if problem is not None:
            return GoalStatus.ABORTED, {}, problem["en"]
        self._command_base(task)
        last_sent = None

        def base_position():
            nonlocal last_sent
            pose = (self._x, self._y, self._theta)
            if pose == last_sent:
                return None
            last_sent = pose
            return {"base_position": {"header": {"frame_id": "map"}, "pose": _pose(*pose)}}

        status = self._follow(task, lambda: self._base is task, lambda: self._replace_base(_Velocity()),
                              cancelled, feedback, base_position)
        if status is GoalStatus.PREEMPTED and task.bumped is not None:
            return GoalStatus.ABORTED, {}, blocked_on_the_way(task.bumped.id)["en"]
        return status, {}

    # --- head -------------------------------------------------------------------------

    def _on_head(self, message):
        position = message.get("data")
        if not isinstance(position, str) or position not in HEAD_POSITIONS:
            log.warning("simulated HOBBIT: unknown head position %r ignored", position)
            return
        with self.lock:
            self._head = position

    def _on_emotion(self, message):
        emotion = message.get("data")
        if not isinstance(emotion, str) or emotion not in EMOTIONS:  # the program hears it (on ROS: the log)
            raise RobotCommandError(TEXTS("sim_unknown_emotion", emotion=repr(emotion),
                                          known=", ".join(sorted(EMOTIONS))))
        with self.lock:
            self._emotion = emotion

    # --- arm --------------------------------------------------------------------------

    def _halt_arm(self):
        """Stop the arm where it is; an arm stopped between two poses is at unnamed joint values."""
        task = self._arm_task
        if task is not None and task.command.pose and task.progress > 0:
            self._arm = "joints"
        self._arm_task = None

    def _serve_arm(self, goal, feedback, cancelled):
        with self.lock:
            task = _arm_task_for(goal, self._turntable_angle)
            if task is None:
                return GoalStatus.ABORTED, {"result": {"data": False}}
            self._halt_arm()
            self._arm_task = task
        reported = None

        def progress():
            nonlocal reported
            quarter = int(task.progress * 4)
            if quarter == reported:
                return None
            reported = quarter
            return {"feedback": {"data": f"{task.name} {quarter * 25} %"}}

        status = self._follow(task, lambda: self._arm_task is task, self._halt_arm, cancelled, feedback, progress)
        return status, {"result": {"data": status is GoalStatus.SUCCEEDED}}

    # --- goals ------------------------------------------------------------------------

    def _follow(self, task, is_current, halt, cancelled, feedback, feedback_message):
        """Follow a started task until the robot leaves it: SUCCEEDED when done, else PREEMPTED.

        The task is left when it is done, replaced by a newer one, or halted because its goal was cancelled.

        ``feedback_message()`` (called under the lock) returns the feedback to send now, or None.
        """
        while True:
            with self.lock:
                message = feedback_message()
                if not is_current():
                    status = GoalStatus.SUCCEEDED if task.done else GoalStatus.PREEMPTED
                elif cancelled.is_set():
                    halt()
                    status = GoalStatus.PREEMPTED
                else:
                    status = None
            if message is not None:
                feedback(message)
            if status is not None:
                return status
            self.next_tick(cancelled)

    # --- tablet -------------------------------------------------------------------------

    def _serve_mmui(self, request, interrupt):
        params = {param.get("name"): param.get("value") for param in request.get("params") or []}
        kind, text = params.get("type"), str(params.get("text", ""))
        with self.lock:
            self._shown = None
        if kind in DIALOGS:
            return {"params": [{"name": "result", "value": self._ask(kind, text, _seconds(params.get("Timeout")),
                                                                     interrupt)}]}
        if kind == "D_PLAIN":
            with self.lock:
                self._shown = {"kind": kind, "text": text}
            self._notify(text)
        elif kind == "F_CALLSOS":
            self._notice("SOS call started")
        elif kind in ("F_LOUDER", "F_QUIETER"):
            with self.lock:
                step = VOLUME_STEP if kind == "F_LOUDER" else -VOLUME_STEP
                self._volume = min(100, max(0, self._volume + step))
                volume = self._volume
            self._notice(f"volume {volume} %")
        else:
            raise RobotCommandError(f"the tablet does not know the request type {kind!r}")
        return {"params": []}

    def _ask(self, kind, text, timeout, interrupt):
        if self.tablet is None:
            raise RobotCommandError(f"nobody can answer the tablet: {text!r}")
        shown = {"kind": kind, "text": text}
        with self.lock:
            self._shown = shown
        try:
            return str(self.tablet.ask(DIALOGS[kind], text, timeout, interrupt))
        finally:
            with self.lock:
                if self._shown is shown:
                    self._shown = None

    def _notice(self, text):
        with self.lock:
            self._notices.append(text)
        self._notify(text)

    def _notify(self, text):
        if self.tablet is not None:
            self.tablet.notify(text)


def _seconds(value):
    """A Timeout param as seconds; DIALOG_TIMEOUT when it is missing or not a positive number."""
    try:
        seconds = float(value)
    except (TypeError, ValueError):
        return DIALOG_TIMEOUT
    return seconds if math.isfinite(seconds) and seconds > 0 else DIALOG_TIMEOUT
