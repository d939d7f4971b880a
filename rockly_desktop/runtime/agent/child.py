"""One program's run under the agent, in a process of its own (so the agent lives on if the program crashes):

    python3 -m rockly_desktop.runtime.agent.child STANDALONE.py --backend KIND [connection options] ...

It is the run's link host: the program's code runs in a process of its own below it (``runtime/link_host.py``),
which it starts first thing. It runs the standalone file's program (read as data) with the runtime's ``Run``: its
events go to standard
output as JSON lines (``runtime.event_stream``), and it takes the agent's requests on standard input, one a
line: ``pause``, ``step``, ``continue``, ``stop``, ``breakpoints ["ID", ...]`` (the blocks to pause before from now
on: the attached editor's). The end of standard input means the agent is gone (killed,
crashed): the run stops and the robot's safe stop runs here, so the robot stops whatever became of the
agent. SIGTERM and Ctrl+C stop it with the safe stop too (``Run``'s handlers).
"""
import json
import sys
import threading
from pathlib import Path

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.runtime.agent.library import standalone_program
from rockly_desktop.runtime.event_stream import EventStream, started_record
from rockly_desktop.runtime.link_host import ProgramProcess
from rockly_desktop.runtime.options import connection
from rockly_desktop.runtime.robot_limits import RobotLimitsError
from rockly_desktop.runtime.robot_limits import default_path as default_limits_path
from rockly_desktop.runtime.run import EXIT_ERROR, Run
from rockly_desktop.runtime.standalone import parser, run_limits

VARIABLES_SECONDS = 0.1  # how often the variables are looked at (as often as a window's own run shows them)
REQUESTS = ("pause", "step", "continue", "stop", "breakpoints")


def follow_requests(control, requests=None):
    """Apply the agent's requests from ``requests`` (standard input) to ``control`` until it ends; then stop."""
    for line in requests or sys.stdin:
        request = line.strip()
        if request == "pause":
            control.request_pause()
        elif request == "step":
            control.step()
        elif request == "continue":
            control.resume()
        elif request == "stop":
            control.request_stop()
        elif request.startswith("breakpoints "):
            control.set_breakpoints(_block_ids(request[len("breakpoints "):]))
    control.request_stop()  # the agent went away: the robot must not drive on unwatched by it


def sample_variables(run, stream, ended, seconds: float = VARIABLES_SECONDS):
    """Write the program's variables to ``stream`` whenever they changed, every ``seconds`` until ``ended``: a window
    attached to a run that is not paused follows them (the runner says them only at a pause and at the end), and
    one attaching later is shown them at once (the agent keeps the latest)."""
    shown = {}
    while not ended.wait(seconds):
        runner = run.runner
        values = runner.variables_snapshot() if runner is not None else {}
        if values != shown:
            shown = values
            stream.write({"event": "variables", "values": values})


def _block_ids(text: str) -> list:
    """The block ids of a ``breakpoints`` request (none for one that is not a JSON list of texts)."""
    try:
        ids = json.loads(text)
    except ValueError:
        return []
    return [block for block in ids if isinstance(block, str)] if isinstance(ids, list) else []


def _limits_folder(argv: list) -> Path:
    """The folder of the robot's limits file the agent gave this run (``--robot-limits``), else the default's."""
    given = argv[argv.index("--robot-limits") + 1] if "--robot-limits" in argv[:-1] else None
    return Path(given or default_limits_path()).parent


def main(argv=None) -> int:
    """Run the standalone file named first in ``argv``; its other arguments are the file's own."""
    argv = list(sys.argv[1:] if argv is None else argv)
    # the program's own process starts while the profiles are read; it sees neither the agent's library (its
    # programs, keys and pairings) nor the robot's own limits
    process = ProgramProcess.start(hidden=[Path(argv[0]).resolve().parent.parent, _limits_folder(argv)])
    try:
        return _run(argv, process)
    finally:
        process.close()


def _run(argv: list, process) -> int:
    program, run_code = standalone_program(Path(argv[0]).read_text(encoding="utf-8"))
    language = program.get("language", "en")
    args = parser(program, language).parse_args(argv[1:])
    language = args.language or language
    profile = ProfileRegistry.discover().profiles.get(program["profile"]["id"])
    types = program.get("blocks", {})
    stream = EventStream(sys.stdout, types)
    stream.write(started_record(program.get("source"), program["profile"]["id"], profile.version if profile else "?",
                                args.backend))
    if profile is None:
        print(app_text("standalone_no_profile", language, profile=program["profile"]["id"],
                       version=program["profile"]["version"], installed="-"), file=sys.stderr)
        stream.write({"event": "exit", "status": EXIT_ERROR})
        return EXIT_ERROR
    try:
        limits = run_limits(program, args.robot_limits)
    except RobotLimitsError as error:
        print(error.in_language(language), file=sys.stderr)
        stream.write({"event": "exit", "status": EXIT_ERROR})
        return EXIT_ERROR
    run = Run(profile, {"code": run_code, "variables": program.get("variables")}, types, language,
              program.get("source") or "rockly-program", out=_to_standard_error, on_event=stream.event, trace=True,
              end_out=_to_standard_error, process=process)
    threading.Thread(target=follow_requests, args=(run.control,), daemon=True, name="agent-requests").start()
    ended = threading.Event()
    sampler = threading.Thread(target=sample_variables, args=(run, stream, ended), daemon=True,
                               name="agent-variables")
    sampler.start()
    try:
        status = run.run(args.backend, connection(args.backend, args), args.answer, args.speed, limits, None,
                         program.get("source"), print_blocks=False)
    finally:
        ended.set()
        sampler.join()
    stream.write({"event": "exit", "status": status})
    return status


def _to_standard_error(line: str):
    print(line, file=sys.stderr, flush=True)


if __name__ == "__main__":
    sys.exit(main())
