"""Running a profile's simulator as a real ROS 1 node: its SimWorld bridged to ROS.

The profile's manifest declares ``ros_interface`` (what the real robot subscribes,
publishes, serves and offers as actions, with ROS types). Messages from ROS go into the world;
what the simulator publishes goes out on ROS; services and actions are served by the
simulator's own handlers, with feedback and preemption passed through.

``SimulatorNode`` is the whole of ``rockly sim PROFILE --ros``: the node, the world, the
simulator and the bridge, its put-back service (``/rockly_sim/reset``), and their orderly end
(``shutdown``). It has no window of its own; whoever runs it may show ``node.simulator.snapshot()``
and answer its tablet.
"""
import logging
import threading
import time

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros1.message_values import from_message, to_message
from rockly_desktop.robot.sim.served_simulator import PUT_BACK_SERVICE, ServedSimulator

log = logging.getLogger(__name__)

CLOSE_WAIT_SECONDS = 2.0  # how long a shutdown waits for service calls in progress to answer


class SimRosBridge:
    """Connects ``world`` to ROS as ``interface`` says (rospy's node must already run)."""

    def __init__(self, world, interface: dict, types):
        import rospy

        self._rospy = rospy
        self._world = world
        self._types = types
        self._endpoints = []
        self._interrupt = Interrupt()  # stopped by close(): a question waiting for a person ends
        self._calls = 0
        self._calls_changed = threading.Condition()
        for topic, msg_type in interface.get("subscribes", {}).items():
            self._endpoints.append(rospy.Subscriber(
                topic, types.message_class(msg_type),
                lambda message, topic=topic, msg_type=msg_type: self._deliver(topic, msg_type, from_message(message))))
        for topic, msg_type in interface.get("publishes", {}).items():
            publisher = rospy.Publisher(topic, types.message_class(msg_type), queue_size=50)
            message_class = types.message_class(msg_type)
            world.subscribe(topic, lambda data, publisher=publisher, message_class=message_class:
                            publisher.publish(to_message(message_class, data)))
            self._endpoints.append(publisher)
        for name, srv_type in interface.get("services", {}).items():
            self._endpoints.append(rospy.Service(
                name, types.service_class(srv_type),
                lambda request, name=name, srv_type=srv_type: self._serve(name, srv_type, request)))
        self._action_servers = [self._serve_action(name, action_type)
                                for name, action_type in interface.get("actions", {}).items()]

    def _deliver(self, topic, msg_type, message):
        """Hand a message heard on ROS to the simulated robot; one it refuses is logged (a topic has no answer)."""
        try:
            self._world.publish(topic, msg_type, message)
        except RobotCommandError as refusal:
            log.warning("simulated robot: %s", refusal)

    def _serve(self, name, srv_type, request):
        with self._calls_changed:
            self._calls += 1
        try:
            response = self._world.call_service(name, from_message(request), self._interrupt)
        except ProgramStopped:
            raise RobotCommandError(app_local_text("ros_sim_shut_down", name=name)) from None
        finally:
            with self._calls_changed:
                self._calls -= 1
                self._calls_changed.notify_all()
        return to_message(self._types.service_class(srv_type)._response_class, response)

    @property
    def closing(self) -> bool:
        """True once ``close()`` was called."""
        return self._interrupt.stop_requested

    def close(self, timeout: float = CLOSE_WAIT_SECONDS):
        """End every wait of a service call in progress (the caller gets an error) and every
        goal (cancelled), waiting up to ``timeout`` s for the service calls to answer."""
        self._interrupt.request_stop()
        deadline = time.monotonic() + timeout
        with self._calls_changed:
            while self._calls and self._calls_changed.wait(max(0.0, deadline - time.monotonic())):
                pass
            if self._calls:
                log.warning("%d service call(s) still running at shutdown", self._calls)

    def _serve_action(self, name, action_type):
        import actionlib

        action_class, _goal_class, result_class, feedback_class = self._types.action_classes(action_type)
        server = None

        def execute(goal):
            sim_goal = self._world.send_goal(name, from_message(goal),
                                             lambda data: server.publish_feedback(to_message(feedback_class, data)))
            while not self._world.wait_for(lambda: sim_goal.outcome is not None, 0.02):
                if server.is_preempt_requested() or self.closing or self._rospy.is_shutdown():
                    sim_goal.cancelled.set()
            outcome = sim_goal.outcome
            result = to_message(result_class, outcome.result)
            if outcome.status is GoalStatus.SUCCEEDED:
                server.set_succeeded(result)
            elif outcome.status is GoalStatus.PREEMPTED:
                server.set_preempted(result)
            else:
                server.set_aborted(result, outcome.text)

        server = actionlib.SimpleActionServer(name, action_class, execute_cb=execute, auto_start=False)
        server.start()
        return server


class SimulatorNode(ServedSimulator):
    """``profile``'s simulator served on ROS by this process's node; ``shutdown()`` ends it all.

    ``tablet`` is the simulator's tablet port (``ask``/``notify``), called from ROS's
    service threads. Raises RocklyError when ROS or the master is not there.
    """

    def __init__(self, profile, types, master_uri=None, speed=1.0, tablet=None):
        import rospy

        from rockly_desktop.robot.ros1.connection import RosConnection
        from rockly_desktop.robot.sim.sim_world import SimWorld

        self.connection = RosConnection.get(master_uri)
        self.world = SimWorld()
        self.simulator = profile.create("simulator", self.world, tablet=tablet, speed=speed)
        self._bridge = SimRosBridge(self.world, profile.ros_interface, types)
        self.simulator.start()
        trigger = types.service_class("std_srvs/Trigger")
        rospy.Service(PUT_BACK_SERVICE, trigger, lambda _request: to_message(trigger._response_class, self.put_back()))

    @property
    def where(self) -> str:
        """The ROS master the node is registered with (the window names it)."""
        return self.connection.master_uri

    def _leave(self):
        """End the node: its publishers, subscribers and services are taken off the master."""
        self.connection.shutdown("rockly sim ended")


def serve_simulator(profile, connection: dict, speed: float = 1.0, tablet=None) -> SimulatorNode:
    """``profile``'s simulator on ROS 1 at ``connection``'s ``master`` (the registry's ``sim_server``)."""
    from rockly_desktop.robot.ros1.message_classes import MessageTypes

    return SimulatorNode(profile, MessageTypes(profile.message_folders), connection.get("master") or None,
                         speed, tablet)
