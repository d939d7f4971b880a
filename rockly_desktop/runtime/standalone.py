"""What a standalone export (``rockly export PROGRAM --standalone -o OUT.py``) runs: its command line.

    python3 OUT.py [--backend sim|ros1|ros2] [connection options] [--answer A]... [--speed S]
                   [--language en|de] [--events PATH|-] [--record OUT.mcap] [--any-profile-version]
                   [--robot-limits FILE]

The file holds the program (the page's run code, its block types, its variables' names), the robot
profile's id and version it was made for, and the teacher's limits in force when it was exported (a run
keeps the stricter of those and the robot's own, ``runtime.robot_limits``); the runtime installed on the
computer it runs on (``rockly-runtime``) provides everything else. Nothing here needs Qt or Blockly.

Exit status: 0 finished; 1 an error in the program, or the robot could not be reached; 2 a wrong
command line; 3 the profile is not installed here, has another version than the one the program was
made for, or the file is of a newer format; 128 + the signal's number when Ctrl+C (130) or SIGTERM (143)
stopped it. However it ends, the robot's safe stop has run.
"""
import argparse
import sys
from pathlib import Path

from rockly_desktop.core.app_texts import app_text, languages
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.recording.mcap_file import problem_text
from rockly_desktop.robot import links
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.runtime.event_stream import EventStream, event_record, started_record
from rockly_desktop.runtime.link_host import ProgramProcess
from rockly_desktop.runtime.options import add_connection_options, connection
from rockly_desktop.runtime.robot_limits import RobotLimitsError, read_robot_limits
from rockly_desktop.runtime.robot_limits import default_path as default_limits_path
from rockly_desktop.runtime.run import EXIT_ERROR, Run

FORMAT = 1  # of the PROGRAM a standalone file holds; a newer one is refused with a message
EXIT_PROFILE = 3


def limits_data(limits: Limits) -> dict:
    """``limits`` as plain data, for the file."""
    return {"max_speed": limits.max_speed, "max_turn": limits.max_turn, "switched_off": sorted(limits.switched_off)}


def limits_from_data(data: dict) -> Limits:
    """The Limits a file holds (``limits_data``'s form)."""
    return Limits(data.get("max_speed"), data.get("max_turn"), frozenset(data.get("switched_off", ())))


def run_limits(program: dict, robot_limits_path=None) -> Limits:
    """The limits a run of ``program`` keeps here: the stricter of the program's and the robot's own
    (``runtime.robot_limits``; RobotLimitsError when the robot's file is broken)."""
    return limits_from_data(program.get("limits", {})).stricter(read_robot_limits(robot_limits_path))


def parser(program: dict, language: str) -> argparse.ArgumentParser:
    """The standalone file's command line (its help in ``language``)."""
    parser = argparse.ArgumentParser(
        prog=program.get("source") or "rockly-program",
        description=app_text("standalone_description", language, program=program.get("source", "?"),
                             profile=program["profile"]["id"], version=program["profile"]["version"]))
    kinds = links.link_kinds()
    parser.add_argument("--backend", default=links.DEFAULT_KIND, choices=[entry.kind for entry in kinds],
                        help=app_text("standalone_backend_help", language, default=links.DEFAULT_KIND,
                                      kinds=", ".join(f"{entry.kind} ({entry.title})" for entry in kinds)))
    add_connection_options(parser, kinds)
    parser.add_argument("--answer", action="append", default=[], help=app_text("standalone_answer_help", language))
    parser.add_argument("--speed", type=float, default=1.0, help=app_text("standalone_speed_help", language))
    parser.add_argument("--language", choices=languages(),
                        help=app_text("standalone_language_help", language, default=language))
    parser.add_argument("--events", metavar="PATH", help=app_text("standalone_events_help", language))
    parser.add_argument("--record", metavar="OUT.mcap", help=app_text("standalone_record_help", language))
    parser.add_argument("--any-profile-version", action="store_true",
                        help=app_text("standalone_any_version_help", language))
    parser.add_argument("--robot-limits", metavar="FILE",
                        help=app_text("standalone_robot_limits_help", language, default=default_limits_path()))
    return parser


