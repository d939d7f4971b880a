"""Putting a run together: the profile's commands on a robot, the runner, the safe stop."""
from rockly_desktop.executor.runner import ProgramRunner
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.robot.limits import Capability, LimitedBackend, Limits, limits_text
from rockly_desktop.robot.ros_commands import RosCommands


def _switched_off(profile, limits: Limits, language: str) -> list:
    """The profile's capabilities ``limits`` switch off (ids it does not declare are ignored)."""
    return [Capability(entry["id"], localize(entry["name"], language), frozenset(entry.get("topics", ())),
                       frozenset(entry.get("services", ())), frozenset(entry.get("actions", ())))
            for entry in profile.capabilities if entry["id"] in limits.switched_off]


def limited_backend(profile, backend, limits: Limits, language: str) -> LimitedBackend:
    """``backend`` kept within a teacher's ``limits``, from what the profile's manifest declares:
    its drive interface (``velocity_topics``) and the capabilities switched off."""
    return LimitedBackend(backend, limits, profile.velocity_topics, _switched_off(profile, limits, language), language)


def limits_line(profile, limits: Limits, language: str):
    """One line in ``language`` saying which of a teacher's ``limits`` a run on ``profile`` keeps; None: none."""
    return limits_text(limits, [capability.name for capability in _switched_off(profile, limits, language)], language)


def make_runner(profile, robot, run_code: dict, control, emit, language: str = "en",
                limits: Limits = None) -> ProgramRunner:
    """A ProgramRunner for the page's ``getRunCode`` answer, bound to ``robot``.

    The program sees the profile's command object as ``robot`` and the generic ROS
    commands as ``ros``; when the run ends for any reason, the robot's safe stop runs.
    Both command objects go through the teacher's ``limits`` (see ``robot/limits.py``).
    The run reports its errors in ``language``.
    """
    backend = limited_backend(profile, robot.backend(control.interrupt), limits or Limits(), language)
    commands = profile.create("api", backend)
    ros = RosCommands(backend, types=profile.ros_types)

    def on_end():
        failures = robot.safe_stop()
        if failures:
            raise RuntimeError("; ".join(failures))

    runner = ProgramRunner(run_code["code"], {"robot": commands, "ros": ros}, control, emit,
                           run_code.get("variables"), on_end, language)
    ros.say = backend.note = runner.show_output
    return runner
