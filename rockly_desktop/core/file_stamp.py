"""Noticing that a program file changed on disk since a window read or wrote it, as editors do.

A window keeps a FileStamp of its file: taken before it reads the file (a change made while
it reads is then noticed, never missed) and from the very bytes it wrote when it saves. The
file's inode, size and modification time unchanged mean the file is; otherwise the hash of its
content decides, so a file touched or written again with the same text is not a change.
"""
import hashlib
import os
import stat
from dataclasses import asdict, dataclass

MAX_STAMPED_BYTES = 64 * 1024 * 1024  # as core.program.MAX_FILE_BYTES: a larger file is not opened anyway


@dataclass(frozen=True)
class FileStamp:
    """What a file was: inode, size, modification time (ns) and its content's SHA-256."""

    inode: int
    size: int
    mtime_ns: int
    sha256: str

    def to_json(self) -> dict:
        """The stamp as JSON data (kept in a recovery file)."""
        return asdict(self)

    @classmethod
    def from_json(cls, data):
        """A stamp from ``to_json``'s data; None when ``data`` is not one."""
        try:
            stamp = cls(int(data["inode"]), int(data["size"]), int(data["mtime_ns"]), str(data["sha256"]))
        except (TypeError, KeyError, ValueError):
            return None
        return stamp


def _same_file(stamp: FileStamp, info: os.stat_result) -> bool:
    return (stamp.inode, stamp.size, stamp.mtime_ns) == (info.st_ino, info.st_size, info.st_mtime_ns)


def stamp_written(info: os.stat_result, data: bytes) -> FileStamp:
    """The stamp of a file a window just wrote: ``info`` is its status, ``data`` what was written."""
    return FileStamp(info.st_ino, info.st_size, info.st_mtime_ns, hashlib.sha256(data).hexdigest())


def stamp_file(path, known: FileStamp = None):
    """The file at ``path`` as it is now; ``known`` itself when the file is still that one by inode,
    size and time (its content is not read again). None when it is missing, not a regular file
    (a FIFO is never opened), too large or unreadable."""
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_STAMPED_BYTES:
            return None
        if known is not None and _same_file(known, info):
            return known
        handle = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
        with os.fdopen(handle, "rb") as stream:
            info = os.fstat(stream.fileno())
            data = stream.read(MAX_STAMPED_BYTES + 1)
    except OSError:
        return None
    return FileStamp(info.st_ino, info.st_size, info.st_mtime_ns, hashlib.sha256(data).hexdigest())
