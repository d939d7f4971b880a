"""The topics a ROS state feed records into a StateStore: each subscribed once, a failing one said once.

Both ROS feeds (``ros1/state_feed.py``, ``ros2/state_feed.py``) poll their graph and hand every
topic here; how a topic's messages are reached is theirs (``callbacks_of``).
"""
import logging

log = logging.getLogger(__name__)


class FollowedTopics:
    """Records the messages of each topic ``follow`` is given into ``store``.

    ``callbacks_of(topic, msg_type)`` is the list of callbacks the topic's messages are handed to
    (subscribing on first use); it raises when the topic cannot be followed (its type unknown here).
    """

    def __init__(self, store, callbacks_of):
        self._store = store
        self._callbacks_of = callbacks_of
        self._subscribed = set()
        self._unknown = set()

    def follow(self, topic: str, msg_type: str):
        """Record ``topic``'s messages from now on (nothing when it is followed or cannot be already)."""
        if topic in self._subscribed or (topic, msg_type) in self._unknown:
            return
        try:
            callbacks = self._callbacks_of(topic, msg_type)
        except Exception as error:
            log.info("cannot follow %s (%s): %s", topic, msg_type, error)
            self._unknown.add((topic, msg_type))
            return
        callbacks.append(lambda message: self._store.record(topic, msg_type, message))
        self._subscribed.add(topic)
