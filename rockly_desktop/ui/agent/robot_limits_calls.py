"""``RobotLimitsOnRobot``: the robot's own limits (the agent's ``robot_limits``: the file every run on the robot
keeps, as ``rockly agent limits`` sets it there), read and kept from the window's Teacher tab. The agent is asked
off the window's thread (``AgentCalls``) the way the robot bar asks it (``AgentWay``); only a laptop paired as a
teacher is answered (the refusal says so)."""
from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.ui.agent.agent_bar import AgentWay
from rockly_desktop.ui.agent.agent_calls import AgentCalls


class RobotLimitsOnRobot:
    """The robot's limits through its agent at ``way``, for the QObject ``owner`` (answers after it is gone are
    dropped); refusals and failures are said in ``language``."""

    def __init__(self, owner, way: AgentWay, language: str):
        self._way, self._language = way, language
        self.calls = AgentCalls(owner)

    def read(self, then):
        """Ask for the robot's limits; ``then(limits, problem)`` on the window's thread: ``limits`` as the agent
        keeps them (``{"max_speed", "max_turn", "switched_off"}``), or None and why (``problem``)."""
        self._ask(lambda client: client.robot_limits(), then)

    def keep(self, limits: dict, then):
        """Keep ``limits`` as the robot's own; ``then(limits, problem)`` as ``read`` (what the robot keeps now)."""
        self._ask(lambda client: client.robot_limits(limits), then)

    def _ask(self, call, then):
        way, language = self._way, self._language

        def work():
            client = AgentClient(way.host or "", way.port, language, name="rockly window", via=way.via,
                                 graph_kind=way.graph_kind)
            try:
                return call(client)
            finally:
                client.close()

        self.calls.run(work, lambda limits, error: then(limits, error.message if isinstance(error, AgentError)
                                                       else None))
