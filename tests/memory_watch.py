"""Watching processes' memory (RSS) while a stream runs, failing as soon as it grows past a bound."""
import gc
import time
from pathlib import Path

from waiting import eventually


def rss_bytes(pid="self") -> int:
    """The resident memory of process ``pid`` (this one by default), in bytes."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) * 1024
    raise LookupError(f"no VmRSS for process {pid}")


def watch_growth(seconds: float, bounds: dict) -> dict:
    """Sample the RSS of the processes ``bounds`` names ({pid: bytes it may grow}) for ``seconds``; fail at
    once when one grows past its bound (a leak must not take the machine's memory). A process that ends meanwhile
    (a helper Rockly replaced on a loaded machine) is watched until it ended. Returns {pid: peak growth}."""
    gc.collect()
    start = {pid: size for pid, size in ((pid, _rss_or_none(pid)) for pid in bounds) if size is not None}
    peak = dict.fromkeys(start, 0)
    end = time.monotonic() + seconds

    def sampled_to_the_end():
        for pid in list(start):
            size = _rss_or_none(pid)
            if size is None:
                del start[pid]
                continue
            peak[pid] = max(peak[pid], size - start[pid])
            grown, allowed = peak[pid] / 2 ** 20, bounds[pid] / 2 ** 20
            assert peak[pid] < bounds[pid], f"process {pid} grew {grown:.0f} MB (bound {allowed:.0f} MB)"
        return time.monotonic() >= end

    eventually(sampled_to_the_end, timeout=seconds + 30, interval=0.25)
    return peak


def _rss_or_none(pid):
    """``rss_bytes(pid)``, or None when the process has ended."""
    try:
        return rss_bytes(pid)
    except (FileNotFoundError, ProcessLookupError, LookupError):
        return None
