"""``rockly lessons ...``: lessons for teachers and for grading, without a window.

    rockly lessons list [--robot ROBOT] [--level LEVEL]   the lessons by robot and level (and broken ones)
    rockly lessons validate PATH...      check a lesson folder, a folder of lessons or a lesson pack zip
    rockly lessons check LESSON PROGRAM... [--csv FILE] [--jobs N]
                                         check programs (files or folders of .rockly files) against a
                                         lesson (its id or folder): per program each goal's result
    rockly lessons export FOLDER -o F.zip / import F.zip [--replace]   lesson packs, as block packs are
    rockly lessons reference             print the lesson.yaml and goal reference (Markdown)

``check`` generates every program's code with one windowless editor (the only Qt here) and hands the
code to one checking process per core (``lessons/parallel.py``) as soon as it is generated; the
programs' files are only read. Exit status: 0 when every program passed every goal, 1 otherwise (or a
problem: a broken lesson, no program).
"""
import csv
import io
import sys
import tempfile
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.lessons.archive import export_lessons, import_lessons
from rockly_desktop.lessons.check import GeneratedProgram
from rockly_desktop.lessons.lesson import is_lesson_folder, load_lesson
from rockly_desktop.lessons.lesson_file import LessonError
from rockly_desktop.lessons.library import LessonLibrary, lesson_folders, lesson_reference
from rockly_desktop.lessons.parallel import ParallelChecks, cores
from rockly_desktop.lessons.schema import LEVELS
from rockly_desktop.profiles.registry import ProfileRegistry

EXIT_PASSED, EXIT_FAILED = 0, 1
PROGRAM_SUFFIX = ".rockly"


def add_lessons_parser(commands, language_option) -> None:
    """The ``lessons`` command and its subcommands, on ``commands`` (argparse subparsers)."""
    lessons = commands.add_parser("lessons", help="lessons and challenges, checked on the simulator")
    actions = lessons.add_subparsers(dest="lessons_command", required=True)
    listing = actions.add_parser("list", help="the lessons by robot and level")
    listing.add_argument("--robot", help="only this robot's lessons (its profile id)")
    listing.add_argument("--level", choices=LEVELS, help="only this level's lessons")
    validate = actions.add_parser("validate", help="check lessons: a folder, a folder of lessons, a pack zip")
    validate.add_argument("paths", nargs="+", metavar="PATH")
    check = actions.add_parser("check", help="check programs against a lesson on the simulator")
    check.add_argument("lesson", help="the lesson's id or folder")
    check.add_argument("programs", nargs="+", metavar="PROGRAM", help=".rockly files or folders of them")
    check.add_argument("--csv", metavar="FILE", help="also write a table (- for standard output)")
    check.add_argument("--jobs", type=int, default=0, help="checking processes (default: one per core)")
    export = actions.add_parser("export", help="write a folder of lessons to one zip file")
    export.add_argument("folder")
    export.add_argument("-o", "--output", required=True)
    importing = actions.add_parser("import", help="install a lesson pack zip")
    importing.add_argument("zip")
    importing.add_argument("--replace", action="store_true", help="replace a pack of the same name")
    reference_parser = actions.add_parser("reference", help="print the lesson.yaml and goal reference (Markdown)")
    for action in (listing, validate, check, export, importing, reference_parser):
        language_option(action)


def run_lessons_command(args, language: str) -> int:
    """Run ``rockly lessons`` as parsed into ``args``; returns the exit status."""
    profiles = ProfileRegistry.discover().profiles
    try:
        if args.lessons_command == "list":
            return list_lessons(profiles, args.robot, args.level, language)
        if args.lessons_command == "validate":
            return validate(args.paths, profiles, language)
        if args.lessons_command == "check":
            return check(args.lesson, args.programs, profiles, language, args.csv, args.jobs or cores())
        if args.lessons_command == "export":
            path = export_lessons(args.folder, args.output)
            print(app_text("lesson_exported", language, path=path))
            return EXIT_PASSED
        if args.lessons_command == "import":
            folder = import_lessons(args.zip, profiles, replace=args.replace)
            print(app_text("lesson_imported", language, path=args.zip, folder=folder))
            return EXIT_PASSED
        print(lesson_reference(profiles), end="")
        return EXIT_PASSED
    except RocklyError as error:
        print(f"rockly lessons: {error.in_language(language)}", file=sys.stderr)
        return EXIT_FAILED


def list_lessons(profiles, robot, level, language) -> int:
    """Print the lessons by robot and level, then the broken ones; 1 when one is broken."""
    library = LessonLibrary.discover(profiles)
    for robot_id, levels in library.by_robot_and_level().items():
        if robot and robot_id != robot:
            continue
        print(profiles[robot_id].display_name(language))
        for level_id, lessons in levels.items():
            if level and level_id != level:
                continue
            print(f"  {profiles[robot_id].localize(profiles[robot_id].level(level_id)['name'], language)}")
            for lesson in lessons:
                print(f"    {lesson.id:28} {lesson.title(language)}")
    for problem in library.problems:
        print(f"BROKEN  {problem.in_language(language)}", file=sys.stderr)
    return EXIT_FAILED if library.problems else EXIT_PASSED


