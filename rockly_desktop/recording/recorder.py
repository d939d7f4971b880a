"""Recording one run: events from any thread into a bounded queue, a writer thread streams them to MCAP.

The program's thread and the robot's threads only put small tuples in a queue (or, for
blocks and printed lines, in deques filled while they have budget); the writer thread wakes
every ``TICK_SECONDS``, writes what came in time order, samples the variables, the
expression blocks' values and the simulator's state, and closes a chunk every ``FLUSH_SECONDS`` so that a crash loses at
most that much. Memory and the writer's work stay bounded whatever the rates and sizes: topics are
capped per topic at ``topic_rate`` messages a second, blocks at ``BLOCKS_PER_TICK`` per tick (a
tight loop is then sampled), printed lines at ``LINES_PER_TICK`` per tick (the rest is counted on
the output channel as ``{"skipped": n}``), a full queue drops what comes (counted in the
recording's stats as ``overflow``), and the robot's messages waiting in it hold at most
``QUEUE_BYTES`` (``message_bytes``'s estimate): a camera's message that does not fit while the
writer is behind is dropped and counted per topic (``dropped``), so a slow disk or encoder never
fills memory. A program printing in an endless loop once queued every line: the writer then wrote
20,000 a tick, holding the GIL in turns with the window, and the run's end waited for the backlog.
A write that fails (a full disk) stops the recording, not the run: what was written stays
readable, what comes later is dropped, and ``on_stopped(error)`` is called once.
"""
import logging
import queue
import threading
import time
from collections import deque

from rockly_desktop.core.message_size import message_bytes
from rockly_desktop.recording import channels
from rockly_desktop.recording.mcap_file import McapFile

log = logging.getLogger(__name__)

TICK_SECONDS = 0.05
FLUSH_SECONDS = 1.0
SNAPSHOT_SECONDS = 0.2
BLOCKS_PER_TICK = 100
LINES_PER_TICK = 100
QUEUE_SIZE = 20_000
QUEUE_BYTES = 64 * 2 ** 20

_STOP = object()


