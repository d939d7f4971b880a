"""Copies of programs with unsaved changes that outlive a crash: writing, finding, removing them.

Every window keeps at most one recovery file, ``NAME.rockly`` in ``paths.recovery_dir()``,
where NAME is the process id and a random part (two windows never share a name, and a
process id reused after a reboot does not matter). Beside it, ``NAME.lock`` carries an
exclusive ``flock`` for as long as the window lives. The kernel drops that lock when the
process ends, however it ends (a crash, ``kill -9``, a power cut), so a recovery file whose
lock nobody holds was left by a Rockly that did not close cleanly: ``claim_abandoned``
finds it and takes the lock itself while the person decides, so no other Rockly offers it
meanwhile. A lock file appears already locked (it is locked under a temporary name, then
renamed), so a lock file that can be locked has no owner.

A recovery file is a ``.rockly`` program with one more key: ``"recovery": {"file": the
program's file or null, "saved_at": ISO 8601 time, "pid": ..., "file_stamp": the program
file's FileStamp as the window last read or wrote it, or absent}``; any Rockly can open it.
The stamp lets the window that restores the program notice that the file changed since.
"""
import fcntl
import os
import secrets
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

from rockly_desktop.core import deep_json, paths
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.file_stamp import FileStamp
from rockly_desktop.core.program import (
    PROGRAM_SUFFIX,
    Program,
    parse_program,
    read_text_file,
    remove_stale_temp_files,
    write_text_atomically,
)

LOCK_SUFFIX = ".lock"


def _locked(path: Path):
    """Open ``path`` (made if missing) and take its exclusive lock: the open file, or None
    when another open file holds the lock (in this process or another)."""
    handle = os.open(path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o600)
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        os.close(handle)
        return None
    return handle


def _unlink(path: Path):
    try:
        path.unlink()
    except FileNotFoundError:
        pass


class RecoverySession:
    """One window's recovery file: ``write`` it while the program has unsaved changes,
    ``remove`` it when they are saved or thrown away, ``close`` at a clean exit.

    Nothing is made on disk before the first ``write``.
    """

    def __init__(self, folder=None):
        self.folder = Path(folder) if folder else paths.recovery_dir()
        name = f"{os.getpid()}-{secrets.token_hex(4)}"
        self.path = self.folder / f"{name}{PROGRAM_SUFFIX}"
        self.lock_path = self.folder / f"{name}{LOCK_SUFFIX}"
        self._lock = None

    def write(self, program: Program, program_path=None, file_stamp=None):
        """Keep ``program`` (belonging to the file ``program_path``, None if never saved, which was
        ``file_stamp`` when the window read or wrote it), replacing the last copy atomically;
        raises ProgramFileError when it cannot."""
        if self._lock is None:
            self._hold_lock()
        saved_at = datetime.now(timezone.utc).isoformat(timespec="seconds")
        recovery = {"file": str(program_path) if program_path else None, "saved_at": saved_at, "pid": os.getpid()}
        if program_path and file_stamp is not None:
            recovery["file_stamp"] = file_stamp.to_json()
        write_text_atomically(self.path, program.to_json(extra={"recovery": recovery}))

    def remove(self):
        """Delete the copy (the program has no unsaved changes any more); the lock stays."""
        _unlink(self.path)

    def close(self):
        """A clean exit: delete the copy and the lock file."""
        self.remove()
        if self._lock is not None:
            _unlink(self.lock_path)
            os.close(self._lock)
            self._lock = None

    def _hold_lock(self):
        try:
            self.folder.mkdir(mode=0o700, parents=True, exist_ok=True)
            temporary = self.folder / f".{self.lock_path.name}.new"
            handle = _locked(temporary)
            os.replace(temporary, self.lock_path)  # the lock file appears locked
        except OSError as error:
            raise ProgramFileError(self.lock_path, f"the recovery folder cannot be used ({error.strerror})") from None
        self._lock = handle


@dataclass
class Recovery:
    """A recovery file a Rockly left behind, claimed (locked) by this process until it is
    ``discard``-ed (deleted) or ``release``-d (left for a later start).

    ``program_path`` is the file the program belongs to (None: it was never saved);
    ``saved_at`` when the copy was written (timezone-aware); ``file_stamp`` the program file's
    FileStamp as the window knew it (None: not known, a copy an older Rockly wrote).
    """

    path: Path
    program_path: str
    saved_at: datetime
    program: Program = field(repr=False)
    file_stamp: FileStamp = None
    _lock: int = field(default=None, repr=False)

    @property
    def lock_path(self) -> Path:
        """The lock file beside the recovery file."""
        return self.path.with_suffix(LOCK_SUFFIX)

    def discard(self):
        """Delete the recovery file (and its lock file, and what a write cut short left): the
        person no longer needs it."""
        _unlink(self.path)
        remove_stale_temp_files(self.path)
        _unlink(self.lock_path)
        self.release()

    def release(self):
        """Let go of the claim: the file stays and is offered again at a later start."""
        if self._lock is not None:
            os.close(self._lock)
            self._lock = None


def read_recovery(path) -> Recovery:
    """Read a recovery file (unclaimed); raise ProgramFileError when it is not one."""
    path = Path(path)
    text = read_text_file(path)
    program = parse_program(text, path)
    details = deep_json.loads(text).get("recovery")
    if not isinstance(details, dict):
        raise ProgramFileError(path, "this is not a recovery file (no \"recovery\")")
    try:
        saved_at = datetime.fromisoformat(details["saved_at"])
    except (KeyError, TypeError, ValueError):
        raise ProgramFileError(path, "the recovery file does not say when it was written") from None
    program_path = details.get("file")
    if saved_at.tzinfo is None or not (program_path is None or isinstance(program_path, str)):
        raise ProgramFileError(path, "the recovery file's \"recovery\" is not valid")
    return Recovery(path, program_path, saved_at, program, FileStamp.from_json(details.get("file_stamp")))


def claim_abandoned(folder=None):
    """The newest recovery file no running Rockly holds, claimed for this process; None if there is none.

    Files that cannot be read are passed over (and kept); lock files nobody holds and no
    recovery file needs any more are deleted.
    """
    folder = Path(folder) if folder else paths.recovery_dir()
    try:
        candidates = sorted(folder.glob(f"*{PROGRAM_SUFFIX}"), key=_modified_time, reverse=True)
        locks = list(folder.glob(f"*{LOCK_SUFFIX}"))
    except OSError:
        return None
    for lock_path in locks:
        if not lock_path.with_suffix(PROGRAM_SUFFIX).exists():
            _remove_unheld_lock(lock_path)
    for candidate in candidates:
        recovery = _claim(candidate)
        if recovery is not None:
            return recovery
    return None


def _modified_time(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0


def _remove_unheld_lock(lock_path: Path):
    try:
        handle = _locked(lock_path)
    except OSError:
        return
    if handle is not None:
        _unlink(lock_path)
        os.close(handle)


def _claim(path: Path):
    """``path`` as a claimed Recovery when its owner is gone and it can be read, else None."""
    try:
        handle = _locked(path.with_suffix(LOCK_SUFFIX))
    except OSError:
        return None
    if handle is None:  # its Rockly is running (or another one is offering it)
        return None
    try:
        recovery = read_recovery(path)
    except ProgramFileError:
        if not path.exists():  # discarded by another Rockly meanwhile: the lock file we made goes too
            _unlink(path.with_suffix(LOCK_SUFFIX))
        os.close(handle)
        return None
    recovery._lock = handle
    return recovery
