"""The ``rockly`` command: the window, and headless tools for profiles and programs.

    rockly [PROGRAM]                    open the editor (optionally with a program)
    rockly --kiosk [PROGRAM]            a fair stand: full screen, PROGRAM (or an empty one) for each visitor
    rockly profiles list                show installed robot profiles and broken ones
    rockly profiles validate PATH       check one profile folder
    rockly profiles new NAME [--dir DIR] create a working skeleton profile to start from
    rockly profiles reference           print the profile.yaml reference (Markdown)
    (``rockly plugins ...`` is the older name of ``rockly profiles ...`` and still works)
    rockly export PROGRAM -o OUT.py     write the Python generated from a program (-o -: to standard output)
    rockly import PROGRAM.py -o OUT.rockly  Python back to blocks; what blocks cannot say stays in Python blocks
    rockly export PROGRAM --standalone -o OUT.py  ... as a file that runs without the window where Rockly's
                                        runtime is installed (runtime/: rockly-runtime; see runtime/standalone.py)
    rockly run PROGRAM [--answer A]...  run a program on the simulator (or --backend KIND), without a window
    (export, run, replay and recordings list take --language en|de: the blocks' texts and every message;
     default: the app's language)
    rockly sim PROFILE --ros            the profile's simulated robot as a ROS 1 node, in a small window
    rockly run PROGRAM --record OUT.mcap  ... and record the run
    rockly replay RECORDING.mcap        print a recorded run's timeline (block, time, outcome)
    rockly recordings list              list the recordings in the recordings folder
    rockly blocks make --profile P --pack K --id ID --kind KIND ...  make a block without code into a block pack
    rockly blocks list [PACK]           list a block pack's blocks (without PACK: the installed packs)
    rockly blocks export PACK -o F.zip  write a block pack to one file; rockly blocks import F.zip installs one
    rockly lessons list|validate|check|export|import|reference  lessons, checked on the simulator
                                        (check LESSON PROGRAM...: each goal's result; --csv; exit 0: all passed)
    rockly agent --backend ros1|ros2|sim  the agent on the robot: keeps programs, runs them (runtime/agent/)
    rockly robot list|send|start|stop|delete|attach  talk to a robot's agent (--host ROBOT)

The kinds of robot (``--backend``, ``rockly sim``'s ``--ros``, their connection options) come from the
robot-link registry, ``robot/links.py``.
"""
import argparse
import logging
import os
import sys
from pathlib import Path

from rockly_desktop import __version__

COMMANDS = {"profiles": "cli_command_profiles", "export": "cli_command_export", "import": "cli_command_import",
            "run": "cli_command_run", "sim": "cli_command_sim", "replay": "cli_command_replay",
            "recordings": "cli_command_recordings", "blocks": "cli_command_blocks", "lessons": "cli_command_lessons",
            "agent": "cli_command_agent", "robot": "cli_command_robot"}  # each tool command: its line in --help
SUBCOMMANDS = (*COMMANDS, "plugins")  # "plugins": the older name of "profiles"
PROGRAM_HELP = "a .rockly file, a first-Rockly .xml file or a Python program (.py), turned into blocks in memory"
IMPORT_KEPT_PYTHON = 3  # `rockly import`'s exit code when parts stayed Python (1: an error, 0: lossless)


