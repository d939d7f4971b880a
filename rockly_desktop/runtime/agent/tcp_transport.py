"""The agent's TCP transport: JSON lines (``agent.protocol``) on one connection per client, inside TLS 1.3
(``agent.tls``).

The agent's first line on a connection is its greeting ``{"nonce": HEX}``, new for each connection: a paired
client's ``hello`` proves its key over it (``pairings.hello_data``). A client that speaks plain JSON (a Rockly
from before pairing, protocol format 1) is answered, in plain JSON, that it must be updated and paired, and closed.

``AgentServer`` offers an ``Agent`` on a TCP port (the agent's side); ``TcpLine`` is a client's connection to
it (``AgentClient``'s side). A connection that closes is a client gone, and so is one that takes nothing the
agent sends for ``SEND_SECONDS`` or falls ``OUTBOX_BYTES`` behind, one that sends a line longer than
``MAX_LINE_BYTES`` or too slowly (``LineReader``), and one more than the server holds (``AgentServer``).
"""
import collections
import hmac
import secrets
import select
import socket
import socketserver
import ssl
import threading
import time

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.runtime.agent.protocol import (
    MAX_LINE_BYTES,
    AgentError,
    AgentRefusal,
    client_before_pairing,
    decode,
    encode,
    refusal_text,
)
from rockly_desktop.runtime.agent.tls import TLS_HANDSHAKE, LockedTls, client_context, fingerprint, short_fingerprint


class TcpLine:
    """A client's TLS connection to the agent at ``host``:``port``: ``take(message)`` gets every message the agent
    sends (on the reader thread, in order); ``gone()`` is called once when the connection has ended. ``pinned``:
    the fingerprint of the agent's certificate this laptop paired with (None: not paired; any is taken and said
    in ``fingerprint``); another one is refused before a byte of the client's is sent. ``nonce``: the agent's
    greeting, for the hello's proof."""

    beats_always = False  # the agent hears a closed connection; heartbeats only say the editor is there

    def __init__(self, host: str, port: int, language: str, timeout: float, take, gone, pinned: str = None):
        self.where = f"{host}:{port}"  # what a window names
        try:
            raw = socket.create_connection((host, port), timeout)
        except OSError as error:
            raise AgentError("agent_unreachable", app_text("agent_unreachable", language, host=host, port=port,
                                                           reason=error.strerror or str(error))) from None
        raw.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        no_answer = AgentError("agent_no_answer", app_text("agent_no_answer", language, where=self.where,
                                                          seconds=f"{timeout:g}"))
        try:
            self._socket = client_context().wrap_socket(raw)  # the handshake, within ``timeout``
        except socket.timeout:
            raw.close()
            raise no_answer from None
        except OSError as error:
            raw.close()
            raise AgentError("agent_no_tls", app_text("agent_no_tls", language, host=host, port=port,
                                                      reason=getattr(error, "reason", None) or str(error))) from None
        self.fingerprint = fingerprint(self._socket.getpeercert(binary_form=True))
        if pinned and not hmac.compare_digest(pinned, self.fingerprint):
            self._socket.close()
            raise AgentError("agent_other_certificate", app_text(
                "agent_other_certificate", language, where=self.where, seen=short_fingerprint(self.fingerprint),
                paired=short_fingerprint(pinned)))
        self._tls = LockedTls(self._socket)
        self._rest = b""  # read, not yet a whole line
        try:
            greeting = decode(self._next_line(timeout) or b"") or {}
        except socket.timeout:
            self._socket.close()
            raise no_answer from None
        except OSError:
            greeting = {}
        self.nonce = greeting.get("nonce")
        if not isinstance(self.nonce, str):
            self._socket.close()
            raise AgentError("agent_no_tls", app_text("agent_no_tls", language, host=host, port=port,
                                                      reason="no greeting"))
        self._send_lock = threading.Lock()
        self._take, self._gone = take, gone
        self._reader = threading.Thread(target=self._read, daemon=True, name="agent-client")
        self._reader.start()

    def write(self, message: dict) -> bool:
        """Send ``message``; False when the connection is gone."""
        try:
            with self._send_lock:  # two threads' messages never interleave
                self._tls.sendall(encode(message))
            return True
        except OSError:
            return False

    def lose(self):
        """End the connection as lost (the agent fell silent): ``gone`` follows on the reader thread."""
        try:
            self._tls.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass

    def close(self):
        """End the connection (``gone`` follows on the reader thread) and wait for the reader."""
        self.lose()
        self._reader.join(5)
        self._tls.close()

    def _next_line(self, timeout: float = None):
        """The agent's next line (None: the connection has ended)."""
        while b"\n" not in self._rest:
            data = self._tls.recv(1 << 16, timeout)
            if not data:
                return None
            self._rest += data
        line, self._rest = self._rest.split(b"\n", 1)
        return line

    def _read(self):
        try:
            while (line := self._next_line()) is not None:
                message = decode(line)
                if message is not None:
                    self._take(message)
        except (OSError, ValueError):
            pass
        self._gone()


