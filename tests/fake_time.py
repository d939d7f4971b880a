"""A clock that moves only when the test moves it, for the code under test's ``time`` module."""
from waiting import eventually


class FakeTime:
    """Stands in for a module's ``time`` (``monkeypatch.setattr(module, "time", FakeTime())``).

    ``monotonic()`` and ``time()`` are ``now``.
    """

    def __init__(self):
        self.now = 0.0
        self.reads = 0

    def monotonic(self):
        self.reads += 1
        return self.now

    def time(self):
        self.reads += 1
        return self.now

    def read_again(self):
        """Return once the code under test has looked at the clock again (twice, so a whole turn of its loop)."""
        reads = self.reads
        eventually(lambda: self.reads >= reads + 2)
