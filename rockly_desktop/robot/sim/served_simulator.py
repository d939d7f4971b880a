"""A profile's simulator served on a ROS middleware (``rockly sim PROFILE --ros`` or ``--ros2``): how it is
put back and how it ends."""
import logging

log = logging.getLogger(__name__)

# The service (std_srvs/Trigger) that puts the served simulator back as it started, in the simulator's
# own namespace, where no real robot's interface has a name.
PUT_BACK_SERVICE = "/rockly_sim/reset"


class ServedSimulator:
    """The part the ROS 1 and ROS 2 simulator nodes share: their ``simulator`` reaches the graph
    through their ``_bridge``, and ``shutdown()`` ends both, once."""

    _ended = False

    def put_back(self) -> dict:
        """The answer to PUT_BACK_SERVICE (a std_srvs/Trigger response): the robot back at its start pose,
        standing still, every part as at the start (the simulator's ``reset()``, as the window's Put back)."""
        try:
            self.simulator.reset()
        except NotImplementedError as error:
            return {"success": False, "message": str(error)}
        return {"success": True, "message": ""}

    def shutdown(self):
        """End waiting questions and goals, stop the simulator (its safe stop first), then leave the
        middleware (``_leave``). Once only."""
        if self._ended:
            return
        self._ended = True
        self._bridge.close()
        safe_stop = getattr(self.simulator, "safe_stop", None)
        if safe_stop is not None:
            try:
                safe_stop()
            except Exception:
                log.exception("the simulator's safe stop failed")
        self.simulator.shutdown()
        self._leave()

    def _leave(self):
        """The middleware's part of the end."""
        raise NotImplementedError