# What the agent sends a client waits in the client's own outbox, written by a thread of its own: the run's
# events, the beats to the other clients and the program itself (whose events would back up) never wait for a
# client's network. A client is dropped, its connection shut, when its connection takes none of it for
# SEND_SECONDS (a laptop gone to sleep, a cut network: TCP closes nothing) or when it falls OUTBOX_BYTES behind.
SEND_SECONDS = 2.0
OUTBOX_BYTES = 16 * 1024 * 1024
LINGER_SECONDS = 2.0  # for a refused client to take its refusal (and stop sending) before its connection closes


class _Client:
    """One connected client: its socket, language, whether it watches the run, and its outbox."""

    def __init__(self, connection):
        self.connection = connection
        self.language = "en"
        self.name = "?"
        self.attached = False
        self.wants_control = False
        self.paired = None  # its PairedClient, once its hello proved its key (or it paired)
        self.nonce = secrets.token_hex(16)  # what its hello proves the key over: new for every connection
        self._outbox = collections.deque()
        self._outbox_bytes = 0
        self._sending = False
        self._changed = threading.Condition()
        self._dropped = False
        self._writer = threading.Thread(target=self._write, name="rockly-agent-client-send", daemon=True)
        self._writer.start()

    def send(self, message: dict) -> bool:
        """Queue ``message`` for the client; False when it is gone or has been dropped (see ``OUTBOX_BYTES``)."""
        data = encode(message)
        with self._changed:
            if self._dropped:
                return False
            if self._outbox_bytes + len(data) > OUTBOX_BYTES:
                self._drop()
                return False
            self._outbox.append(data)
            self._outbox_bytes += len(data)
            self._changed.notify()
        return True

    deliver = send  # the run's events: each TCP client gets its own copy

    def cut(self):
        """End the connection (its client was revoked): its reader ends, and so its place among the clients."""
        with self._changed:
            self._drop()

    def close(self):
        """The client has gone: its writer ends (what it had not taken is dropped)."""
        with self._changed:
            self._drop()
        self._writer.join(SEND_SECONDS + 1)

    def refuse(self, message: dict):
        """Tell the client ``message`` and end the connection so that it is read: sent whole within
        ``LINGER_SECONDS``, the sending side shut, and what the client still sends read and dropped until it
        closes (or ``LINGER_SECONDS``), since a close with unread bytes resets the connection and the client
        would lose the message."""
        self.send(message)
        until = time.monotonic() + LINGER_SECONDS
        with self._changed:
            self._changed.wait_for(lambda: (not self._outbox and not self._sending) or self._dropped, LINGER_SECONDS)
        try:
            self.connection.shutdown(socket.SHUT_WR)
            poll = select.poll()
            poll.register(self.connection, select.POLLIN)
            while (left := until - time.monotonic()) > 0 and poll.poll(left * 1000):
                if self.connection.recv_available(1 << 16) == b"":
                    break
        except OSError:
            pass
        self.close()

    def _write(self):
        while True:
            with self._changed:
                while not self._outbox and not self._dropped:
                    self._changed.wait()
                if self._dropped:
                    return
                data = self._outbox.popleft()
                self._outbox_bytes -= len(data)
                self._sending = True
            try:
                self.connection.sendall(data, SEND_SECONDS)
            except OSError:  # closed, or SEND_SECONDS without taking a byte: a line cut mid-message is no line
                with self._changed:
                    self._drop()
                return
            with self._changed:
                self._sending = False
                self._changed.notify_all()  # a refusal waiting to be sent whole

    def _drop(self):
        """(with ``_changed`` held) Stop sending and shut the connection, which ends its reader and so its place
        among the agent's clients."""
        if self._dropped:
            return
        self._dropped = True
        self._outbox.clear()
        self._outbox_bytes = 0
        self._changed.notify_all()
        try:
            self.connection.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass


