"""Putting a run together: the profile's commands on a robot, the runner, the safe stop."""
from rockly_desktop.executor.runner import ProgramRunner
from rockly_desktop.robot.ros_commands import RosCommands
from rockly_desktop.robot.wrappers.limits import Capability, LimitedBackend, Limits, limits_text
from rockly_desktop.robot.wrappers.own_speed import OwnSpeed
from rockly_desktop.robot.wrappers.recorded import RecordedBackend
from rockly_desktop.robot.wrappers.ros_versions import link_backend


def _switched_off(profile, limits: Limits, language: str) -> list:
    """The profile's capabilities ``limits`` switch off (ids it does not declare are ignored)."""
    return [Capability(entry["id"], profile.localize(entry["name"], language), frozenset(entry.get("topics", ())),
                       frozenset(entry.get("services", ())), frozenset(entry.get("actions", ())))
            for entry in profile.capabilities if entry["id"] in limits.switched_off]


def limited_backend(profile, backend, limits: Limits, language: str) -> LimitedBackend:
    """``backend`` kept within a teacher's ``limits``, from what the profile's manifest declares:
    its drive interface (``velocity_topics``), the capabilities switched off and the motions at the
    robot's own speed (``own_speed``, whose safe-stop messages pass)."""
    return LimitedBackend(backend, limits, profile.velocity_topics, _switched_off(profile, limits, language), language,
                          own_speed=OwnSpeed.from_manifest(profile.own_speed, profile.safe_stop))


def limits_line(profile, limits: Limits, language: str):
    """One line in ``language`` saying which of a teacher's ``limits`` a run on ``profile`` keeps; None: none."""
    return limits_text(limits, [capability.name for capability in _switched_off(profile, limits, language)], language)


def make_runner(profile, robot, run_code: dict, control, emit, language: str = "en",
                limits: Limits = None, recording=None, notes=None) -> ProgramRunner:
    """A ProgramRunner for the page's ``getRunCode`` answer, bound to ``robot``.

    The program sees the profile's command object as ``robot`` and the generic ROS
    commands as ``ros``; when the run ends for any reason, the robot's safe stop runs.
    Both command objects go through the teacher's ``limits`` (see ``robot/wrappers/limits.py``), and send
    what differs per ROS version as the robot wants it (``robot/wrappers/ros_versions.py``).
    The run reports its errors in ``language``. A ``RunRecording`` (``recording``) records the
    run: what the program sends, its blocks, variables and events, until it ends. ``notes(entry)`` is told
    the same of what is sent and what comes back (``RecordedBackend``'s entries; the block maker's "Try it").
    """
    limited = limited_backend(profile, link_backend(robot, control.interrupt), limits or Limits(), language)
    backend = limited if recording is None else RecordedBackend(limited, recording.command)
    if notes is not None:
        backend = RecordedBackend(backend, notes)
    commands = profile.create("api", backend)
    ros = RosCommands(backend, types=profile.ros_types)

    def on_end():
        failures = robot.safe_stop()
        if recording is not None:
            recording.safe_stop(failures)
        if failures:
            raise RuntimeError("; ".join(failures))

    if recording is not None:
        emit = _both(recording.emit, emit)
    runner = ProgramRunner(run_code["code"], {"robot": commands, "ros": ros}, control, emit,
                           run_code.get("variables"), on_end, language,
                           entered=None if recording is None else recording.recorder.blocks,
                           entered_stamp=None if recording is None else recording.recorder.block_clock)
    ros.say = limited.note = runner.show_output
    if recording is not None:
        recording.follow(runner)
    return runner


def _both(first, second):
    def emit(event):
        first(event)
        second(event)
    return emit
