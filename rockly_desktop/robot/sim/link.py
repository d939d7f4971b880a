"""The built-in simulator as a robot link (``robot/link.py``): the profile's simulator in this process."""
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import DefinitionNotLearnt
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot import link_parts, links
from rockly_desktop.robot.health import GREEN, HealthItem, server_health, topic_health
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.wrappers.ros_versions import ros_name, short_type


def listened_types(profile) -> dict:
    """{topic: {types}} the profile's simulated robot subscribes with: its ``ros_interface`` type and
    the ones ``ros_versions`` give the name on other versions (a simulator takes either)."""
    listens = {}
    for topic, type_name in (profile.ros_interface.get("subscribes") or {}).items():
        variants = (profile.ros_versions.get(topic) or profile.ros_versions.get(ros_name(topic)) or {}).values()
        listens[ros_name(topic)] = {short_type(name) for name in (type_name, *variants)}
    return listens


class SimulatedRobot:
    """A profile's simulator running in this process for the whole session.

    ``tablet`` answers the robot's tablet dialogs (a window, or the CLI's --answer list); with
    ``clock=False`` simulated time passes only when something calls ``simulator.step(dt)`` (a lesson's check).
    """

    kind = "sim"
    ros_version = None  # a simulator takes what a profile declares for either ROS version
    ros_distribution = None  # the ROS 2 distribution the robot plays (robot/wrappers/ros_versions.py); None: none

    def __init__(self, profile, tablet=None, speed: float = 1.0, clock: bool = True):
        self.profile = profile
        self.world = SimWorld()
        self.state = StateStore()
        self.world.tap(self.state.record)
        self.simulator = profile.create("simulator", self.world, tablet=tablet, speed=speed)
        self.simulator.start(clock=clock)
        self._encoder = None
        self._listens = listened_types(profile)
        self._published = set()  # the topics programs published on (the simulated robot's commands, made blocks')

    @classmethod
    def unavailable(cls):
        """The simulator is always there."""
        return None

    @classmethod
    def open(cls, profile, connection: dict = None, *, tablet=None, speed: float = 1.0, timeout: float = 5.0):
        """The profile's simulator, started now (it needs no connection; ``ros_distribution`` in
        ``connection`` makes it the robot of that ROS 2 distribution, e.g. 'jazzy')."""
        robot = cls(profile, tablet=tablet, speed=speed)
        robot.ros_distribution = (connection or {}).get("ros_distribution")
        return robot

    @property
    def world_id(self):
        """The fingerprint of the simulator's solid world (``World.fingerprint``), None when it has none."""
        world = self.simulator.solid_world
        return world.fingerprint() if world is not None else None

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped; a message the simulated robot
        would not get on a real ROS (another type than it listens for, values that do not fit) is refused."""
        return SimBackend(self.world, interrupt, self._listens, self.profile.ros_types, published=self._published)

    def follow_graph(self):
        """Nothing to start: the simulated world fills ``state`` from the beginning."""

    def want_parameters(self, wanted: bool):
        """Nothing to ask: the simulated world's parameters are read where they are."""

    def status(self):
        """A simulator in this process has no connection to lose."""
        return None

    def warnings(self) -> list:
        """Nothing to warn about."""
        return []

    def snapshot(self) -> dict:
        """The simulated robot's state, for the simulator view."""
        return self.simulator.snapshot()

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the simulated robot's topics: the simulated robot publishes each,
        except those only programs published on (Rockly's own: ``own_publishers``)."""
        robots = self.profile.ros_interface.get("publishes") or {}
        return [(topic, msg_type, int(topic in robots or topic not in self._published))
                for topic, msg_type in self.world.topics()]

    def graph_services(self) -> list:
        """(service, type) of the simulated robot's services, typed as its profile declares them ("" if not)."""
        declared = self.profile.ros_interface.get("services") or {}
        return [(name, declared.get(name, "")) for name in self.world.services()]

    def graph_actions(self) -> list:
        """(action, type) of the simulated robot's action servers, typed as its profile declares them."""
        declared = self.profile.ros_interface.get("actions") or {}
        return [(name, declared.get(name, "")) for name in self.world.actions()]

    def graph_parameters(self) -> list:
        """The names of the simulated robot's parameters."""
        return sorted(self.world.params.copy())  # a run may set one meanwhile

    def interface_definition(self, kind: str, name: str, type_name: str):
        """The simulated robot offers only what its profile defines: nothing more to learn."""
        raise DefinitionNotLearnt(app_local_text("maker_fields_unknown", type=type_name))

    @classmethod
    def read_definition(cls, profile, connection: dict, kind: str, name: str, type_name: str):
        """The simulated robot offers only what its profile defines: nothing more to learn."""
        raise DefinitionNotLearnt(app_local_text("maker_fields_unknown", type=type_name))

    def own_publishers(self) -> dict:
        """{topic: 1} for each topic a program published on (Rockly's publisher, as on a real ROS)."""
        return dict.fromkeys(set(self._published), 1)

    def health(self) -> list:
        """HealthItems of the simulated robot (its interface as the manifest declares it)."""
        interface = self.profile.ros_interface
        link = HealthItem(app_local_text("health_simulator"), GREEN, app_local_text("health_simulator_running"))

        def has_server(kind, name):
            return self.world.has_service(name) if kind == "services" else self.world.has_action(name)

        return [link] + topic_health(interface, self.state.topics()) + server_health(interface, has_server)

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return link_parts.safe_stop(self)

    def recording_encoder(self):
        """The simulator's ROS-shaped messages as the registry's encoder for the simulator writes them
        (ROS 1's, where genpy is installed; else None: JSON). One encoder for the session, whose message
        classes for the simulator's topics are made on the first call, before a run starts (not by the
        recording's writer while the program runs)."""
        if self._encoder is None:
            self._encoder = links.recording_encoder(self.kind, self.profile,
                                                    [msg_type for _topic, msg_type in self.world.topics()])
        return self._encoder

    def reset(self):
        """Put the simulated robot back as it started (its profile's ``reset()``)."""
        self.simulator.reset()

    def shutdown(self):
        """Stop the simulator's threads."""
        self.safe_stop()
        self.simulator.shutdown()
