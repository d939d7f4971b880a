"""The in-process ROS stand-in (rockly_desktop/robot/sim/sim_world.py): topics, services, actions, stops."""
import threading
import time

import pytest
from background import Background

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError, RobotTimeout
from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

STOP_BOUND = 0.05  # s from a stop request to ProgramStopped in the waiting thread
SHORT = 0.05       # s, a timeout that should run out


class ObservedWorld(SimWorld):
    """A SimWorld that tells the test when someone subscribed or started waiting, and counts subscriptions."""

    def __init__(self):
        super().__init__()
        self.subscribed = threading.Event()
        self.waiting = threading.Event()
        self.subscriptions = 0

    def subscribe(self, topic, callback):
        unsubscribe = super().subscribe(topic, callback)
        self.subscriptions += 1
        self.subscribed.set()

        def counted_unsubscribe():
            unsubscribe()
            self.subscriptions -= 1

        return counted_unsubscribe

    def wait_for(self, predicate, timeout):
        self.waiting.set()
        return super().wait_for(predicate, timeout)


def held_until(event):
    """An action handler whose goals succeed once ``event`` is set."""
    def handler(goal, send_feedback, cancelled):
        event.wait(30)
        return GoalStatus.SUCCEEDED, {}

    return handler


def seconds_from_stop_to_raise(interrupt, started, wait):
    """Run ``wait()`` in a thread, request a stop once ``started`` is set; seconds until it raised ProgramStopped."""
    call = Background(wait)
    assert started.wait(5)
    stopped_at = time.monotonic()
    interrupt.request_stop()
    call.join()
    assert isinstance(call.error, ProgramStopped), call.error
    return call.ended_at - stopped_at


@pytest.fixture
def world():
    return ObservedWorld()


@pytest.fixture
def interrupt():
    return Interrupt()


@pytest.fixture
def backend(world, interrupt):
    return SimBackend(world, interrupt)


@pytest.fixture
def release():
    """Set at the end of a test so that goal handlers still running finish."""
    event = threading.Event()
    yield event
    event.set()


# --- topics -----------------------------------------------------------------------------


def test_latest_is_none_until_a_message_arrives(backend):
    assert backend.latest("/chatter", "std_msgs/String") is None


def test_published_message_is_the_latest_and_is_listed_with_its_type(world, backend):
    message = {"linear": {"x": 0.2}}
    backend.publish("/cmd_vel", "geometry_msgs/Twist", message)
    backend.publish("/chatter", "std_msgs/String", {"data": "one"})
    backend.publish("/chatter", "std_msgs/String", {"data": "two"})
    message["linear"]["x"] = 9.0  # the publisher's dict is not the stored one

    assert backend.latest("/cmd_vel", "geometry_msgs/Twist") == {"linear": {"x": 0.2}}
    assert world.latest("/chatter") == {"data": "two"}
    assert world.topics() == [("/chatter", "std_msgs/String"), ("/cmd_vel", "geometry_msgs/Twist")]


def test_latest_returns_a_copy(world):
    world.publish("/pose", "geometry_msgs/Pose", {"position": {"x": 1.0}})
    world.latest("/pose")["position"]["x"] = 5.0
    assert world.latest("/pose") == {"position": {"x": 1.0}}


def test_every_subscriber_gets_each_message_until_it_unsubscribes(world):
    first, second = [], []
    unsubscribe = world.subscribe("/chatter", first.append)
    world.subscribe("/chatter", second.append)
    world.publish("/chatter", "std_msgs/String", {"data": "a"})
    unsubscribe()
    world.publish("/chatter", "std_msgs/String", {"data": "b"})
    world.publish("/other", "std_msgs/String", {"data": "c"})

    assert first == [{"data": "a"}]
    assert second == [{"data": "a"}, {"data": "b"}]


def test_a_subscriber_may_publish_from_its_callback(world):
    world.subscribe("/ping", lambda message: world.publish("/pong", "std_msgs/Int64", {"data": message["data"] + 1}))
    world.publish("/ping", "std_msgs/Int64", {"data": 1})
    assert world.latest("/pong") == {"data": 2}


def test_wait_for_message_returns_the_next_message_not_the_stored_one(world, backend):
    world.publish("/state", "std_msgs/String", {"data": "old"})
    call = Background(lambda: backend.wait_for_message("/state", "std_msgs/String", 5))
    assert world.subscribed.wait(5)
    world.publish("/state", "std_msgs/String", {"data": "new"})
    world.publish("/state", "std_msgs/String", {"data": "newer"})
    assert call.join().result == {"data": "new"}


