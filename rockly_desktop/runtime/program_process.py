"""The program's own process: it runs a program's code and owns no robot link.

    python3 -m rockly_desktop.runtime.program_process FD [FOLDER ...]

``FD`` is its end of a socket pair with the link host (``runtime/link_host.py``), which owns the robot
link, keeps the limits and does the safe stop. The wire (``runtime/link_wire.py``) carries, from the host:
``profile`` (the robot's commands to make, sent at once so a waiting process is ready), ``start`` (the
code, its variables, the language, the controls), ``control`` (pause, step, continue, stop, breakpoints,
delay), answers to calls and pushed messages; to the host: ``ready``, ``call`` (each robot command, see
``remote_backend.py``), ``event`` (each run event, as ``runtime/event_stream.py`` writes it), ``sample``
(every ``SAMPLE_SECONDS``, what changed of: the block it is at, the variables, the values, and for a recording the
blocks entered since the last sample with their ``monotonic_ns``) and ``refused`` (the profile's commands could
not be made). A tight loop so costs the host one line per sample, not one per block.

Before anything else it leaves the network (a network namespace of its own, where Linux allows it): the
program's only way to the robot is the host. Each ``FOLDER`` (the agent's library with its keys and pairings,
the folder of the robot's own limits) it neither sees nor changes: in a mount namespace of its own, an empty
read-only folder lies over it. The host closing its end ends this process at once.
"""
import ctypes
import errno
import os
import queue
import socket
import sys
import threading
import time
from collections import deque

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import RunFinished, RunPaused
from rockly_desktop.executor.run_setup import program_runner
from rockly_desktop.profiles.profile import Profile
from rockly_desktop.runtime.event_stream import event_record
from rockly_desktop.runtime.remote_backend import HostConnection, RemoteBackend

SAMPLE_SECONDS = 0.033  # how often the block and the variables are looked at (as often as the window shows them)
BLOCKS_PER_SAMPLE = 100  # blocks entered a recording gets per sample (a tight loop is then sampled)
CLONE_NEWUSER, CLONE_NEWNET, CLONE_NEWNS = 0x10000000, 0x40000000, 0x00020000
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC, MS_REC, MS_PRIVATE = 0x1, 0x2, 0x4, 0x8, 0x4000, 0x40000