class Recorder:
    """Streams one run to the MCAP file at ``path``.

    ``encoder(msg_type, message) -> (definition, bytes)`` serialises a robot topic's message in its
    ROS encoding, which the encoder names (``message_encoding``: 'ros1' or 'cdr'; ``schema_encoding``:
    'ros1msg' or 'ros2msg'; ``schema_name(msg_type)``); None: topics are written as JSON, as is a
    type the encoder cannot encode (said once in the log); ``topic_rate`` caps each topic (messages a
    second, 0 or less: no topic is recorded); ``clock()`` gives nanoseconds since the epoch;
    ``on_stopped(error)`` is called once, from the writer thread or ``close``, when a write fails
    (``stopped`` is then that OSError).
    """

    def __init__(self, path, encoder=None, topic_rate: float = 10.0, clock=None, on_stopped=None):
        self.path = path
        self.stopped = None
        self._on_stopped = on_stopped
        self._encoder = encoder
        self._gap = int(1e9 / topic_rate) if topic_rate > 0 else None
        # block hooks stamp with block_clock: monotonic_ns, or the given clock itself (a lesson's simulated time)
        self._offset = time.time_ns() - time.monotonic_ns() if clock is None else 0
        self._clock = clock or (lambda: time.monotonic_ns() + self._offset)
        self.block_clock = time.monotonic_ns if clock is None else clock
        self._queue = queue.Queue(QUEUE_SIZE)
        self._last_sent = {}
        self._capped = {}
        self._overflow = 0
        self._dropped = {}
        self._queued_bytes = 0
        self._bytes_lock = threading.Lock()
        self._unencodable = set()
        self._file = None
        self._thread = None
        self._stopping = threading.Event()
        self._hooks = None
        self._variables = None
        self._snapshot = None
        self._last_variables = None
        self._values = None
        self._last_values = {}
        self._last_snapshot = None
        self._next_snapshot = 0.0
        self.blocks = deque()  # (monotonic_ns, block id), filled by the block hook
        self._lines = deque()  # (ns since the epoch, text) printed this tick, at most LINES_PER_TICK
        self._lines_skipped = 0  # grows in the program's thread only
        self._lines_skipped_written = 0  # grows in the writer's thread only
        self._block_types = {}

    # --- set-up --------------------------------------------------------------------------

    def start(self, metadata: dict, program: bytes = None):
        """Open the file, store ``metadata`` and the ``.rockly`` ``program`` and start the writer thread;
        raises OSError when that cannot be written (no file is left then)."""
        self._file = McapFile(self.path)
        now = self._clock()
        try:
            self._file.metadata(channels.METADATA, metadata)
            if program is not None:
                self._file.attach(now, channels.PROGRAM_ATTACHMENT, "application/json", program)
            self._file.flush()
        except OSError:
            self._file.discard()
            raise
        self._thread = threading.Thread(target=self._run, name="rockly-recorder", daemon=True)
        self._thread.start()

    def follow(self, hooks, variables=None, snapshot=None, block_types=None, values=None):
        """Record the blocks ``hooks`` enters (it fills ``self.blocks`` while ``hooks.block_budget`` lasts),
        the ``variables()`` when they change, the simulator's ``snapshot()`` and the expression blocks'
        ``values()`` (those that changed)."""
        self._hooks = hooks
        self._values = values
        self._variables = variables
        self._snapshot = snapshot
        self._block_types = dict(block_types or {})
        hooks.block_budget = BLOCKS_PER_TICK

    # --- from any thread -------------------------------------------------------------------

    def note(self, channel: str, payload: dict):
        """Record one of Rockly's events on ``channel`` (see ``channels``)."""
        self._put((self._clock(), channel, payload))

    def printed(self, text: str):
        """Record a line the program printed, unless this tick's ``LINES_PER_TICK`` are taken (then it is counted)."""
        if len(self._lines) < LINES_PER_TICK:
            self._lines.append((self._clock(), text))
        else:
            self._lines_skipped += 1

    def topic(self, topic: str, msg_type: str, message):
        """Record a robot topic's message, unless it comes sooner than the rate cap allows (or is no
        topic: a simulator's service calls and goals, which the commands channel holds)."""
        if "/" not in msg_type or self.stopped is not None:
            return
        now = self._clock()
        gap = self._gap
        if gap is None or now - self._last_sent.get(topic, -gap) < gap:
            self._capped[topic] = self._capped.get(topic, 0) + 1
            return
        self._last_sent[topic] = now
        size = message_bytes(message)
        with self._bytes_lock:
            if self._queued_bytes + size > QUEUE_BYTES:
                self._dropped[topic] = self._dropped.get(topic, 0) + 1
                return
            self._queued_bytes += size
        self._put((now, None, (topic, msg_type, message, size)))

    def _put(self, item):
        """Queue ``item``; when the queue is full or the recording stopped it is let go (a robot
        message's bytes given back)."""
        if self.stopped is None:
            try:
                self._queue.put_nowait(item)
                return
            except queue.Full:
                self._overflow += 1
        if item[1] is None:
            with self._bytes_lock:
                self._queued_bytes -= item[2][3]

    def stats(self) -> dict:
        """What was not recorded so far: per topic ``capped`` (the rate cap) and ``dropped`` (the queue's bytes
        full), and ``overflow`` (the queue's count full)."""
        return {"capped": dict(self._capped), "overflow": self._overflow, "dropped": dict(self._dropped)}

    # --- the writer thread -------------------------------------------------------------------

    def close(self):
        """Write what is left, the stats and the summary; close the file. Idempotent."""
        if self._thread is None:
            return
        self._stopping.set()
        self._thread.join()
        self._thread = None
        try:
            if self.stopped is None:
                self._write_pending(final=True)
                if self._dropped:
                    log.warning("recording %s: messages dropped while the writer was behind: %s",
                                self.path, self._dropped)
                self._file.write_json(channels.STATS, *channels.SCHEMAS[channels.STATS], self._clock(), self.stats())
            self._file.close()
        except OSError as error:
            self._stop(error)
            self._file.close()

    def _run(self):
        last_flush = time.monotonic()
        while self.stopped is None and not self._stopping.wait(TICK_SECONDS):
            try:
                self._write_pending()
                if time.monotonic() - last_flush >= FLUSH_SECONDS:
                    self._file.flush()
                    last_flush = time.monotonic()
            except OSError as error:
                self._stop(error)
            except Exception:  # a recording must never take the run down
                log.exception("recording %s failed", self.path)

    def _stop(self, error: OSError):
        """A write failed: the recording ends here (once)."""
        if self.stopped is not None:
            return
        self.stopped = error
        log.info("recording %s stopped: %s", self.path, error)
        if self._on_stopped is not None:
            self._on_stopped(error)

    def _write_pending(self, final: bool = False):
        items = []
        while True:
            try:
                items.append(self._queue.get_nowait())
            except queue.Empty:
                break
        taken = sum(payload[3] for _stamp, channel, payload in items if channel is None)
        with self._bytes_lock:
            self._queued_bytes -= taken
        items += self._block_items()
        items += self._printed_items()
        items += self._samples(final)
        items.sort(key=lambda item: item[0])
        for log_ns, channel, payload in items:
            if channel is None:
                self._write_topic(log_ns, *payload[:3])
            else:
                self._file.write_json(channel, *channels.SCHEMAS[channel], log_ns, payload)

    def _block_items(self) -> list:
        items = []
        blocks = self.blocks
        while blocks:
            stamp, block_id = blocks.popleft()
            items.append((stamp + self._offset, channels.BLOCKS,
                          {"block": block_id, "type": self._block_types.get(block_id, "")}))
        hooks = self._hooks
        if hooks is not None:
            if not hooks.block_budget and hooks.current_block is not None:  # a tight loop: where it is now
                items.append((self._clock(), channels.BLOCKS, {"block": hooks.current_block, "type":
                              self._block_types.get(hooks.current_block, ""), "sampled": True}))
            hooks.block_budget = BLOCKS_PER_TICK
        return items

    def _printed_items(self) -> list:
        """This tick's printed lines, then how many were skipped since the last count (ending the tick's budget)."""
        items = []
        lines = self._lines
        for _ in range(len(lines)):
            stamp, text = lines.popleft()
            items.append((stamp, channels.OUTPUT, {"text": text}))
        skipped = self._lines_skipped - self._lines_skipped_written
        if skipped:
            self._lines_skipped_written += skipped
            items.append((self._clock(), channels.OUTPUT, {"skipped": skipped}))
        return items

    def _samples(self, final: bool) -> list:
        items = []
        if self._variables is not None:
            values = self._variables()
            if values != self._last_variables:
                self._last_variables = values
                items.append((self._clock(), channels.VARIABLES, {"values": values}))
        if self._values is not None:
            values = self._values()
            changed = {block: text for block, text in values.items() if self._last_values.get(block) != text}
            if changed:
                self._last_values = values
                items.append((self._clock(), channels.VALUES, {"values": changed}))
        if self._snapshot is not None and (final or time.monotonic() >= self._next_snapshot):
            self._next_snapshot = time.monotonic() + SNAPSHOT_SECONDS
            snapshot = self._snapshot()
            still = {key: value for key, value in (snapshot or {}).items() if key != "time"}
            if snapshot is not None and still != self._last_snapshot:  # a robot standing still is written once
                self._last_snapshot = still
                items.append((self._clock(), channels.SIMULATOR, snapshot))
        return items

    def _write_topic(self, log_ns, topic, msg_type, message):
        if self._encoder is not None and msg_type not in self._unencodable:
            try:
                definition, data = self._encoder(msg_type, message)
            except Exception as error:
                log.info("recording %s as JSON: %s cannot be encoded (%s)", topic, msg_type, error)
                self._unencodable.add(msg_type)
            else:
                encoder = self._encoder
                self._file.write_ros(topic, (encoder.message_encoding, encoder.schema_encoding),
                                     encoder.schema_name(msg_type), definition, log_ns, data)
                return
        if isinstance(message, dict):
            self._file.write_json(topic, msg_type, {"type": "object"}, log_ns, message)