def test_wait_for_message_times_out_naming_the_topic(backend):
    started = time.monotonic()
    with pytest.raises(RobotTimeout, match=r"^no message arrived on the topic '/DiscreteMotionState' within 0.05 s$"):
        backend.wait_for_message("/DiscreteMotionState", "std_msgs/String", SHORT)
    assert time.monotonic() - started >= SHORT


def test_wait_for_message_leaves_no_subscription_behind(world, backend):
    with pytest.raises(RobotTimeout):
        backend.wait_for_message("/state", "std_msgs/String", 0.01)
    world.subscribed.clear()
    call = Background(lambda: backend.wait_for_message("/state", "std_msgs/String", 5))
    assert world.subscribed.wait(5)
    world.publish("/state", "std_msgs/String", {"data": "x"})
    call.join()
    assert world.subscriptions == 0


# --- services ---------------------------------------------------------------------------


def test_service_call_runs_the_handler_with_the_request_and_the_interrupt(world, backend, interrupt):
    calls = []

    def add(request, handler_interrupt):
        calls.append((request, handler_interrupt))
        return {"sum": request["a"] + request["b"]}

    world.advertise_service("/add", add)
    request = {"a": 2, "b": 3}
    assert backend.call_service("/add", "test_srvs/Add", request, SHORT) == {"sum": 5}
    assert calls == [({"a": 2, "b": 3}, interrupt)]
    assert calls[0][0] is not request


def test_unknown_service_times_out_naming_it(backend):
    started = time.monotonic()
    with pytest.raises(RobotTimeout, match=r"^the service '/MMUI' is not available \(waited 0.05 s\)$"):
        backend.call_service("/MMUI", "hobbit_msgs/Request", {}, SHORT)
    assert time.monotonic() - started >= SHORT


def test_service_advertised_while_the_caller_waits_is_called(world, backend):
    call = Background(lambda: backend.call_service("/late", "std_srvs/Trigger", {}, 5))
    assert world.waiting.wait(5)
    world.advertise_service("/late", lambda request, interrupt: {"success": True})
    assert call.join().result == {"success": True}


def test_service_handler_failure_is_a_command_error_naming_the_service(world, backend):
    def broken(request, interrupt):
        raise KeyError("params")

    world.advertise_service("/broken", broken)
    with pytest.raises(RobotCommandError, match=r"^the service '/broken' failed: 'params'$"):
        backend.call_service("/broken", "std_srvs/Trigger", {}, SHORT)


def test_service_handler_command_error_reaches_the_caller_unchanged(world, backend):
    def refuse(request, interrupt):
        raise RobotCommandError("nobody can answer the tablet: 'Hi'")

    world.advertise_service("/MMUI", refuse)
    with pytest.raises(RobotCommandError, match=r"^nobody can answer the tablet: 'Hi'$"):
        backend.call_service("/MMUI", "hobbit_msgs/Request", {}, SHORT)


# --- actions ----------------------------------------------------------------------------


def test_goal_to_an_unknown_action_server_is_refused_naming_it(backend):
    with pytest.raises(RobotCommandError, match=r"^there is no action server 'hobbit_arm'$"):
        backend.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", {})


def test_goal_runs_in_its_own_thread_and_sends_feedback_and_result(world, backend):
    handler_threads, feedback_threads, feedback = [], [], []

    def count(goal, send_feedback, cancelled):
        handler_threads.append(threading.get_ident())
        for number in range(goal["to"]):
            send_feedback({"at": number})
        return GoalStatus.SUCCEEDED, {"counted": goal["to"]}

    def on_feedback(message):
        feedback_threads.append(threading.get_ident())
        feedback.append(message)

    world.advertise_action("count", count)
    outcome = backend.send_goal("count", "test_msgs/CountAction", {"to": 3}, on_feedback).wait(5)

    assert (outcome.status, outcome.result) == (GoalStatus.SUCCEEDED, {"counted": 3})
    assert feedback == [{"at": 0}, {"at": 1}, {"at": 2}]
    assert handler_threads[0] != threading.get_ident()
    assert set(feedback_threads) == set(handler_threads)


