"""The state of each block that talks to the robot, from what its commands did: a block's badge.

A service call or a goal makes its block ``running``; the answer makes it ``succeeded``,
the goal's outcome ``succeeded``, ``aborted``, ``preempted`` or ``rejected``, a failure
``timed_out`` (a RobotTimeout), ``stopped`` (the person stopped the program: ProgramStopped) or
``failed``, each with the seconds it took. Fed live by
a run's recording and, for a replay, with the recorded commands up to a moment.
"""
_STARTS = ("call", "goal")
_FAILURES = {"RobotTimeout": "timed_out", "ProgramStopped": "stopped"}  # error class -> state


def _failure(text: str) -> str:
    """The state of a block whose command failed with ``text`` ("ErrorClass: message")."""
    return _FAILURES.get(text.split(":", 1)[0], "failed")


class BadgeStates:
    """``states``: block id -> (state, seconds or None); ``version`` grows with every change."""

    def __init__(self):
        self.states = {}
        self.version = 0

    def take(self, entry: dict):
        """Take one command entry (``robot/wrappers/recorded.py``'s, with its ``block``)."""
        block, kind = entry.get("block"), entry.get("kind")
        if block is None:
            return
        if kind in _STARTS:
            state = ("running", None)
        elif kind == "response":
            state = ("succeeded", entry.get("seconds"))
        elif kind == "outcome":
            state = (entry.get("status") or "succeeded", entry.get("seconds"))
        elif kind == "failed":
            state = (_failure(str(entry.get("text", ""))), entry.get("seconds"))
        else:
            return
        self.states = {**self.states, block: state}  # a new dict: readers in other threads see one or the other
        self.version += 1
