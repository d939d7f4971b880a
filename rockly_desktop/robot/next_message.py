"""Waiting for a topic's next message, as the ROS backends do it: a subscription and an
interruptible wait for its event."""
import threading

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotTimeout


def next_message(backend, topic: str, msg_type: str, timeout: float, grace: float = 0.0) -> dict:
    """The next message on ``topic`` through ``backend``'s ``subscribe`` and ``wait_for_event``;
    RobotTimeout naming the topic after ``timeout`` seconds (and ``grace`` more, which the words do not count)."""
    received, arrived = [], threading.Event()
    unsubscribe = backend.subscribe(topic, msg_type, lambda message: (received.append(message), arrived.set()))
    try:
        if not backend.wait_for_event(arrived, timeout + grace):
            raise RobotTimeout(app_local_text("sim_no_message", topic=topic, timeout=timeout))
    finally:
        unsubscribe()
    return received[0]
