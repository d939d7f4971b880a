"""Samples of one curve in fixed memory, and reading a field's new samples from the state store."""
import numpy as np


class SampleBuffer:
    """The (time, value) samples of one curve, oldest first, never more than ``bound`` of them.

    Two preallocated numpy arrays with a little spare room: appending writes behind the newest
    sample, and when the room runs out the kept samples move back to the front. Memory is fixed
    at creation; ``times`` and ``values`` are views without copying.
    """

    def __init__(self, bound: int):
        if bound < 1:
            raise ValueError("a sample buffer holds at least one sample")
        self.bound = bound
        capacity = bound + bound // 4 + 1
        self._times = np.empty(capacity)
        self._values = np.empty(capacity)
        self._start = 0
        self._end = 0
        self.last_time = None  # newest time ever appended (kept when trimmed away)
        self.at_last_time = 0  # how many appended samples carry exactly that time

    def __len__(self):
        return self._end - self._start

    @property
    def capacity(self) -> int:
        """The size of the preallocated arrays."""
        return len(self._times)

    @property
    def times(self):
        return self._times[self._start:self._end]

    @property
    def values(self):
        return self._values[self._start:self._end]

    def extend(self, times, values):
        """Append samples (times not older than the newest so far); the oldest go when over the bound."""
        times = np.asarray(times, dtype=float)
        values = np.asarray(values, dtype=float)
        if not len(times):
            return
        newest = times[-1]
        at_newest = len(times) - int(np.searchsorted(times, newest, "left"))
        self.at_last_time = at_newest + (self.at_last_time if newest == self.last_time else 0)
        self.last_time = float(newest)
        if len(times) >= self.bound:
            times, values = times[-self.bound:], values[-self.bound:]
            self._start = 0
            self._end = 0
        count = len(times)
        self._start += max(0, len(self) + count - self.bound)
        if self._end + count > self.capacity:
            kept = len(self)
            self._times[:kept] = self._times[self._start:self._end]
            self._values[:kept] = self._values[self._start:self._end]
            self._start, self._end = 0, kept
        self._times[self._end:self._end + count] = times
        self._values[self._end:self._end + count] = values
        self._end += count

    def trim_before(self, oldest: float):
        """Forget the samples older than ``oldest``."""
        self._start += int(np.searchsorted(self.times, oldest, "left"))

    def between(self, first: float, last: float):
        """(times, values) views of the samples with ``first <= time <= last``."""
        times = self.times
        low = int(np.searchsorted(times, first, "left"))
        high = int(np.searchsorted(times, last, "right"))
        return times[low:high], self.values[low:high]

    def clear(self):
        self._start = self._end = 0
        self.last_time = None
        self.at_last_time = 0


def read_new_samples(store, topic: str, path: str, buffer: SampleBuffer) -> None:
    """Append to ``buffer`` the samples of field ``path`` of ``topic`` that ``store`` (a
    :class:`~rockly_desktop.core.state_store.StateStore`) got since the buffer's newest one."""
    since = buffer.last_time
    points = store.series(topic, path, since=since)
    if since is not None:
        # ``since`` is inclusive: skip the samples at that time that are already in the buffer.
        skip = 0
        while skip < len(points) and skip < buffer.at_last_time and points[skip][0] == since:
            skip += 1
        points = points[skip:]
    if points:
        samples = np.array(points, dtype=float)
        buffer.extend(samples[:, 0], samples[:, 1])