def test_cancelled_goal_ends_preempted(world, backend):
    def until_cancelled(goal, send_feedback, cancelled):
        assert cancelled.wait(5)
        return GoalStatus.PREEMPTED, {"stopped": True}

    world.advertise_action("work", until_cancelled)
    handle = backend.send_goal("work", "test_msgs/WorkAction", {})
    handle.cancel()
    outcome = handle.wait(5)
    assert (outcome.status, outcome.result) == (GoalStatus.PREEMPTED, {"stopped": True})


def test_goal_wait_times_out_naming_the_action(world, backend, release):
    world.advertise_action("slow", held_until(release))
    handle = backend.send_goal("slow", "test_msgs/SlowAction", {})
    started = time.monotonic()
    with pytest.raises(RobotTimeout, match=r"^the action 'slow' did not finish within 0.05 s$"):
        handle.wait(SHORT)
    assert time.monotonic() - started >= SHORT


def test_cancel_all_goals_cancels_every_goal_of_that_action_from_any_backend(world, interrupt, release):
    def until_cancelled(goal, send_feedback, cancelled):
        return (GoalStatus.PREEMPTED if cancelled.wait(5) else GoalStatus.SUCCEEDED), {}

    world.advertise_action("arm", until_cancelled)
    world.advertise_action("base", held_until(release))
    program = SimBackend(world, interrupt)
    arm_goals = [program.send_goal("arm", "t/ArmAction", {}) for _ in range(2)]
    base_goal = program.send_goal("base", "t/BaseAction", {})

    SimBackend(world, Interrupt()).cancel_all_goals("arm")  # e.g. the safe stop's own backend

    assert [goal.wait(5).status for goal in arm_goals] == [GoalStatus.PREEMPTED, GoalStatus.PREEMPTED]
    with pytest.raises(RobotTimeout):
        base_goal.wait(SHORT)
    release.set()
    assert base_goal.wait(5).status is GoalStatus.SUCCEEDED


def test_action_server_that_fails_aborts_the_goal(world, backend):
    def broken(goal, send_feedback, cancelled):
        raise ValueError("no arm")

    world.advertise_action("broken", broken)
    outcome = backend.send_goal("broken", "test_msgs/BrokenAction", {}).wait(5)
    assert (outcome.status, outcome.result) == (GoalStatus.ABORTED, {})


# --- stop requests ----------------------------------------------------------------------


def test_stop_interrupts_a_message_wait(world, backend, interrupt):
    delay = seconds_from_stop_to_raise(
        interrupt, world.waiting, lambda: backend.wait_for_message("/never", "std_msgs/String", 30))
    assert delay < STOP_BOUND


def test_stop_interrupts_waiting_for_a_service(world, backend, interrupt):
    delay = seconds_from_stop_to_raise(
        interrupt, world.waiting, lambda: backend.call_service("/missing", "std_srvs/Trigger", {}, 30))
    assert delay < STOP_BOUND


def test_stop_interrupts_a_service_handler_that_waits_on_the_interrupt(world, backend, interrupt):
    asked = threading.Event()

    def dialog(request, handler_interrupt):
        asked.set()
        handler_interrupt.wait_until(lambda: False, 30)
        return {}

    world.advertise_service("/dialog", dialog)
    delay = seconds_from_stop_to_raise(interrupt, asked, lambda: backend.call_service("/dialog", "t/Dialog", {}, 30))
    assert delay < STOP_BOUND


def test_stop_interrupts_a_goal_wait(world, backend, interrupt, release):
    world.advertise_action("slow", held_until(release))
    handle = backend.send_goal("slow", "test_msgs/SlowAction", {})
    delay = seconds_from_stop_to_raise(interrupt, world.waiting, lambda: handle.wait(30))
    assert delay < STOP_BOUND


def test_stop_interrupts_a_sleep(backend, interrupt):
    sleeping = threading.Event()

    def sleep():
        sleeping.set()
        backend.sleep(30)

    assert seconds_from_stop_to_raise(interrupt, sleeping, sleep) < STOP_BOUND


def test_after_a_stop_waits_raise_at_once_but_publishing_still_works(world, backend, interrupt):
    interrupt.request_stop()
    with pytest.raises(ProgramStopped):
        backend.wait_for_message("/state", "std_msgs/String", 30)
    backend.publish("/cmd_vel", "geometry_msgs/Twist", {})  # the safe stop publishes after the stop
    assert world.latest("/cmd_vel") == {}
