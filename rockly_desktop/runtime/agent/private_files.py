"""Files only their owner may read (mode 0600), written whole or not at all: the agent's pairings and TLS key,
the laptop's robot keys."""
import json
import os
import tempfile
from contextlib import contextmanager
from pathlib import Path


def write_private(path: Path, data: bytes):
    """Make ``path`` hold ``data``, readable and writable by its owner only, all or nothing: written to a file of
    mode 0600 beside it (never wider, not even for a moment), flushed to the disk, then put in its place."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    descriptor, name = tempfile.mkstemp(prefix="." + path.name + "-", dir=str(path.parent))  # mkstemp: mode 0600
    try:
        with os.fdopen(descriptor, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(name, str(path))
    except BaseException:
        try:
            os.unlink(name)
        except OSError:
            pass
        raise


def private_folder(folder: Path) -> Path:
    """``folder``, made (with its parents) when missing; itself readable by its owner only."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    os.chmod(str(folder), 0o700)
    return folder


def write_private_json(path: Path, value):
    """``write_private`` of ``value`` as JSON."""
    write_private(path, (json.dumps(value, indent=1, ensure_ascii=False) + "\n").encode("utf-8"))


def read_json(path: Path, default):
    """The JSON value in ``path``; ``default`` when there is no such file. OSError or ValueError when it cannot be
    read."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return default
    return json.loads(text)


@contextmanager
def held(lock_path: Path):
    """Hold the lock file ``lock_path`` (made when missing) against other processes for the ``with`` block."""
    import fcntl

    lock_path = Path(lock_path)
    lock_path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    descriptor = os.open(str(lock_path), os.O_RDWR | os.O_CREAT, 0o600)
    try:
        fcntl.flock(descriptor, fcntl.LOCK_EX)
        yield
    finally:
        os.close(descriptor)  # and so the lock