def _tool_parser() -> argparse.ArgumentParser:
    from rockly_desktop.robot import links  # not on the window's start-up path
    from rockly_desktop.runtime.options import add_connection_options

    parser = argparse.ArgumentParser(prog="rockly", description="Program ROS robots with blocks.")
    parser.add_argument("--version", action="version", version=f"rockly {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)

    profiles = commands.add_parser("profiles", aliases=["plugins"], help="robot profiles")
    profile_commands = profiles.add_subparsers(dest="profile_command", required=True)
    profile_commands.add_parser("list", help="list installed robot profiles")
    validate = profile_commands.add_parser("validate", help="check a robot profile folder")
    validate.add_argument("path", type=Path)
    new = profile_commands.add_parser("new", help="create a working skeleton robot profile")
    new.add_argument("name", help="the profile id: lower-case letters, digits and _, e.g. my_robot")
    new.add_argument("--dir", type=Path, help="create it in DIR/NAME (default: your profile folder)")
    profile_commands.add_parser("reference", help="print the profile.yaml reference (Markdown)")

    export = commands.add_parser("export", help="write the Python generated from a program")
    export.add_argument("program", type=Path, help=PROGRAM_HELP)
    export.add_argument("-o", "--output", type=Path, required=True,
                        help="the .py file to write (- for standard output)")
    export.add_argument("--standalone", action="store_true", help=_text("cli_standalone_help"))
    _python_profile_option(export)
    _language_option(export)

    converting = commands.add_parser("import", help=_text("cli_import_help"))
    converting.add_argument("program", type=Path, help="a Python program (.py)")
    converting.add_argument("-o", "--output", type=Path, required=True, help="the .rockly file to write")
    converting.add_argument("--profile", help="the robot profile (default: the one the file's header names)")
    converting.add_argument("--force", action="store_true", help="replace OUT if it exists")
    _language_option(converting)

    run = commands.add_parser("run", help="run a program without a window")
    run.add_argument("program", type=Path, help=PROGRAM_HELP)
    run.add_argument("--backend", default=links.DEFAULT_KIND, choices=[entry.kind for entry in links.link_kinds()],
                     help="the robot to run on: " + ", ".join(f"{entry.kind} ({entry.title})" for entry in
                                                              links.link_kinds()) + f"; default: {links.DEFAULT_KIND}")
    add_connection_options(run, links.link_kinds())
    run.add_argument("--answer", action="append", default=[],
                     help="an answer for the next tablet question (repeatable)")
    run.add_argument("--speed", type=float, default=1.0, help="simulated time runs this many times faster")
    run.add_argument("--record", type=Path, metavar="OUT.mcap", help="record the run to this MCAP file")
    _python_profile_option(run)
    _language_option(run)

    replay = commands.add_parser("replay", help="print a recorded run's timeline")
    replay.add_argument("recording", type=Path, help="an .mcap file Rockly recorded")
    _language_option(replay)
    recordings = commands.add_parser("recordings", help="recorded runs")
    listing = recordings.add_subparsers(dest="recordings_command", required=True).add_parser(
        "list", help="list the recordings in the recordings folder")
    listing.add_argument("--folder", type=Path, help="another folder (default: the one the preferences name)")
    _language_option(listing)

    from rockly_desktop.blocks_command import add_blocks_parser

    add_blocks_parser(commands, _language_option)
    from rockly_desktop.lessons_command import add_lessons_parser

    add_lessons_parser(commands, _language_option)

    from rockly_desktop.runtime.agent.commands import add_agent_parser, add_robot_parser

    add_agent_parser(commands, _language_option)
    add_robot_parser(commands, _language_option)

    sim = commands.add_parser("sim", help="run a profile's simulated robot as a ROS node, in a small window")
    sim.add_argument("profile", help="the robot profile id (see rockly profiles list)")
    servers = [entry for entry in links.link_kinds() if entry.sim_option]
    serve_on = sim.add_mutually_exclusive_group(required=True)
    for entry in servers:
        serve_on.add_argument(entry.sim_option, dest="serve_on", action="store_const", const=entry.kind,
                              help=f"serve the robot's ROS interface: the simulator as {entry.title}")
    add_connection_options(sim, servers)
    sim.add_argument("--answer", action="append", default=[],
                     help="an answer for the next tablet question (repeatable); when they run out, the window asks")
    sim.add_argument("--speed", type=float, default=1.0, help="simulated time runs this many times faster")
    sim.add_argument("--no-window", dest="window", action="store_false",
                     help="run without the window showing the robot and its tablet (servers, CI): "
                          "tablet questions are then answered only from --answer")
    return parser


def _language_option(parser):
    from rockly_desktop.core.app_texts import languages

    parser.add_argument("--language", choices=languages(), help=_text("cli_language_help"))


def _text(key: str) -> str:
    """A command's help text (in English, as argparse's own words are)."""
    from rockly_desktop.core.app_texts import app_text

    return app_text(key, "en")


def _app_language() -> str:
    """The language chosen in the app's settings (Preferences)."""
    from rockly_desktop.settings.app_settings import AppSettings

    return AppSettings().language


def _gui_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="rockly", description="Program ROS robots with blocks.",
                                     epilog=_commands_overview(), formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"rockly {__version__}")
    parser.add_argument("program", nargs="?", type=Path, help="a program to open")
    parser.add_argument("--kiosk", action="store_true",
                        help="kiosk mode for a fair stand: full screen, the program (or an empty one) for each "
                             "visitor; leaving needs the teacher's PIN or key chord")
    return parser


