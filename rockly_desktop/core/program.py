"""The ``.rockly`` program file: a small JSON envelope around Blockly's workspace JSON.

A file looks like::

    {"format": "rockly-program", "version": 1, "profile": "my_robot",
     "workspace": { ...Blockly's JSON serialization... }}

A program using blocks of block packs also records them, ``"packs": {"pack_id": "1.0.2"}``
(id and version), so that opening it without a pack can say which one is missing.

Reading never changes the file; writing is atomic (temp file, fsync, rename), through
symbolic links to their target.
"""
import glob
import json
import os
import stat
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from rockly_desktop.core import deep_json
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.file_stamp import FileStamp, stamp_written

FORMAT_NAME = "rockly-program"
FORMAT_VERSION = 1
PROGRAM_SUFFIX = ".rockly"
MAX_FILE_BYTES = 64 * 1024 * 1024  # a 10,000-block program is about 3 MB


@dataclass
class Program:
    """A program: the robot profile it is written for and its Blockly workspace."""

    profile_id: str
    workspace: dict = field(default_factory=dict)
    breakpoints: list = field(default_factory=list)
    packs: dict = field(default_factory=dict)  # {block pack id: version} of the packs whose blocks it uses

    def to_json(self, extra=None) -> str:
        """The file's text, stable and readable in a diff (compact when very deeply nested).

        ``extra`` adds top-level keys that readers of programs pass over (a recovery
        file's ``recovery``). A lone surrogate (half of an emoji, from a broken paste)
        cannot be written as UTF-8; such a document is written with ``\\u`` escapes instead."""
        document = {
            "format": FORMAT_NAME,
            "version": FORMAT_VERSION,
            "profile": self.profile_id,
            "workspace": self.workspace,
            "breakpoints": list(self.breakpoints),
            **({"packs": dict(self.packs)} if self.packs else {}),
            **(extra or {}),
        }
        text = deep_json.dumps(document, indent=1, ensure_ascii=False)
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:
            text = deep_json.dumps(document, indent=1, ensure_ascii=True)
        return text + "\n"


def parse_program(text: str, path="<text>") -> Program:
    """Parse a ``.rockly`` document; raise ProgramFileError saying what is wrong."""
    if not text.strip():
        raise ProgramFileError(path, app_local_text("file_empty"))
    try:
        document = deep_json.loads(text)
    except json.JSONDecodeError as error:
        raise ProgramFileError(path, app_local_text("file_broken_json", line=error.lineno, column=error.colno,
                                                    problem=error.msg)) from None
    except ValueError as error:  # a number that is not finite, or nesting past deep_json.MAX_DEPTH
        raise ProgramFileError(path, app_local_text("file_not_rockly_because", problem=error)) from None
    if not isinstance(document, dict) or document.get("format") != FORMAT_NAME:
        raise ProgramFileError(path, app_local_text("file_not_rockly"))
    version = document.get("version")
    if not isinstance(version, int) or isinstance(version, bool) or version < 1:
        raise ProgramFileError(path, app_local_text("file_no_version"))
    if version > FORMAT_VERSION:
        raise ProgramFileError(path, app_local_text("file_newer", version=version, newest=FORMAT_VERSION))
    profile_id = document.get("profile")
    if not isinstance(profile_id, str) or not profile_id:
        raise ProgramFileError(path, app_local_text("file_no_profile"))
    workspace = document.get("workspace")
    if not isinstance(workspace, dict):
        raise ProgramFileError(path, app_local_text("file_no_workspace"))
    breakpoints = document.get("breakpoints", [])
    if not isinstance(breakpoints, list) or not all(isinstance(item, str) for item in breakpoints):
        raise ProgramFileError(path, app_local_text("file_bad_breakpoints"))
    packs = document.get("packs", {})
    if not isinstance(packs, dict) or not all(isinstance(key, str) and isinstance(value, str)
                                              for key, value in packs.items()):
        raise ProgramFileError(path, app_local_text("file_bad_packs"))
    return Program(profile_id=profile_id, workspace=workspace, breakpoints=breakpoints, packs=packs)


