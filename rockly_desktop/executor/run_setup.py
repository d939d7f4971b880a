"""Putting a run together: the profile's commands on a robot, the runner, the safe stop."""
from rockly_desktop.executor.runner import ProgramRunner
from rockly_desktop.robot.ros_commands import RosCommands


def make_runner(profile, robot, run_code: dict, control, emit, language: str = "en") -> ProgramRunner:
    """A ProgramRunner for the page's ``getRunCode`` answer, bound to ``robot``.

    The program sees the profile's command object as ``robot`` and the generic ROS
    commands as ``ros``; when the run ends for any reason, the robot's safe stop runs.
    The run reports its errors in ``language``.
    """
    backend = robot.backend(control.interrupt)
    commands = profile.create("api", backend)
    ros = RosCommands(backend, types=profile.ros_types)

    def on_end():
        failures = robot.safe_stop()
        if failures:
            raise RuntimeError("; ".join(failures))

    runner = ProgramRunner(run_code["code"], {"robot": commands, "ros": ros}, control, emit,
                           run_code.get("variables"), on_end, language)
    ros.say = runner.show_output
    return runner
