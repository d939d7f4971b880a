"""A real, tiny file system to fill: a tmpfs mounted for one test (needs root; skipped otherwise)."""
import contextlib
import errno
import subprocess

import pytest


@contextlib.contextmanager
def tiny_disk(folder, size: str = "1m"):
    """A tmpfs of ``size`` mounted on ``folder`` (made) for the ``with`` block, unmounted after it."""
    folder.mkdir(parents=True, exist_ok=True)
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size},mode=0777", "tmpfs", str(folder)],
                             capture_output=True, text=True)
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.strip()}")
    try:
        yield folder
    finally:
        if subprocess.run(["umount", str(folder)], capture_output=True).returncode != 0:
            subprocess.run(["umount", "--lazy", str(folder)], check=True)  # a file still open: gone once closed


def fill(folder, name: str = "filler"):
    """Write zeros to ``folder/name`` until the file system is full."""
    block = bytes(4096)
    with open(folder / name, "wb", buffering=0) as stream:
        try:
            while True:
                stream.write(block)
        except OSError as error:
            assert error.errno == errno.ENOSPC