def isolate(hidden=()) -> bool:
    """Move this process into a network namespace of its own (no interface but a down loopback) and, with
    ``hidden`` folders, a mount namespace of its own with each of them covered by an empty read-only tmpfs; as
    root or in a user namespace of its own. False where Linux refuses (then nothing is hidden either). Call it
    while the process has one thread."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None, use_errno=True)
    except OSError:
        return False
    namespaces = CLONE_NEWNET | (CLONE_NEWNS if hidden else 0)
    for flags in (namespaces, CLONE_NEWUSER | namespaces):
        if libc.unshare(flags) == 0:
            return _hide(libc, hidden)
        if ctypes.get_errno() not in (errno.EPERM, errno.EINVAL, errno.ENOSPC, errno.EUSERS):
            break
    return False


def _hide(libc, hidden) -> bool:
    """Cover each folder of ``hidden`` that exists (in this process's own mount namespace); whether all are."""
    if not hidden:
        return True
    if libc.mount(b"none", b"/", None, MS_REC | MS_PRIVATE, None) != 0:  # nothing done here reaches the host
        return False
    covered = True
    for folder in hidden:
        if not os.path.isdir(folder):
            continue
        flags = MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC
        covered = libc.mount(b"tmpfs", os.fsencode(folder), b"tmpfs", flags, b"size=4k,mode=0555") == 0 and covered
    return covered


def apply_control(control: RunControl, record: dict):
    """One of the host's control requests, applied to the run's ``control``."""
    request = record.get("do")
    if request == "pause":
        control.request_pause()
    elif request == "step":
        control.step()
    elif request == "continue":
        control.resume()
    elif request == "stop":
        control.request_stop()
    elif request == "breakpoints":
        control.set_breakpoints(block for block in record.get("ids") or () if isinstance(block, str))
    elif request == "delay":
        control.set_delay(float(record.get("seconds") or 0.0))


class _Sampler:
    """Says, every ``SAMPLE_SECONDS`` and before a pause or the end (``flush``), what changed of where the program
    is, its variables and values, and (``entered``: the runner's deque of blocks entered, for a recording) the
    blocks entered since the last time."""

    def __init__(self, host: HostConnection, entered=None):
        self.host = host
        self.entered = entered
        self.runner = None
        self._shown = {}
        self._lock = threading.Lock()
        self._ended = threading.Event()

    def follow(self, runner):
        """Sample ``runner`` from now on, on a thread of its own, until ``end``."""
        self.runner = runner
        if self.entered is not None:
            runner.hooks.block_budget = BLOCKS_PER_SAMPLE
        thread = threading.Thread(target=self._loop, name="rockly-sample", daemon=True)
        thread.start()
        return thread

    def _loop(self):
        while not self._ended.wait(SAMPLE_SECONDS):
            self.flush()

    def end(self, thread):
        """Stop sampling; a last sample is said."""
        self._ended.set()
        thread.join()
        self.flush()

    def flush(self):
        """Say what changed since the last sample."""
        runner = self.runner
        if runner is None:
            return
        with self._lock:
            sample = {"block": runner.hooks.current_block, "variables": runner.variables_snapshot(),
                      "values": runner.values_snapshot()}
            changed = {key: value for key, value in sample.items() if self._shown.get(key, ()) != value}
            if self.entered is not None:
                batch = [self.entered.popleft() for _ in range(len(self.entered))]
                if not runner.hooks.block_budget and sample["block"] is not None:  # a tight loop: where it is now
                    batch.append((time.monotonic_ns(), sample["block"]))
                runner.hooks.block_budget = BLOCKS_PER_SAMPLE
                if batch:
                    changed["entered"] = batch
            if changed:
                self._shown.update(sample)
                self.host.send({"op": "sample", **changed})


def _emit(host: HostConnection, sampler: _Sampler):
    def emit(event):
        record = event_record(event, {})
        if record is None:
            return
        if isinstance(event, (RunPaused, RunFinished)):
            sampler.flush()  # the blocks entered before it, in its order (a recording keeps both)
        if isinstance(event, RunFinished):
            record["details"] = event.details
        host.send({"op": "event", **record})
    return emit


def run(host: HostConnection, inbox: queue.Queue, control: RunControl, isolated: bool):
    """Take the profile and the program from the host, run it, say how it ended."""
    host.send({"op": "ready", "isolated": isolated})
    profile = None
    while True:
        record = inbox.get()
        if record.get("op") == "profile":
            profile = Profile.from_command_side(record["profile"])
            try:
                profile.load_object("api")  # imported while the host still opens the link
            except RocklyError:  # said when the run makes the commands
                pass
        elif record.get("op") == "start":
            break
    language = record.get("language", "en")
    control.trace = bool(record.get("trace"))
    control.set_breakpoints(record.get("breakpoints") or ())
    control.set_delay(float(record.get("delay") or 0.0))
    backend = RemoteBackend(host, control.interrupt)

    def on_end():  # the host's safe stop, before the run says it ended
        failures = host.call("safe_stop")
        if failures:
            raise RuntimeError("; ".join(failures))

    entered = deque() if record.get("entered") else None  # the host records the run: it wants the blocks entered
    sampler = _Sampler(host, entered)
    try:
        runner = program_runner(profile, backend, record["run_code"], control, _emit(host, sampler),
                                language, on_end, entered=entered)
    except RocklyError as error:
        host.send({"op": "refused", "text": error.in_language(language)})
        return
    backend.hooks = runner.hooks
    sampling = sampler.follow(runner)
    try:
        runner.run()
    finally:
        sampler.end(sampling)


def main(argv=None) -> int:
    """Serve the host on the socket pair whose end ``argv[0]`` names."""
    argv = list(sys.argv[1:] if argv is None else argv)
    isolated = isolate(argv[1:])  # first, while this process has one thread
    sock = socket.socket(fileno=int(argv[0]))
    sock.settimeout(None)
    inbox = queue.Queue()
    control = RunControl()

    def on_record(record):
        if record.get("op") == "control":
            apply_control(control, record)
        else:
            inbox.put(record)

    host = HostConnection(sock, on_record)
    host.start()
    run(host, inbox, control, isolated)
    host.send({"op": "end"})
    return 0


if __name__ == "__main__":
    sys.exit(main())
