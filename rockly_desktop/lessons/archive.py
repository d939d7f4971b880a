"""Lesson packs: a folder of lessons shared as one zip, as block packs are (``rockly lessons export/import``).

The zip holds one top folder, the pack, with its lessons below it. Importing refuses anything unsafe
before writing (an absolute path, ``..``, a link, a name twice, too many entries or bytes: the rules of
block packs' zips), unpacks into a hidden folder beside the user's lessons, reads every lesson there
(``load_lesson``: a broken one refuses the whole pack, naming its file and line), and only then puts
the pack in place.
"""
import os
import shutil
import stat
import tempfile
import zipfile
from pathlib import Path, PurePosixPath

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.lessons.lesson import load_lesson
from rockly_desktop.lessons.lesson_file import LessonError
from rockly_desktop.lessons.library import lesson_folders, user_lessons_dir

MAX_ENTRIES = 2000
MAX_BYTES = 50 * 1024 * 1024   # unpacked: lessons are text, programs and a few pictures


def export_lessons(folder, output) -> Path:
    """Write the lessons in ``folder`` (a pack: a folder of lesson folders, or one lesson) to the zip
    ``output``, all or nothing; returns its path. LessonError when the folder holds no lesson."""
    folder, output = Path(folder), Path(output)
    if not lesson_folders(folder):
        raise LessonError(folder, 0, app_local_text("lesson_problem_no_lessons"))
    output.parent.mkdir(parents=True, exist_ok=True)
    handle, temp_name = tempfile.mkstemp(prefix=f".{output.name}.", suffix=".tmp", dir=output.parent)
    os.close(handle)
    try:
        with zipfile.ZipFile(temp_name, "w", zipfile.ZIP_DEFLATED) as archive:
            for path in sorted(folder.rglob("*")):
                relative = path.relative_to(folder)
                hidden = any(part.startswith(".") or part == "__pycache__" for part in relative.parts)
                if path.is_file() and not path.is_symlink() and not hidden:
                    archive.write(path, f"{folder.name}/{relative.as_posix()}")
        os.replace(temp_name, output)
    except BaseException:
        Path(temp_name).unlink(missing_ok=True)
        raise
    return output


def _pack_entries(path: Path, archive: zipfile.ZipFile):
    """(the pack's top folder, [ZipInfo]) after refusing anything unsafe."""
    infos = archive.infolist()
    if len(infos) > MAX_ENTRIES:
        raise LessonError(path, 0, app_local_text("lesson_problem_zip_entries", entries=MAX_ENTRIES))
    total, names, tops = 0, set(), set()
    for info in infos:
        pure = PurePosixPath(info.filename)
        if ("\\" in info.filename or pure.is_absolute() or ".." in pure.parts or ":" in info.filename
                or stat.S_ISLNK(info.external_attr >> 16)):
            raise LessonError(path, 0, app_local_text("lesson_problem_zip_unsafe", name=info.filename))
        total += info.file_size
        if total > MAX_BYTES:
            raise LessonError(path, 0, app_local_text("lesson_problem_zip_size", megabytes=MAX_BYTES // 2**20))
        if pure in names:
            raise LessonError(path, 0, app_local_text("lesson_problem_zip_twice", name=str(pure)))
        names.add(pure)
        tops.add(pure.parts[0])
    if len(tops) != 1:
        raise LessonError(path, 0, app_local_text("lesson_problem_zip_top"))
    return tops.pop(), infos


def import_lessons(path, profiles: dict, folder=None, replace: bool = False) -> Path:
    """Install the lesson pack zip ``path`` into ``folder`` (the user's lessons by default); returns where
    it is. Every lesson is read first: a broken one (LessonError) or a pack already there (unless
    ``replace``) leaves everything as it was."""
    path = Path(path)
    folder = Path(folder) if folder is not None else user_lessons_dir()
    try:
        archive = zipfile.ZipFile(path)
    except (OSError, zipfile.BadZipFile) as error:
        raise LessonError(path, 0, app_local_text("lesson_problem_zip_unreadable", reason=error)) from None
    with archive:
        top, infos = _pack_entries(path, archive)
        target = folder / top
        if target.exists() and not replace:
            raise LessonError(path, 0, app_local_text("lesson_problem_pack_installed", pack=top, folder=target,
                                                              option="--replace"))
        folder.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=".import-", dir=folder))
        try:
            for info in infos:
                archive.extract(info, staging)
            unpacked = staging / top
            found = lesson_folders(unpacked)
            if not found:
                raise LessonError(path, 0, app_local_text("lesson_problem_pack_empty"))
            for lesson_folder in found:
                try:
                    load_lesson(lesson_folder, profiles)
                except LessonError as error:   # named as it is in the zip, not in the hidden folder
                    inside = Path(error.path).relative_to(staging).as_posix()
                    raise LessonError(f"{path}: {inside}", error.line, error._problem) from None
            if target.exists():
                shutil.rmtree(target)
            os.replace(unpacked, target)
        finally:
            shutil.rmtree(staging, ignore_errors=True)
    return target
