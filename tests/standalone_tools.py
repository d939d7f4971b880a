"""Exporting a program as a standalone file and running that file, as a user does (real processes)."""
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

from program_builder import rockly_document

REPO = Path(__file__).resolve().parents[1]


def export_standalone(source: Path, output: Path, *extra, env=None) -> Path:
    """``rockly export SOURCE --standalone -o OUTPUT`` (the window's settings from ``env``'s folders)."""
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "export", str(source), "--standalone",
                             "-o", str(output), *extra], capture_output=True, text=True, timeout=120, cwd=REPO,
                            env=env)
    assert result.returncode == 0, result.stderr
    return output


def exported_program(folder: Path, top_block, name: str = "drive", profile: str = "hobbit") -> tuple:
    """``(standalone .py, .rockly)``: a program of ``top_block`` (program_builder's) written into ``folder`` as
    ``NAME.rockly`` and exported in English, with settings folders of its own there (no teacher's limits)."""
    source = folder / f"{name}.rockly"
    source.write_text(rockly_document([top_block], profile=profile))
    env = environment(XDG_CONFIG_HOME=str(folder / "config"), XDG_DATA_HOME=str(folder / "data"))
    return export_standalone(source, folder / f"{name}.py", "--language", "en", env=env), source


def run_file(path: Path, *args, python=sys.executable, env=None, timeout=120) -> subprocess.CompletedProcess:
    """``python3 PATH ARGS``, from a folder that is not Rockly's (the runtime must be installed, not found)."""
    return subprocess.run([str(python), str(path), *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=path.parent, env=env)


def start_file(path: Path, *args, env=None) -> subprocess.Popen:
    """``python3 PATH ARGS`` as a running process (its standard output a pipe)."""
    return subprocess.Popen([sys.executable, str(path), *map(str, args)], text=True, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=path.parent, env=env)


def events(stdout: str) -> list:
    """The JSON-lines event stream a file wrote with ``--events -``."""
    return [json.loads(line) for line in stdout.splitlines()]


def wait_for_event(process: subprocess.Popen, wanted, seen: list, timeout=60):
    """Read ``process``'s event lines into ``seen`` until one is ``wanted(record)``; return that record."""
    for line in process.stdout:
        seen.append(json.loads(line))
        if wanted(seen[-1]):
            return seen[-1]
    raise AssertionError(f"the event never came: {seen}; {process.stderr.read()}")


def end(process: subprocess.Popen):
    """Leave no process behind."""
    if process.poll() is None:
        process.send_signal(signal.SIGKILL)
    process.wait(10)


def environment(**changes) -> dict:
    return {**os.environ, **changes}