def _commands_overview() -> str:
    """``rockly --help``'s list of the tool commands, one line each."""
    width = max(map(len, COMMANDS))
    lines = [f"  rockly {name:<{width}}  {_text(key)}" for name, key in COMMANDS.items()]
    return "\n".join([_text("cli_commands_heading"), *lines])


def _profiles_list() -> int:
    from rockly_desktop.profiles.registry import ProfileRegistry

    registry = ProfileRegistry.discover()
    for profile in registry.profiles.values():
        print(f"{profile.id:<14} {profile.display_name():<20} {profile.version:<10} "
              f"{profile.source:<12} {profile.root}")
    if not registry.profiles:
        print("No robot profiles are installed.")
    for error in registry.errors:
        print(f"BROKEN  {error}", file=sys.stderr)
    return 1 if registry.errors else 0


def _profiles_validate(path: Path) -> int:
    from rockly_desktop.core import paths
    from rockly_desktop.core.errors import ManifestError
    from rockly_desktop.profiles.checks import code_problems
    from rockly_desktop.profiles.packs.pack import is_pack_folder
    from rockly_desktop.profiles.profile import load_profile

    if is_pack_folder(path):
        return _pack_validate(path)
    try:
        profile = load_profile(path, paths.shared_toolboxes_dir())
    except ManifestError as error:
        print(f"INVALID  {error}", file=sys.stderr)
        return 1
    problems = code_problems(profile)
    for problem in problems:
        print(f"INVALID  {problem}", file=sys.stderr)
    if problems:
        return 1
    print(f"OK  {profile.id} {profile.version}: {len(profile.blocks)} blocks, "
          f"{len(profile.toolbox_categories)} toolbox categories, commands {profile.api_target}")
    return 0


def _pack_validate(path: Path) -> int:
    """``rockly profiles validate`` of a block pack folder: its files, and that it joins its profile."""
    from rockly_desktop.core.errors import ManifestError
    from rockly_desktop.profiles.packs.merge import merge_problem
    from rockly_desktop.profiles.packs.pack import load_pack
    from rockly_desktop.profiles.registry import ProfileRegistry

    try:
        pack = load_pack(path)
    except ManifestError as error:
        print(f"INVALID  {error}", file=sys.stderr)
        return 1
    profiles = ProfileRegistry.discover().base_profiles
    if pack.adds_to not in profiles:
        print(f"INVALID  {path}: adds_to: '{pack.adds_to}' is no installed robot profile "
              f"(installed: {', '.join(profiles) or '-'})", file=sys.stderr)
        return 1
    problem = merge_problem(profiles[pack.adds_to], pack)
    if problem is not None:
        print(f"INVALID  {path}: {problem}", file=sys.stderr)
        return 1
    print(f"OK  block pack {pack.id} {pack.version}: {len(pack.blocks)} blocks, "
          f"{len(pack.toolbox_categories)} toolbox categories, adds to {pack.adds_to}")
    return 0