# What a connection may hold of the agent: a connection cap in all and per address (each connection costs two
# threads and a descriptor, and 1,100 idle ones once locked out every client, STOP included); a first line within
# FIRST_LINE_SECONDS; and a line once begun must go on (no gap over GAP_SECONDS) and end within LINE_SECONDS plus a
# second per LINE_BYTES_A_SECOND it holds (a slowloris sends a byte now and then and never ends it).
MAX_CONNECTIONS = 64
MAX_CONNECTIONS_PER_ADDRESS = 16
FIRST_LINE_SECONDS = 10.0
GAP_SECONDS = 10.0
LINE_SECONDS = 10.0
LINE_BYTES_A_SECOND = 32 * 1024


class LineRefused(Exception):
    """A connection's line the agent will not wait for or hold: ``key`` names the catalogue text."""

    def __init__(self, key: str):
        super().__init__(key)
        self.key = key


class LineReader:
    """The lines a connection sends, within the bounds above; ``next_line()`` is the next one (None: closed)."""

    def __init__(self, connection):
        self._connection = connection
        self._poll = select.poll()
        self._poll.register(connection, select.POLLIN)
        self._buffer = bytearray()
        self._scanned = 0  # bytes of the buffer known to hold no line end
        self._opened = time.monotonic()
        self._lines = 0

    def next_line(self):
        """The next line (with its ``\n``), or None when the connection has closed; LineRefused past a bound."""
        begun = time.monotonic() if self._buffer else None
        while True:
            end = self._buffer.find(b"\n", self._scanned)
            if end >= 0:
                line = bytes(self._buffer[:end + 1])
                del self._buffer[:end + 1]
                self._scanned, self._lines = 0, self._lines + 1
                return line
            self._scanned = len(self._buffer)
            if len(self._buffer) > MAX_LINE_BYTES:
                raise LineRefused("agent_line_too_long")
            if begun is None and self._buffer:
                begun = time.monotonic()
            wait = self._wait(begun)
            if wait is not None and wait <= 0 or not self._connection.pending() and not self._poll.poll(
                    None if wait is None else wait * 1000):
                raise LineRefused("agent_line_too_slow")
            data = self._connection.recv_available(1 << 16)
            if data == b"":
                return None
            self._buffer += data or b""

    def _wait(self, begun):
        """Seconds to wait for more (None: as long as it takes: a client between requests)."""
        now = time.monotonic()
        if self._lines == 0:
            return self._opened + FIRST_LINE_SECONDS - now
        if begun is None:
            return None
        return min(GAP_SECONDS, begun + LINE_SECONDS + len(self._buffer) / LINE_BYTES_A_SECOND - now)


