"""Running a profile's simulator on ROS 2: its SimWorld bridged to the graph through the helper.

As on ROS 1 (``robot.ros1.sim_bridge``), the manifest's ``ros_interface`` says what the real
robot subscribes, publishes, serves and offers as actions. Messages from ROS 2 go into the
world; what the simulator publishes goes out; services and actions are answered by the
simulator's handlers (``helper.sim_serving`` holds the ROS 2 side, in the helper process). Endpoints whose
interface package ROS 2's environment lacks (a robot's own messages) are left out, said once.

``Ros2SimulatorNode`` is the whole of ``rockly sim PROFILE --ros2`` (made by ``serve_simulator``,
the registry's ``sim_server``).
"""
import logging
import threading

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.catalogue import LocalText
from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.client import Ros2Helper, words
from rockly_desktop.robot.ros2.environment import Ros2Settings, declared_distribution, ros2_name
from rockly_desktop.robot.sim.served_simulator import ServedSimulator
from rockly_desktop.robot.wrappers.ros_versions import base_types, converted, declared_type, ros_name

log = logging.getLogger(__name__)


class Ros2SimBridge:
    """Connects ``world`` to ROS 2 as ``interface`` says, through ``helper``; a topic ``wanted`` names
    ({ROS name: type}) is carried as that type (a Jazzy robot's TwistStamped ``/cmd_vel``), the world
    keeping the interface's."""

    def __init__(self, world, interface: dict, helper, wanted: dict = None):
        self._world = world
        self._helper = helper
        self._wanted = {ros_name(name): type_name for name, type_name in (wanted or {}).items()}
        self._interrupt = Interrupt()  # stopped by close(): a question waiting for a person ends
        self.left_out = []  # (name, type, why) of endpoints ROS 2 cannot carry here
        self._sids = []
        for topic, msg_type in interface.get("subscribes", {}).items():
            self._bridge_in(topic, msg_type)
        for topic, msg_type in interface.get("publishes", {}).items():
            self._bridge_out(topic, msg_type)
        for name in interface.get("services", {}):
            helper.on("sim_call", name, lambda data, name=name: self._serve(name, *data))
        for name in interface.get("actions", {}):
            helper.on("sim_goal", name, lambda data, name=name: self._execute(name, *data))
            helper.on("sim_cancel", name, self._cancel)
        self._goals = {}
        for name, type_name, why in helper.call("sim_serve", dict(interface.get("services", {})),
                                                 dict(interface.get("actions", {})), timeout=10.0):
            self._leave_out(name, type_name, words(why))

    def _bridge_in(self, topic, msg_type):
        sid = self._helper.new_id()
        wire_type = self._wanted.get(ros_name(topic), msg_type)
        self._helper.on("msg", sid, lambda data: self._world.publish(topic, msg_type,
                                                                     converted(data, wire_type, msg_type)))
        try:
            self._helper.call("subscribe", sid, topic, wire_type, timeout=10.0)
        except RobotCommandError as error:
            self._helper.off("msg", sid)
            self._leave_out(topic, msg_type, error)
            return
        self._sids.append(sid)

    def _bridge_out(self, topic, msg_type):
        wire_type = self._wanted.get(ros_name(topic), msg_type)
        try:
            self._helper.call("publish_first", topic, wire_type, None, timeout=10.0)
        except RobotCommandError as error:
            self._leave_out(topic, wire_type, error)
            return
        helper = self._helper

        def forward(data):
            if not helper.lost:
                helper.publish(topic, wire_type, converted(data, msg_type, wire_type))
        self._world.subscribe(topic, forward)

    def _leave_out(self, name, type_name, error):
        self.left_out.append((name, type_name, str(error)))
        log.info("not on ROS 2: %s (%s): %s", name, type_name, error)

    def _serve(self, name, rid, request):
        threading.Thread(target=self._answer, args=(name, rid, request), daemon=True,
                         name=f"rockly-sim-call-{name}").start()

    def _answer(self, name, rid, request):
        try:
            response = self._world.call_service(name, request, self._interrupt)
        except (ProgramStopped, RobotCommandError) as error:
            log.warning("the simulated service %s failed: %s", name, error)
            self._helper.cast("sim_answer", rid, False, None)
            return
        if not self._helper.lost:
            self._helper.cast("sim_answer", rid, True, response)

    def _execute(self, name, gid, goal):
        helper = self._helper

        def feedback(data):
            if not helper.lost:
                helper.cast("sim_feedback", gid, data)

        sim_goal = self._world.send_goal(name, goal, feedback)
        self._goals[gid] = sim_goal
        threading.Thread(target=self._finish, args=(gid, sim_goal), daemon=True,
                         name=f"rockly-sim-goal-{name}").start()

    def _finish(self, gid, sim_goal):
        while not self._world.wait_for(lambda: sim_goal.outcome is not None, 0.02):
            if self._interrupt.stop_requested:
                sim_goal.cancelled.set()
        self._goals.pop(gid, None)
        outcome = sim_goal.outcome
        if not self._helper.lost:
            self._helper.cast("sim_goal_end", gid, outcome.status.value, outcome.result, outcome.text)

    def _cancel(self, gid):
        sim_goal = self._goals.get(gid)
        if sim_goal is not None:
            sim_goal.cancelled.set()

    def close(self):
        """End waiting questions and goals (cancelled); the helper's servers end with it."""
        self._interrupt.request_stop()


