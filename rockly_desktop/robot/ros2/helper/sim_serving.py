"""Serving a simulator's services and actions on ROS 2 (runs in the helper process).

The simulated world lives in Rockly's process; here its servers are ROS 2 endpoints of a
second node, ``rockly_sim``, spun by a multi-threaded executor, so that a call waiting for
the world (a tablet question may wait for a person) holds one thread, not the helper's node.
A request goes to Rockly as a ``sim_call`` event and waits for its ``sim_answer``; a goal
goes as ``sim_goal``, a cancel request as ``sim_cancel``, and Rockly answers with
``sim_feedback`` and ``sim_goal_end``.
"""
import itertools
import threading

from rclpy.action import ActionServer, CancelResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor

from rockly_desktop.robot.ros2.helper.ros_values import from_message, interface_class, to_message

ANSWER_WAIT = 600.0  # a person may take a while to answer a tablet question
POLL_SECONDS = 0.02


class SimServing:
    """The ``rockly_sim`` node and the calls and goals waiting for Rockly's world."""

    def __init__(self, rclpy, event):
        self._event = event
        self.node = rclpy.create_node("rockly_sim")
        self._group = ReentrantCallbackGroup()
        self._executor = MultiThreadedExecutor(8)
        self._executor.add_node(self.node)
        self._spin = threading.Thread(target=self._executor.spin, name="ros2-sim-spin", daemon=True)
        self._spin.start()
        self._ids = itertools.count(1)
        self._waiting = {}   # request id -> [Event, answer]
        self._goals = {}     # goal id -> (server goal handle, [Event, end], feedback class)
        self._endpoints = []

    def serve(self, name, type_name):
        """A service whose requests the world answers."""
        service_class = interface_class(type_name, "srv")

        def answer(request, response):
            rid = next(self._ids)
            entry = self._waiting[rid] = [threading.Event(), None]
            self._event("sim_call", name, (rid, from_message(request)))
            if not entry[0].wait(ANSWER_WAIT):
                self._waiting.pop(rid, None)
                return response
            ok, data = self._waiting.pop(rid)[1]
            return to_message(service_class.Response, data) if ok else response

        self._endpoints.append(self.node.create_service(service_class, name, answer, callback_group=self._group))

    def answer(self, rid, ok, data):
        entry = self._waiting.get(rid)
        if entry is not None:
            entry[1] = (ok, data)
            entry[0].set()

    def offer(self, name, type_name):
        """An action server whose goals the world works on."""
        action_class = interface_class(type_name, "action")

        def execute(goal_handle):
            gid = next(self._ids)
            end = [threading.Event(), None]
            self._goals[gid] = (goal_handle, end, action_class.Feedback)
            self._event("sim_goal", name, (gid, from_message(goal_handle.request)))
            told = False
            while not end[0].wait(POLL_SECONDS):
                if goal_handle.is_cancel_requested and not told:
                    self._event("sim_cancel", name, gid)
                    told = True
            self._goals.pop(gid, None)
            status, result, _text = end[1]
            if status == "succeeded":
                goal_handle.succeed()
            elif status == "preempted" and goal_handle.is_cancel_requested:
                goal_handle.canceled()
            else:
                goal_handle.abort()
            return to_message(action_class.Result, result)

        self._endpoints.append(ActionServer(self.node, action_class, name, execute, callback_group=self._group,
                                            cancel_callback=lambda _request: CancelResponse.ACCEPT))

    def feedback(self, gid, data):
        entry = self._goals.get(gid)
        if entry is not None:
            entry[0].publish_feedback(to_message(entry[2], data))

    def goal_end(self, gid, status, result, text):
        entry = self._goals.get(gid)
        if entry is not None:
            entry[1][1] = (status, result, text)
            entry[1][0].set()

    def close(self):
        """End every waiting call (default response) and goal (aborted), then the node."""
        for rid in list(self._waiting):
            self.answer(rid, False, None)
        for gid in list(self._goals):
            self.goal_end(gid, "aborted", {}, "the simulator ended")
        self._executor.shutdown(timeout_sec=1.0)
        self._spin.join(timeout=1.0)
        self.node.destroy_node()
