"""Whether the robot nodes a waiting command depends on are still alive.

The master's watchdog notices a lost master; a robot node that dies while the master
lives would only be noticed at the command's own timeout (two minutes for a motion).
A waiting command depends on the topics it listens to (an action's status, the odometry a
drive watches): twice a second the publishers the master lists for them are asked for
their pid. A killed node does not answer (the master keeps listing a node killed with
``kill -9``, so the list alone would not tell), and a topic whose publishers all stopped
answering ends the wait with RobotConnectionLost naming it. A node that only answers late
(a loaded computer) still counts as answering until it has been silent for SILENT_SECONDS.
A new publisher waits only for the subscribers that answer, so the safe stop after a lost
node does not wait for the dead.
"""
import threading
import time
import xmlrpc.client

from rockly_desktop.robot.ros1.connection import SILENT_SECONDS, ask_master

LOOK_SECONDS = 0.5


class NodeLiveness:
    """The publishers and subscribers of a topic the master lists and how many of them answer
    (thread-safe; the master and each node are asked at most every LOOK_SECONDS, unless fresh)."""

    def __init__(self, master_uri: str, own_node: str = None, ask=ask_master):
        self._master_uri = master_uri
        self._own_node = own_node
        self._ask = ask
        self._lock = threading.Lock()
        self._nodes = ({}, {})  # publishers, subscribers: topic -> [node names]
        self._state_at = -LOOK_SECONDS
        self._alive = {}  # node name -> (when looked, answers, when it last answered or was first looked at)

    def publishers(self, topic: str):
        """(listed, answering) publishers of ``topic``, this node left out; None when the master does not answer."""
        return self._count(0, topic, fresh=False)

    def subscribers(self, topic: str):
        """(listed, answering) subscribers of ``topic`` as the master lists them now (this node
        counts as answering); None when the master does not answer."""
        return self._count(1, topic, fresh=True)

    def _count(self, kind: int, topic: str, fresh: bool):
        with self._lock:
            now = time.monotonic()
            if fresh or now - self._state_at >= LOOK_SECONDS:
                try:
                    publishers, subscribers, _services = self._ask(self._master_uri, "getSystemState")
                except (OSError, xmlrpc.client.Error):
                    return None
                self._nodes, self._state_at = (dict(publishers), dict(subscribers)), now
            nodes = self._nodes[kind].get(topic, [])
            if kind == 0:  # this node's own publishing keeps nothing of the robot alive
                nodes = [node for node in nodes if node != self._own_node]
            return len(nodes), sum(1 for node in nodes if node == self._own_node or self._answers(node, now))

    def _answers(self, node: str, now: float) -> bool:
        looked_at, answers, heard_at = self._alive.get(node, (-LOOK_SECONDS, False, now))
        if now - looked_at >= LOOK_SECONDS:
            try:
                self._ask(self._ask(self._master_uri, "lookupNode", node), "getPid")
                answers, heard_at = True, now
            except TimeoutError:  # late (the node or the master is busy), not gone
                answers = now - heard_at < SILENT_SECONDS
            except (OSError, xmlrpc.client.Error):
                answers = False
            self._alive[node] = (now, answers, heard_at)
        return answers


class Dependencies:
    """The topics one backend's waits depend on: those its subscriptions listen to, plus those
    a wait names (an action's status). A wait that lasts asks ``gone()`` which of them lost
    every publisher: a listed publisher that does not answer (killed), or none listed any
    more where one answered before (shut down)."""

    def __init__(self, liveness: NodeLiveness):
        self._liveness = liveness
        self._listening = {}  # topic -> how many of this backend's subscriptions listen to it
        self._answered = set()  # topics a publisher answered for

    def listen(self, topic: str):
        """A subscription to ``topic`` started; returns the function that ends the dependency."""
        self._listening[topic] = self._listening.get(topic, 0) + 1

        def done():
            self._listening[topic] -= 1
            if not self._listening[topic]:
                del self._listening[topic]
        return done

    def gone(self, also=()):
        """The first topic depended on whose publishers are all gone, or None."""
        for topic in [*self._listening, *also]:
            state = self._liveness.publishers(topic)
            if state is None:  # the master does not answer: the connection watchdog says so
                return None
            listed, answering = state
            if answering:
                self._answered.add(topic)
            elif listed or topic in self._answered:
                return topic
        return None