def read_text_file(path, max_bytes: int = MAX_FILE_BYTES) -> str:
    """Read a UTF-8 text file, turning every failure into a ProgramFileError.

    Only regular files of at most ``max_bytes`` are read: a FIFO would block forever and
    a link to ``/dev/zero`` would fill the memory.
    """
    path = Path(path)
    try:
        info = os.stat(path)
        if stat.S_ISDIR(info.st_mode):
            raise ProgramFileError(path, app_local_text("file_is_folder"))
        if not stat.S_ISREG(info.st_mode):
            raise ProgramFileError(path, app_local_text("file_not_regular"))
        with open(path, "rb") as stream:
            data = stream.read(max_bytes + 1)
    except FileNotFoundError:
        raise ProgramFileError(path, app_local_text("file_missing")) from None
    except IsADirectoryError:
        raise ProgramFileError(path, app_local_text("file_is_folder")) from None
    except OSError as error:
        raise ProgramFileError(path, app_local_text("file_unreadable", problem=error.strerror)) from None
    if len(data) > max_bytes:
        raise ProgramFileError(path, app_local_text("file_too_large", megabytes=max_bytes // (1024 * 1024)))
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ProgramFileError(path, app_local_text("file_not_text")) from None


def load_program(path) -> Program:
    """Read a ``.rockly`` file from disk."""
    return parse_program(read_text_file(path), path)


def write_text_atomically(path, text: str):
    """Replace ``path`` with ``text`` so that readers see the old or the new file, never half;
    return the FileStamp of what was written (None for something not a regular file).

    The text goes to a temporary file in the target's folder, is flushed to disk and then
    renamed over the target. An existing file keeps its permission bits; a new one gets
    the usual ones (0o666 less the umask). A symbolic link is written through: its target
    is replaced (in the target's folder) and the link stays. Something that is not a
    regular file (a terminal, a pipe, a FIFO, ``/dev/stdout``) cannot be renamed over
    without destroying it, so the text is written into it directly.
    """
    path = Path(path)
    try:
        data = text.encode("utf-8")
    except UnicodeEncodeError as error:
        raise ProgramFileError(path, app_local_text("file_unsavable_text", problem=error.reason)) from None
    try:
        existing = os.stat(path)  # follows links
    except FileNotFoundError:
        existing = None  # a new file (or a link to a file still to be made)
    except OSError as error:  # a link loop, a folder we may not look into, ...
        raise ProgramFileError(path, app_local_text("file_not_saved", problem=error.strerror)) from None
    if existing is not None and stat.S_ISDIR(existing.st_mode):
        raise ProgramFileError(path, app_local_text("file_not_saved_folder"))
    if existing is not None and not stat.S_ISREG(existing.st_mode):
        _write_directly(path, data)
        return None
    target = Path(os.path.realpath(path)) if os.path.islink(path) else path
    written = _replace_file(path, target, data, stat.S_IMODE(existing.st_mode) if existing else _new_file_mode())
    return stamp_written(written, data)


def _write_directly(path: Path, data: bytes) -> None:
    """Write into a device or a FIFO as it is (opening a FIFO waits for its reader)."""
    try:
        with open(path, "wb") as stream:
            stream.write(data)
            stream.flush()
    except OSError as error:
        raise ProgramFileError(path, app_local_text("file_not_saved", problem=error.strerror)) from None


def _replace_file(path: Path, target: Path, data: bytes, mode: int) -> os.stat_result:
    """Write ``data`` to a temporary file next to ``target`` and rename it over ``target``;
    errors name ``path`` (what the person asked for). Returns the new file's status, taken
    before the rename, which keeps its inode, size and modification time: what another
    writer puts there after the rename cannot be taken for this one's."""
    folder = target.parent if str(target.parent) else Path(".")
    remove_stale_temp_files(target)
    try:
        handle, temp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as error:
        raise ProgramFileError(path, app_local_text("file_folder_not_writable", problem=error.strerror)) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temp_name, mode)
        written = os.stat(temp_name)
        os.replace(temp_name, target)
    except BaseException as error:
        try:
            os.unlink(temp_name)
        except OSError:
            pass
        if isinstance(error, OSError):
            raise ProgramFileError(path, app_local_text("file_not_saved", problem=error.strerror)) from None
        raise
    return written


STALE_TEMP_SECONDS = 60  # older than any save still writing


def remove_stale_temp_files(target) -> int:
    """Delete temporary files an interrupted save of ``target`` left beside it (a crash or
    kill -9 between writing and renaming); returns how many. Only files of our own naming
    (``.NAME.XXXXXXXX.tmp``) that no save can still be writing are touched."""
    target = Path(target)
    folder = target.parent if str(target.parent) else Path(".")
    removed = 0
    now = time.time()
    try:
        candidates = list(folder.glob(f".{glob.escape(target.name)}.*.tmp"))
    except OSError:
        return 0
    for candidate in candidates:
        middle = candidate.name[len(target.name) + 2:-len(".tmp")]
        try:
            info = candidate.lstat()
            if (len(middle) == 8 and stat.S_ISREG(info.st_mode)
                    and now - info.st_mtime > STALE_TEMP_SECONDS):
                candidate.unlink()
                removed += 1
        except OSError:
            continue
    return removed


def _new_file_mode() -> int:
    """The permission bits ``open()`` gives a new file: 0o666 less the umask (mkstemp's 0o600 is private)."""
    umask = os.umask(0o022)
    os.umask(umask)
    return 0o666 & ~umask


def save_program(path, program: Program) -> FileStamp:
    """Write a program to disk atomically; the FileStamp of what was written (None: not a regular file)."""
    return write_text_atomically(path, program.to_json())
