"""``rockly lessons check`` on a class's folder of 30 programs, against 30 sequential ``rockly run`` of the
same programs on the simulator (issue 31).

The programs are the TurtleBot's shipped lesson programs (tests/lessons/programs): the "stop before the
wall" solution and wrong program ten times each, the square's and the wall follower's solutions five times
each, 17–25 s of simulated driving apiece. Both sides are the real command in a fresh process:

- check: ``rockly lessons check turtlebot-stop-at-wall FOLDER --jobs N`` (one windowless editor generates
  all 30 programs' code, N checking processes run them in simulated time);
- run: ``rockly run PROGRAM`` for each in turn (each generates its code with its own windowless editor and
  drives in real time, at ``--speed``).

Prints both times, per program, the ratio, and how many cores the check kept busy (its processes' CPU time
over its wall time). Aim: under 1 s per program, using both cores.

    python benchmarks/lessons_check.py [--runs 30] [--speed 1] [--jobs 0 (one per core)]
"""
import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
PROGRAMS = REPO / "tests" / "lessons" / "programs"
CLASS = [("turtlebot-stop-at-wall", "solution", 10), ("turtlebot-stop-at-wall", "wrong", 10),
         ("turtlebot-square", "solution", 5), ("turtlebot-follow-wall", "solution", 5)]


def class_folder(folder: Path) -> list:
    """30 students' programs in ``folder``."""
    paths = []
    for lesson, name, count in CLASS:
        for number in range(count):
            path = folder / f"{lesson}-{name}-{number + 1:02}.rockly"
            shutil.copy(PROGRAMS / lesson / f"{name}.rockly", path)
            paths.append(path)
    return paths


def timed(command) -> tuple:
    """(wall seconds, CPU seconds of the process and its children, exit status) of running ``command``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    result = subprocess.run(command, cwd=REPO, capture_output=True, text=True, env=dict(os.environ))
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, result


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=30,
                        help="how many of the programs `rockly run` runs in turn (0: the check alone)")
    parser.add_argument("--speed", type=float, default=1.0, help="`rockly run --speed`")
    parser.add_argument("--jobs", type=int, default=0, help="`rockly lessons check --jobs` (0: one per core)")
    args = parser.parse_args()
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")
    rockly = [sys.executable, "-m", "rockly_desktop"]
    with tempfile.TemporaryDirectory(prefix="rockly-bench-lessons-") as folder:
        paths = class_folder(Path(folder))
        print(f"load average before: {os.getloadavg()[0]:.2f}; cores: {len(os.sched_getaffinity(0))}")
        command = rockly + ["lessons", "check", "turtlebot-stop-at-wall", folder, "--csv", os.devnull]
        if args.jobs:
            command += ["--jobs", str(args.jobs)]
        check_wall, check_cpu, result = timed(command)
        if result.returncode not in (0, 1) or result.stdout.count(".rockly: ") != len(paths):
            print(result.stdout + result.stderr)
            return 1
        print(f"rockly lessons check, {len(paths)} programs: {check_wall:.1f} s ({check_wall / len(paths):.2f} s a "
              f"program), {check_cpu / check_wall:.2f} cores busy")
        runs = min(args.runs, len(paths))
        if not runs:
            return 0
        run_wall = 0.0
        for path in paths[:runs]:
            wall, _cpu, result = timed(rockly + ["run", str(path), "--speed", str(args.speed)])
            run_wall += wall
        per_run = run_wall / runs
        print(f"rockly run --speed {args.speed:g}, {runs} programs in turn: {run_wall:.1f} s ({per_run:.2f} s a "
              f"program)")
        print(f"ratio (run / check, per program): {per_run / (check_wall / len(paths)):.1f}")
        print(f"load average after: {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