def _profiles_new(name: str, folder: Path) -> int:
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.profiles.skeleton import ProfileNameRefused, create_profile, next_steps

    try:
        profile_dir = create_profile(name, folder)
    except RocklyError as error:
        print(f"rockly profiles new: {error}", file=sys.stderr)
        return 2 if isinstance(error, ProfileNameRefused) else 1
    print(next_steps(profile_dir))
    return 0


def _profiles_reference() -> int:
    from rockly_desktop.profiles.reference import manifest_reference_markdown

    print(manifest_reference_markdown(), end="")
    return 0


def _python_profile_option(command):
    command.add_argument("--profile", help=_text("cli_python_profile_help"))


def _refuse_profile_option(parser, args) -> None:
    """``--profile`` is for a ``.py`` program only: a program file names its robot itself (argparse's error, in the
    command's language)."""
    from rockly_desktop.core.app_texts import app_text
    from rockly_desktop.python_blocks.program_file import is_python_program

    if args.profile and not is_python_program(args.program):
        parser.error(app_text("cli_profile_for_python_only", args.language or _app_language()))


def _export(program_path: Path, output: Path, language: str, standalone: bool = False, profile: str = None) -> int:
    from rockly_desktop.app import generate_headless
    from rockly_desktop.core.app_texts import app_text
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.core.export import python_module_text
    from rockly_desktop.core.program import write_text_atomically
    from rockly_desktop.profiles.opening import opening_warnings

    to_stdout = str(output) == "-" or _is_standard_output(output)
    try:
        program, python, run_code, workspace = generate_headless(program_path, language, profile)
        for warning in opening_warnings(program, language):
            print(app_text("cli_warning", language, command="rockly export", warning=warning), file=sys.stderr)
        if standalone:
            text = _standalone_text(program_path, program.profile, run_code, workspace, language)
        else:
            text = python_module_text(python, program.profile.id, program_path.name)
        if to_stdout:
            sys.stdout.write(text)
            sys.stdout.flush()
        else:
            write_text_atomically(output, text)
    except RocklyError as error:
        print(f"rockly export: {error.in_language(language)}", file=sys.stderr)
        return 1
    if not to_stdout:
        print(app_text("cli_wrote", language, path=output))
    return 0


def _import(args, language: str) -> int:
    """``rockly import``: a Python program turned into blocks; says what stayed Python."""
    from rockly_desktop.core.app_texts import app_text
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.core.program import write_text_atomically
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.python_blocks.program_file import convert_python_file

    if args.output.exists() and not args.force:
        print(f"rockly import: {app_text('import_exists', language, path=args.output)}", file=sys.stderr)
        return 1
    try:
        conversion = convert_python_file(args.program, ProfileRegistry.discover(), args.profile)
        write_text_atomically(args.output, conversion.program.to_json())
    except RocklyError as error:
        print(f"rockly import: {error.in_language(language)}", file=sys.stderr)
        return 1
    print(app_text("cli_wrote", language, path=args.output))
    if conversion.lossless:
        print(app_text("import_lossless", language))
        return 0
    print(app_text("import_kept_python", language, count=len(conversion.kept_python)))
    for part in conversion.kept_python:
        print(app_text("import_kept_line", language, line=part.first_line) if part.first_line == part.last_line
              else app_text("import_kept_lines", language, first=part.first_line, last=part.last_line))
    return IMPORT_KEPT_PYTHON


def _standalone_text(program_path: Path, profile, run_code: dict, workspace: dict, language: str) -> str:
    """The standalone file (``runtime.standalone_file``), with the teacher's limits the window keeps now."""
    from rockly_desktop.core.workspace_blocks import block_types_by_id
    from rockly_desktop.run_command import teacher_limits
    from rockly_desktop.runtime.standalone_file import standalone_text

    return standalone_text(program_path.name, profile, run_code, block_types_by_id(workspace),
                           teacher_limits(profile.id), language)


