"""What a run sends to its robot and what comes back, told to a recording.

``RecordedBackend`` wraps the run's RobotBackend (whatever the robot: simulator, ROS 1,
what comes next) and calls ``note(entry)`` for each publish, service call, goal and
cancel, and for each response, feedback, goal outcome and failure, with the seconds a
call or goal took. Entries are plain dicts: ``kind``, ``name`` (topic, service or
action), and ``type``, ``data``, ``status``, ``text``, ``seconds`` where they apply.
"""
import time

from rockly_desktop.robot.interface import GoalHandle, RobotBackend
from rockly_desktop.robot.wrappers.wrapped_backend import WrappedBackend


def _failed(name: str, error: Exception, started: float) -> dict:
    return {"kind": "failed", "name": name, "text": f"{type(error).__name__}: {error}",
            "seconds": time.monotonic() - started}


class RecordedGoal(GoalHandle):
    """A goal whose feedback, outcome and cancel are noted."""

    def __init__(self, inner: GoalHandle, action: str, note, started: float):
        self._inner = inner
        self._action = action
        self._note = note
        self._started = started
        self._ended = False

    def done(self) -> bool:
        """True once the goal has ended."""
        return self._inner.done()

    def wait(self, timeout: float):
        """Wait for the goal's outcome (noted once, with the time since it was sent)."""
        try:
            outcome = self._inner.wait(timeout)
        except Exception as error:
            self._note(_failed(self._action, error, self._started))
            raise
        if not self._ended:
            self._ended = True
            self._note({"kind": "outcome", "name": self._action, "status": outcome.status.value,
                        "text": outcome.text, "data": outcome.result, "seconds": time.monotonic() - self._started})
        return outcome

    def cancel(self) -> None:
        """Cancel the goal (noted)."""
        self._note({"kind": "cancel", "name": self._action})
        self._inner.cancel()


class RecordedBackend(WrappedBackend):
    """A RobotBackend that tells ``note(entry)`` what the program sent and what came back."""

    def __init__(self, inner: RobotBackend, note):
        super().__init__(inner)
        self._note = note

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish (noted before it goes, so a refused one is noted with its failure)."""
        self._note({"kind": "publish", "name": topic, "type": msg_type, "data": message})
        started = time.monotonic()
        try:
            self._inner.publish(topic, msg_type, message)
        except Exception as error:
            self._note(_failed(topic, error, started))
            raise

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service; the request, then the response or the failure, are noted."""
        self._note({"kind": "call", "name": name, "type": srv_type, "data": request})
        started = time.monotonic()
        try:
            response = self._inner.call_service(name, srv_type, request, timeout)
        except Exception as error:
            self._note(_failed(name, error, started))
            raise
        self._note({"kind": "response", "name": name, "type": srv_type, "data": response,
                    "seconds": time.monotonic() - started})
        return response

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None):
        """Send a goal; its feedback and outcome are noted as they come."""
        self._note({"kind": "goal", "name": action, "type": action_type, "data": goal})
        started = time.monotonic()

        def on_feedback(message):
            self._note({"kind": "feedback", "name": action, "data": message})
            if feedback is not None:
                feedback(message)

        try:
            handle = self._inner.send_goal(action, action_type, goal, on_feedback)
        except Exception as error:
            self._note(_failed(action, error, started))
            raise
        return RecordedGoal(handle, action, self._note, started)

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every goal on ``action`` (noted)."""
        self._note({"kind": "cancel", "name": action})
        self._inner.cancel_all_goals(action)