def validate(paths, profiles, language) -> int:
    """Check each path (a lesson, a folder of lessons, a pack zip); print each lesson's verdict."""
    failed = False
    for path in map(Path, paths):
        try:
            if path.suffix == ".zip":
                with tempfile.TemporaryDirectory() as folder:
                    target = import_lessons(path, profiles, folder=folder)
                    for lesson_folder in lesson_folders(target):
                        lesson = load_lesson(lesson_folder, profiles)
                        print(app_text("lesson_valid", language, path=path, lesson=lesson.id))
                continue
            folders = lesson_folders(path) if path.is_dir() else []
            if not folders:
                raise LessonError(path, 0, app_local_text("lesson_problem_validate_path"))
            for lesson_folder in folders:
                try:
                    lesson = load_lesson(lesson_folder, profiles)
                    print(app_text("lesson_valid", language, path=lesson_folder, lesson=lesson.id))
                except LessonError as error:
                    failed = True
                    print(f"BROKEN  {error.in_language(language)}", file=sys.stderr)
        except LessonError as error:
            failed = True
            print(f"BROKEN  {error.in_language(language)}", file=sys.stderr)
    return EXIT_FAILED if failed else EXIT_PASSED


def program_paths(arguments) -> list:
    """The .rockly files named, a folder's (sorted) in its place; LessonError for a folder without one."""
    found = []
    for argument in map(Path, arguments):
        if argument.is_dir():
            inside = sorted(argument.glob(f"*{PROGRAM_SUFFIX}"))
            if not inside:
                raise LessonError(argument, 0, app_local_text("lesson_problem_no_programs"))
            found += inside
        else:
            found.append(argument)
    return found


def find_lesson(name: str, profiles: dict):
    """The lesson ``name``: a lesson folder, or the id of an installed lesson."""
    if is_lesson_folder(name):
        return load_lesson(name, profiles)
    lesson = LessonLibrary.discover(profiles).get(name)
    if lesson is None:
        raise LessonError(name, 0, app_local_text("lesson_problem_no_such_lesson", command="rockly lessons list"))
    return lesson


def check(lesson_name, arguments, profiles, language, csv_path=None, jobs=1) -> int:
    """Check every program against the lesson; print the results in the programs' order; 0 if all passed."""
    from rockly_desktop.app import generate_many

    lesson = find_lesson(lesson_name, profiles)
    paths = program_paths(arguments)
    rows, types = {}, {}
    with ParallelChecks(lesson.folder, min(jobs, len(paths)), language) as pool:
        pool.warm_up()
        futures = {}
        for path, generated in generate_many(paths, language):
            if isinstance(generated, Exception):
                rows[path] = _problem(path, app_text("lesson_cannot_generate", language, program=path.name,
                                                     error=generated.in_language(language)))
                continue
            program, _python, run_code, workspace = generated
            if program.profile.id != lesson.robot:
                rows[path] = _problem(path, app_text(
                    "lesson_wrong_robot", language, program=path.name, robot=program.profile.display_name(language),
                    lesson_robot=lesson.profile.display_name(language)))
                continue
            types[path] = block_types_by_id(workspace)
            futures[path] = pool.submit(GeneratedProgram(path.name, run_code, workspace, types[path]))
        for path, future in futures.items():
            try:
                rows[path] = future.result()
            except RocklyError as error:   # the robot's commands could not be made for it: said, the others go on
                rows[path] = _problem(path, app_text("lesson_cannot_check", language, program=path.name,
                                                     error=error.in_language(language)))
    results = [rows[path] for path in paths]
    for path, result in zip(paths, results, strict=True):
        _print_result(result, types.get(path, {}), language)
    if csv_path:
        _write_csv(results, csv_path)
    return EXIT_PASSED if all(result["passed"] for result in results) else EXIT_FAILED


def _problem(path, words) -> dict:
    return {"program": path.name, "passed": False, "ending": "not_checked", "ending_words": words, "time": None,
            "failing": None, "goals": []}


def _print_result(result, types: dict, language):
    key = "lesson_all_passed" if result["passed"] else "lesson_not_all_passed"
    print(app_text(key, language, program=result["program"]))
    for goal in result["goals"]:
        mark = app_text("lesson_passed" if goal["passed"] else "lesson_failed", language)
        print(f"  [{mark}] {goal['words']}")
    print(f"  {result['ending_words']}")
    if result["failing"] and not result["passed"]:
        time, block = result["failing"]
        named = f"{block} ({types[block]})" if block in types else block or "-"
        print("  " + app_text("lesson_failing_moment", language, time=time, block=named))


def _write_csv(results, csv_path):
    kinds = []
    for result in results:
        for index, goal in enumerate(result["goals"]):
            name = goal["id"] or f"{index + 1}:{goal['kind']}"
            if name not in kinds:
                kinds.append(name)
    buffer = io.StringIO()
    writer = csv.writer(buffer)
    writer.writerow(["program", "passed", "ending", "seconds", *kinds])
    for result in results:
        marks = {goal["id"] or f"{index + 1}:{goal['kind']}": int(goal["passed"])
                 for index, goal in enumerate(result["goals"])}
        seconds = f"{result['time']:.2f}" if result["time"] is not None else ""
        writer.writerow([result["program"], int(result["passed"]), result["ending"], seconds,
                         *(marks.get(kind, "") for kind in kinds)])
    if csv_path == "-":
        sys.stdout.write(buffer.getvalue())
    else:
        Path(csv_path).write_text(buffer.getvalue(), encoding="utf-8")
