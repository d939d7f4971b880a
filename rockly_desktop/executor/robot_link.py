"""The robot a program runs against. Today: the profile's built-in simulator, in-process."""
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.sim_world import SimBackend, SimWorld


class SimulatedRobot:
    """A profile's simulator running in this process for the whole session.

    ``tablet`` answers the robot's tablet dialogs (a window, or the CLI's --answer list).
    """

    name = "simulator"

    def __init__(self, profile, tablet=None, speed: float = 1.0):
        self.profile = profile
        self.world = SimWorld()
        self.simulator = profile.load_object("simulator")(self.world, tablet=tablet, speed=speed)
        self.simulator.start()

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped."""
        return SimBackend(self.world, interrupt)

    def snapshot(self) -> dict:
        """The simulated robot's state, for the simulator view."""
        return self.simulator.snapshot()

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return run_safe_stop(self.profile.manifest.get("safe_stop", []), self.backend(Interrupt()))

    def shutdown(self):
        """Stop the simulator's threads."""
        self.safe_stop()
        self.simulator.shutdown()