def _robot_program(program_path: Path) -> tuple:
    """``(standalone text, .rockly text or None)`` to send to a robot's agent: a ``.rockly`` (or first-Rockly
    ``.xml``) program is exported as ``rockly export --standalone`` would; a ``.py`` is taken as one already."""
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.core.program import read_text_file
    from rockly_desktop.runtime.agent.client import AgentError

    language = _app_language()
    try:
        if program_path.suffix.lower() == ".py":
            return read_text_file(program_path), None
        from rockly_desktop.app import generate_headless

        program, _, run_code, workspace = generate_headless(program_path, language)
        source = read_text_file(program_path) if program_path.suffix.lower() == ".rockly" else None
        return _standalone_text(program_path, program.profile, run_code, workspace, language), source
    except RocklyError as error:
        raise AgentError("program", error.in_language(language)) from None


def _is_standard_output(path: Path) -> bool:
    """True when ``path`` is this process's standard output (``/dev/stdout``, ``/dev/fd/1``, or
    the file stdout is redirected to): the Python then goes there as a stream, with no
    "Wrote" line mixed into it."""
    try:
        target, stdout = os.stat(path), os.fstat(sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        return False
    return (target.st_dev, target.st_ino) == (stdout.st_dev, stdout.st_ino)


def main(argv=None) -> int:
    """Entry point of the ``rockly`` command."""
    argv = list(sys.argv[1:] if argv is None else argv)
    logging.basicConfig(level=os.environ.get("ROCKLY_LOG", "warning").upper(),
                        format="%(levelname)s %(name)s: %(message)s")
    if argv and argv[0] in SUBCOMMANDS:
        from rockly_desktop.runtime.options import connection

        parser = _tool_parser()
        args = parser.parse_args(argv)
        if args.command in ("run", "export"):
            _refuse_profile_option(parser, args)
        if args.command in ("profiles", "plugins"):
            if args.profile_command == "new":
                return _profiles_new(args.name, args.dir)
            if args.profile_command == "reference":
                return _profiles_reference()
            return _profiles_list() if args.profile_command == "list" else _profiles_validate(args.path)
        if args.command == "import":
            return _import(args, args.language or _app_language())
        if args.command == "run":
            from rockly_desktop.run_command import run_program

            return run_program(args.program, args.answer, args.speed, args.language or _app_language(),
                               backend=args.backend,
                               connection=connection(args.backend, args), record=args.record,
                               python_profile=args.profile)
        if args.command in ("replay", "recordings"):
            from rockly_desktop.recording_command import list_recordings, replay

            language = args.language or _app_language()
            return (replay(args.recording, language) if args.command == "replay"
                    else list_recordings(args.folder, language))
        if args.command == "blocks":
            from rockly_desktop.blocks_command import run_blocks_command

            return run_blocks_command(args, args.language or _app_language())
        if args.command == "lessons":
            from rockly_desktop.lessons_command import run_lessons_command

            return run_lessons_command(args, args.language or _app_language())
        if args.command == "agent":
            from rockly_desktop.runtime.agent.commands import agent_command

            return agent_command(args, args.language or "en")
        if args.command == "robot":
            from rockly_desktop.runtime.agent.commands import robot_command

            return robot_command(args, args.language or _app_language(), _robot_program)
        if args.command == "sim":
            from rockly_desktop.sim_command import serve_simulator

            return serve_simulator(args.profile, args.serve_on, connection(args.serve_on, args), args.speed,
                                   args.answer, window=args.window)
        return _export(args.program, args.output, args.language or _app_language(), args.standalone, args.profile)
    args = _gui_parser().parse_args(argv)
    from rockly_desktop.app import run_gui

    return run_gui(args.program, kiosk=args.kiosk)


def gui_main(program=None) -> int:
    """Entry point of ``rockly-gui`` (the desktop launcher): the editor window, with an optional program
    (``--kiosk``: kiosk mode)."""
    from rockly_desktop.app import run_gui

    if program is not None:
        return run_gui(program)
    args = _gui_parser().parse_args(sys.argv[1:])
    return run_gui(args.program, kiosk=args.kiosk)
