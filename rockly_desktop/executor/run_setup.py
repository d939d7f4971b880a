"""Putting a run together: the profile's commands on a robot, the runner, the safe stop."""
from rockly_desktop.executor.runner import ProgramRunner


def make_runner(profile, robot, run_code: dict, control, emit) -> ProgramRunner:
    """A ProgramRunner for the page's ``getRunCode`` answer, bound to ``robot``.

    The program sees the profile's command object as ``robot``; when the run ends for
    any reason, the robot's safe stop runs.
    """
    commands = profile.load_object("api")(robot.backend(control.interrupt))

    def on_end():
        failures = robot.safe_stop()
        if failures:
            raise RuntimeError("; ".join(failures))

    return ProgramRunner(run_code["code"], {"robot": commands}, control, emit,
                         run_code.get("variables"), on_end)