def main(program: dict, run_code: str, argv=None, on_event=None) -> int:
    """Run a standalone file's ``program`` (its ``PROGRAM`` data) and ``run_code`` with the command line
    ``argv``; returns the exit status. ``on_event``: a callable given every event record as a dict (the
    same records ``--events`` writes), for a caller that runs the file's program in its own process."""
    language = program.get("language", "en")
    if program.get("format", FORMAT) > FORMAT:
        print(app_text("standalone_newer_format", language, program=program.get("source", "?"),
                       rockly=program.get("rockly", "?")), file=sys.stderr)
        return EXIT_PROFILE
    args = parser(program, language).parse_args(argv)
    # the program's own process starts while the profiles are read; the robot's limits are out of its reach
    process = ProgramProcess.start(hidden=[Path(args.robot_limits or default_limits_path()).parent])
    try:
        return _run(program, run_code, args, on_event, process)
    finally:
        process.close()


def _run(program: dict, run_code: str, args, on_event, process) -> int:
    language = args.language or program.get("language", "en")
    command = program.get("source") or "rockly-program"
    profile = _installed_profile(program["profile"], args.any_profile_version, language, command)
    if profile is None:
        return EXIT_PROFILE
    types = program.get("blocks", {})
    writers = [on_event] if on_event is not None else []
    out = print
    events = None
    if args.events:
        try:
            stream = sys.stdout if args.events == "-" else open(args.events, "w", encoding="utf-8")
        except OSError as error:
            print(f"{command}: " + app_text("standalone_cannot_write_events", language, path=args.events,
                                            reason=problem_text(error, language)), file=sys.stderr)
            return EXIT_ERROR
        events = EventStream(stream, types)
        writers.append(events.write)
        if args.events == "-":  # standard output carries the events alone: a person's lines go to standard error
            out = _to_standard_error
    for write in writers:
        write(started_record(program.get("source"), profile.id, profile.version, args.backend))
    try:
        limits = run_limits(program, args.robot_limits)
    except RobotLimitsError as error:
        print(f"{command}: {error.in_language(language)}", file=sys.stderr)
        return EXIT_ERROR
    run = Run(profile, {"code": run_code, "variables": program.get("variables")}, types, language, command,
              out=out, on_event=_each(writers, types) if writers else None, trace=bool(writers), end_out=out,
              process=process)
    try:
        status = run.run(args.backend, connection(args.backend, args), args.answer, args.speed, limits, args.record,
                         program.get("source"), print_blocks=False)
        for write in writers:
            write({"event": "exit", "status": status})
        return status
    finally:
        if events is not None and args.events != "-":
            events.open = False
            try:
                stream.close()
            except OSError:  # lines the reader never took (it went away)
                pass


def _installed_profile(wanted: dict, any_version: bool, language: str, command: str):
    """The installed profile the program was made for, or None after saying why it cannot run (not
    installed, or another version without ``any_version``: then only a warning)."""
    registry = ProfileRegistry.discover()
    profile = registry.profiles.get(wanted["id"])
    if profile is None:
        print(f"{command}: " + app_text("standalone_no_profile", language, profile=wanted["id"],
                                        version=wanted["version"],
                                        installed=", ".join(f"{p.id} {p.version}" for p in registry.profiles.values())
                                        or "-"), file=sys.stderr)
        return None
    if profile.version != wanted["version"]:
        values = {"profile": profile.id, "version": wanted["version"], "installed": profile.version}
        if not any_version:
            print(f"{command}: " + app_text("standalone_other_version", language, **values), file=sys.stderr)
            return None
        print(f"{command}: " + app_text("standalone_other_version_used", language, **values), file=sys.stderr)
    return profile


def _to_standard_error(line: str):
    print(line, file=sys.stderr)


def _each(writers, types):
    def on_event(event):
        record = event_record(event, types)
        if record is not None:
            for write in writers:
                write(record)
    return on_event
