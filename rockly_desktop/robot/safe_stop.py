"""Carrying out a profile's ``safe_stop`` list: what "stop" means for its robot."""
import logging

log = logging.getLogger(__name__)


def run_safe_stop(actions, backend) -> list:
    """Do every action (``{publish: {topic, type, message}}`` or ``{cancel_goals: ACTION}``).

    Each action is tried even if an earlier one failed; returns the failures' messages.
    """
    failures = []
    for action in actions:
        (kind, body), = action.items()
        try:
            if kind == "publish":
                backend.publish(body["topic"], body["type"], dict(body.get("message") or {}))
            else:
                backend.cancel_all_goals(body)
        except Exception as error:
            log.warning("safe stop %s %s failed: %s", kind, body, error)
            failures.append(f"{kind} {body}: {error}")
    return failures
