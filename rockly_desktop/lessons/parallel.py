"""Checking many programs at once: one process per core, each checking program after program.

The programs' code is generated before (``rockly lessons check`` does it with one windowless editor);
the workers get generated code only, import no Qt, and read the profiles and the lesson once each.
"""
import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from functools import lru_cache

from rockly_desktop.lessons.check import check_program, summary


def cores() -> int:
    """How many cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:
        return max(1, os.cpu_count() or 1)


@lru_cache(maxsize=None)
def _lesson(folder: str):
    from rockly_desktop.lessons.lesson import load_lesson
    from rockly_desktop.profiles.registry import ProfileRegistry

    return load_lesson(folder, ProfileRegistry.discover().profiles)


def check_in_worker(lesson_folder: str, program, language: str) -> dict:
    """``check_program`` of the lesson in ``lesson_folder`` (read once per worker), as ``summary`` data."""
    return summary(check_program(_lesson(lesson_folder), program, language), language)


def _warm_up(lesson_folder: str) -> bool:
    _lesson(lesson_folder)
    return True


class ParallelChecks:
    """A pool of ``jobs`` worker processes checking programs against the lesson in ``lesson_folder``.

    Start it before generating code (``warm_up``: the workers read the profiles and the lesson meanwhile),
    then ``submit`` each program as it is generated; ``close`` ends the workers."""

    def __init__(self, lesson_folder, jobs: int, language: str = "en"):
        self.lesson_folder = str(lesson_folder)
        self.language = language
        self.jobs = max(1, int(jobs))
        self._pool = ProcessPoolExecutor(self.jobs, mp_context=multiprocessing.get_context("spawn"))

    def warm_up(self):
        """Let every worker start and read the lesson now."""
        return [self._pool.submit(_warm_up, self.lesson_folder) for _ in range(self.jobs)]

    def submit(self, program):
        """A future of the ``summary`` of checking ``program`` (a GeneratedProgram)."""
        return self._pool.submit(check_in_worker, self.lesson_folder, program, self.language)

    def close(self):
        """Wait for the checks submitted and end the workers."""
        self._pool.shutdown(wait=True)

    def __enter__(self):
        return self

    def __exit__(self, *_exc):
        self.close()
