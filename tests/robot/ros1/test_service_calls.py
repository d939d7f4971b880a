"""Service calls on the caller's thread (robot/ros1/service_calls.py): the guard that cuts them,
and Stop and timeouts ending a call that waits on its connection, on a real master."""
import threading

import pytest
from waiting import eventually

from rockly_desktop.core.errors import ProgramStopped, RobotTimeout
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros1.service_calls import CallGuard

# -- the guard, without ROS ------------------------------------------------------------------------


def test_the_guard_cuts_a_wait_once_when_it_must_end():
    guard = CallGuard(poll=0.001)
    must_end, cuts = threading.Event(), []
    watched = guard.watch(must_end.is_set, lambda: cuts.append("cut"))
    must_end.set()
    eventually(lambda: cuts)
    assert guard.unwatch(watched) is True
    assert cuts == ["cut"]


def test_a_wait_that_is_over_before_it_must_end_is_not_cut():
    guard = CallGuard(poll=0.001)
    cuts = []
    watched = guard.watch(lambda: False, lambda: cuts.append("cut"))
    assert guard.unwatch(watched) is False
    assert cuts == []


def test_an_idle_guard_sleeps_and_wakes_for_the_next_wait():
    guard = CallGuard(poll=0.001, linger=0.01)
    guard.unwatch(guard.watch(lambda: False, lambda: None))
    eventually(lambda: guard.sleeping)
    must_end, cuts = threading.Event(), []
    watched = guard.watch(must_end.is_set, lambda: cuts.append("cut"))
    must_end.set()
    eventually(lambda: cuts)
    assert guard.unwatch(watched) is True


# -- on a real master ------------------------------------------------------------------------------

class HeldService:
    """A std_srvs/Trigger service in this process: the first call answers at once, later ones
    when ``release`` is set (a person still thinking about a question on the tablet)."""

    def __init__(self, name):
        import rospy
        from std_srvs.srv import Trigger, TriggerResponse

        self.name = name
        self.calls = 0
        self.answered = 0
        self.release = threading.Event()
        self._response = TriggerResponse
        self._service = rospy.Service(name, Trigger, self._answer)

    def _answer(self, _request):
        self.calls += 1
        if self.calls > 1:
            self.release.wait(30)
        self.answered += 1
        return self._response(True, f"answer {self.calls}")

    def close(self):
        self.release.set()
        self._service.shutdown()


@pytest.fixture(scope="module")
def graph(ros_master):
    from rockly_desktop.robot.ros1.backend import RosGraph
    from rockly_desktop.robot.ros1.connection import RosConnection
    from rockly_desktop.robot.ros1.message_classes import MessageTypes

    return RosGraph(RosConnection.get(ros_master.uri), MessageTypes())


@pytest.fixture
def held(graph, request):
    service = HeldService(f"/rockly_held_{request.node.name}")
    yield service
    service.close()


def backend(graph, interrupt=None):
    from rockly_desktop.robot.ros1.backend import Ros1Backend

    return Ros1Backend(graph, interrupt or Interrupt())


def connected(graph, held):
    """Make the first call (which connects); later calls then run on the caller's thread."""
    assert backend(graph).call_service(held.name, "std_srvs/Trigger", {}, 10) == {"success": True,
                                                                                    "message": "answer 1"}
    assert graph.service(held.name, "std_srvs/Trigger").transport is not None


def test_stop_ends_a_call_waiting_on_its_connection_and_the_next_call_connects_anew(graph, held):
    connected(graph, held)
    interrupt = Interrupt()
    threading.Thread(target=lambda: (eventually(lambda: held.calls == 2), interrupt.request_stop())).start()
    with pytest.raises(ProgramStopped):
        backend(graph, interrupt).call_service(held.name, "std_srvs/Trigger", {}, 30)
    assert held.answered == 1  # the call ended while the service still held its answer
    held.release.set()
    assert backend(graph).call_service(held.name, "std_srvs/Trigger", {}, 10)["message"] == "answer 3"


def test_a_call_waiting_on_its_connection_times_out_naming_the_service(graph, held):
    connected(graph, held)
    with pytest.raises(RobotTimeout, match=f"^the service '{held.name}' did not answer within 0.2 s$"):
        backend(graph).call_service(held.name, "std_srvs/Trigger", {}, 0.2)
    assert held.answered == 1
    held.release.set()
    assert backend(graph).call_service(held.name, "std_srvs/Trigger", {}, 10)["message"] == "answer 3"
