"""The helper's subscriptions, read by a thread of their own without rclpy's executor (runs in the ROS 2 helper).

rclpy's executor spends about 160 µs of Python on every turn, whatever woke it; for a message
that is most of its cost, and on a two-core machine that turn keeps Rockly's reading thread
from a core just when the message is on its way there. Subscriptions live on a node of their
own that no executor spins; one thread waits on them (rclpy's wait set, as the executor does)
and hands each message to its callback as it is taken. A guard condition wakes it when the
subscriptions change. rclpy's ``WaitSet`` is its own implementation's (the helper runs the
pinned rclpy of ``requirements-ros2.txt``).
"""
import contextlib
import threading
import time
import traceback

from rclpy.exceptions import InvalidHandle
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy

ERROR_PAUSE = 0.05  # after a turn that failed, so that a lasting fault does not spin


class TopicReader:
    """Subscriptions on ``node`` (never spun elsewhere), their messages given to their callbacks on one thread."""

    def __init__(self, node):
        self.node = node
        self._subscriptions = {}
        self._lock = threading.Lock()
        self._changed = node.create_guard_condition(lambda: None)
        self._running = True
        self._thread = threading.Thread(target=self._read, name="ros2-topics", daemon=True)
        self._thread.start()

    def subscribe(self, key, message_class, topic, callback, qos):
        """Subscribe ``topic``; ``callback(message)`` is called on the reading thread per message."""
        subscription = self.node.create_subscription(message_class, topic, callback, qos)
        with self._lock:
            self._subscriptions[key] = subscription
        self._changed.trigger()

    def unsubscribe(self, key):
        """Stop the subscription ``key`` (it is destroyed once the reading thread lets go of it)."""
        with self._lock:
            subscription = self._subscriptions.pop(key, None)
        if subscription is not None:
            self._changed.trigger()
            self.node.destroy_subscription(subscription)

    def close(self):
        """End the reading thread."""
        self._running = False
        self._changed.trigger()
        self._thread.join(timeout=1.0)

    def _read(self):
        context = self.node.context
        while self._running and context.ok():
            try:
                self._turn(context)
            except Exception:  # the reading goes on: the subscriptions are the panels' and the program's
                traceback.print_exc()
                time.sleep(ERROR_PAUSE)

    def _turn(self, context):
        """Wait until a subscription has a message (or they changed), and pass the messages on."""
        with self._lock:
            subscriptions = list(self._subscriptions.values())
        with contextlib.ExitStack() as held:  # a handle in use is not destroyed under the wait
            taken = []
            for subscription in subscriptions:
                try:
                    held.enter_context(subscription.handle)
                except InvalidHandle:
                    continue
                taken.append(subscription)
            held.enter_context(self._changed.handle)
            held.enter_context(context.handle)
            wait_set = _rclpy.WaitSet(len(taken), 1, 0, 0, 0, 0, context.handle)
            wait_set.clear_entities()
            for subscription in taken:
                wait_set.add_subscription(subscription.handle)
            wait_set.add_guard_condition(self._changed.handle)
            wait_set.wait(-1)
            ready = wait_set.get_ready_entities("subscription")
            for subscription in taken:
                if subscription.handle.pointer in ready:
                    self._deliver(subscription)

    @staticmethod
    def _deliver(subscription):
        message = subscription.handle.take_message(subscription.msg_type, subscription.raw)
        if message is None:
            return
        try:
            subscription.callback(message[0])
        except Exception:  # one message that cannot be passed on must not end the reading
            traceback.print_exc()