def serve_connection(agent, connection):
    """Read and answer ``connection``'s requests to ``agent`` until it closes (or breaks a bound: it is told why
    and closed)."""
    client = _Client(connection)
    client.send({"nonce": client.nonce})
    agent.join(client)
    lines = LineReader(connection)
    refusal = None
    try:
        while True:
            try:
                line = lines.next_line()
            except LineRefused as refused:
                refusal = {"reply": None, "ok": False, "error": refused.key,
                           "message": refusal_text(AgentRefusal(refused.key, megabytes=MAX_LINE_BYTES // 2**20),
                                                   client.language)}
                break
            if not line:
                break
            request = decode(line)
            if request is None:
                client.send({"reply": None, "ok": False, "error": "agent_bad_request",
                             "message": refusal_text(AgentRefusal("agent_bad_request"), client.language)})
                continue
            answer = agent.answer(client, request)
            if answer is not None:
                client.send(answer)
    except OSError:
        pass
    finally:
        agent.leave(client)
        if refusal is not None:
            client.refuse(refusal)
        else:
            client.close()


class AgentServer(socketserver.ThreadingTCPServer):
    """The agent's TCP server on ``(host, port)`` with TLS ``context`` (``tls.server_context``), holding at most
    ``MAX_CONNECTIONS`` connections (``MAX_CONNECTIONS_PER_ADDRESS`` from one address); one more is told so and
    closed at once."""

    daemon_threads = True
    allow_reuse_address = True

    def __init__(self, agent, host: str, port: int, context: ssl.SSLContext):
        self.agent = agent
        self.context = context
        self._open = {}  # accepted connection -> its address
        self._open_lock = threading.Lock()
        super().__init__((host, port), _Handler)

    def verify_request(self, request, client_address):
        address = client_address[0]
        with self._open_lock:
            if len(self._open) < MAX_CONNECTIONS and (
                    sum(held == address for held in self._open.values()) < MAX_CONNECTIONS_PER_ADDRESS):
                self._open[request] = address
                return True
        try:  # said without waiting: a connection that reads nothing gets nothing
            request.setblocking(False)
            request.send(encode({"reply": None, "ok": False, "error": "agent_too_many_connections",
                                 "message": app_text("agent_too_many_connections", "en")}))
        except OSError:
            pass
        return False

    def shutdown_request(self, request):
        with self._open_lock:
            self._open.pop(request, None)
        super().shutdown_request(request)


    def secured(self, connection):
        """``connection`` inside TLS (a ``LockedTls``), its handshake done within ``FIRST_LINE_SECONDS``; None when
        it is not TLS (a plain JSON client is told to update and pair) or its handshake fails."""
        connection.settimeout(FIRST_LINE_SECONDS)
        try:
            first = connection.recv(1, socket.MSG_PEEK)
            if first and first[0] != TLS_HANDSHAKE:
                _refuse_plain(connection)
                return None
            secured = self.context.wrap_socket(connection, server_side=True) if first else None
        except OSError:  # ssl.SSLError too: not TLS 1.3, a broken handshake, the time up
            return None
        if secured is None:
            return None
        secured.settimeout(None)
        return LockedTls(secured)


def _refuse_plain(connection):
    """Tell a client speaking plain JSON (a Rockly from before pairing) to update and pair, answering its first request
    (its hello: so the client shows the message at once) in the language it names, and end the connection."""
    data = b""
    until = time.monotonic() + LINGER_SECONDS
    while b"\n" not in data and len(data) < 65536 and time.monotonic() < until:
        connection.settimeout(max(0.01, until - time.monotonic()))
        chunk = connection.recv(4096)
        if not chunk:
            break
        data += chunk
    request = decode(data.split(b"\n", 1)[0]) or {}
    language = request.get("language") if request.get("language") in ("en", "de") else "en"
    connection.settimeout(LINGER_SECONDS)
    refusal = client_before_pairing(request.get("rockly", "?"))
    connection.sendall(encode({"reply": request.get("id"), "ok": False, "error": refusal.key,
                               "message": refusal_text(refusal, language)}))
    connection.shutdown(socket.SHUT_WR)
    while time.monotonic() < until and connection.recv(4096):
        pass


class _Handler(socketserver.BaseRequestHandler):
    def handle(self):
        self.request.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        secured = self.server.secured(self.request)
        if secured is None:
            return
        try:
            serve_connection(self.server.agent, secured)
        finally:
            secured.close()