class Ros2SimulatorNode(ServedSimulator):
    """``profile``'s simulator served on ROS 2 through this process's helper; ``shutdown()`` ends it.

    ``tablet`` is the simulator's tablet port; ``ros_distribution`` the ROS 2 distribution it plays
    (its topics as a robot of that one has them: a Jazzy robot's TwistStamped ``/cmd_vel``; None:
    ROS 2's usual types). Raises Ros2Unavailable when ROS 2 is not set up.
    """

    def __init__(self, profile, settings: Ros2Settings = None, speed=1.0, tablet=None, ros_distribution: str = None):
        from rockly_desktop.robot.sim.sim_world import SimWorld

        self.settings = settings or Ros2Settings()
        self.ros_distribution = ros_distribution
        self.helper = Ros2Helper.get(self.settings)
        self.world = SimWorld()
        self.simulator = profile.create("simulator", self.world, tablet=tablet, speed=speed)
        self._bridge = Ros2SimBridge(self.world, profile.ros_interface, self.helper,
                                     played_types(profile, ros_distribution))
        self.simulator.start()

    @property
    def where(self) -> LocalText:
        """'ROS 2, domain 7, localhost' ('ROS 2 Jazzy, …' playing a distribution) for the window and the console."""
        return app_local_text("ros2_link_where", ros=ros2_name(self.ros_distribution), where=self.settings.describe())

    @property
    def left_out(self) -> list:
        """(name, type, why) of the robot's endpoints ROS 2's environment cannot carry."""
        return list(self._bridge.left_out)

    def _leave(self):
        """End the helper (its servers and publishers with it)."""
        Ros2Helper.close_current()


def played_types(profile, distribution: str = None) -> dict:
    """{ROS name: type} of the names ``profile``'s ``ros_versions`` vary, as a ROS 2 robot of ``distribution``
    has them."""
    bases = base_types(profile.ros_interface)
    return {ros_name(name): declared_type(bases.get(ros_name(name)), variants, "ros2", distribution)
            for name, variants in (getattr(profile, "ros_versions", None) or {}).items()}


def serve_simulator(profile, connection: dict, speed: float = 1.0, tablet=None) -> Ros2SimulatorNode:
    """``profile``'s simulator on ROS 2 with ``connection``'s domain id, discovery range, peers and
    the ROS 2 distribution it plays (the registry's ``sim_server``, ``rockly sim PROFILE --ros2``)."""
    return Ros2SimulatorNode(profile, Ros2Settings.from_connection(connection), speed, tablet,
                             declared_distribution(connection))
