"""The agent's TCP transport: JSON lines (``agent.protocol``) on one connection per client.

``AgentServer`` offers an ``Agent`` on a TCP port (the agent's side); ``TcpLine`` is a client's connection to
it (``AgentClient``'s side). A connection that closes is a client gone, and so is one that takes nothing the
agent sends for ``SEND_SECONDS``.
"""
import socket
import socketserver
import struct
import threading

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.runtime.agent.protocol import (
    MAX_LINE_BYTES,
    AgentError,
    AgentRefusal,
    decode,
    encode,
    refusal_text,
)


class TcpLine:
    """A client's connection to the agent at ``host``:``port``: ``take(message)`` gets every message the agent
    sends (on the reader thread, in order); ``gone()`` is called once when the connection has ended."""

    beats_always = False  # the agent hears a closed connection; heartbeats only say the editor is there

    def __init__(self, host: str, port: int, language: str, timeout: float, take, gone):
        self.where = f"{host}:{port}"  # what a window names
        try:
            self._socket = socket.create_connection((host, port), timeout)
        except OSError as error:
            raise AgentError("agent_unreachable", app_text("agent_unreachable", language, host=host, port=port,
                                                           reason=error.strerror or str(error))) from None
        self._socket.settimeout(None)
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._send_lock = threading.Lock()
        self._take, self._gone = take, gone
        self._reader = threading.Thread(target=self._read, daemon=True, name="agent-client")
        self._reader.start()

    def write(self, message: dict) -> bool:
        """Send ``message``; False when the connection is gone."""
        try:
            with self._send_lock:
                self._socket.sendall(encode(message))
            return True
        except OSError:
            return False

    def lose(self):
        """End the connection as lost (the agent fell silent): ``gone`` follows on the reader thread."""
        try:
            self._socket.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass

    def close(self):
        """End the connection (``gone`` follows on the reader thread) and wait for the reader."""
        self.lose()
        self._socket.close()
        self._reader.join(5)

    def _read(self):
        try:
            for line in self._socket.makefile("rb"):
                message = decode(line)
                if message is not None:
                    self._take(message)
        except (OSError, ValueError):
            pass
        self._gone()


# A client whose connection takes none of what the agent sends for this long (a laptop gone to sleep, a cut
# network: TCP closes nothing) is dropped: the run's events and the agent's beats to every other client wait
# for each send, and the program itself waits once its events back up.
SEND_SECONDS = 2.0


class _Client:
    """One connected client: its socket, language, and whether it watches the run."""

    def __init__(self, connection):
        self.connection = connection
        self.language = "en"
        self.name = "?"
        self.attached = False
        self.wants_control = False
        self._lock = threading.Lock()
        self._dropped = False
        whole, part = divmod(SEND_SECONDS, 1)
        connection.setsockopt(socket.SOL_SOCKET, socket.SO_SNDTIMEO, struct.pack("ll", int(whole), int(part * 1e6)))

    def send(self, message: dict) -> bool:
        """Send ``message``; False when the client is gone or has been dropped for taking nothing (its connection
        is then shut, which ends its reader and so its place among the agent's clients)."""
        with self._lock:
            if self._dropped:
                return False
            try:
                self.connection.sendall(encode(message))
                return True
            except OSError:  # closed, or SEND_SECONDS without taking a byte: a line cut mid-message is no line
                self._dropped = True
                try:
                    self.connection.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass
                return False

    deliver = send  # the run's events: each TCP client gets its own copy


def serve_connection(agent, connection):
    """Read and answer ``connection``'s requests to ``agent`` until it closes."""
    client = _Client(connection)
    agent.join(client)
    reader = connection.makefile("rb")
    try:
        while True:
            line = reader.readline(MAX_LINE_BYTES + 1)
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


class AgentServer(socketserver.ThreadingTCPServer):
    """The agent's TCP server on ``(host, port)``."""

    daemon_threads = True
    allow_reuse_address = True

    def __init__(self, agent, host: str, port: int):
        self.agent = agent
        super().__init__((host, port), _Handler)


class _Handler(socketserver.BaseRequestHandler):
    def handle(self):
        self.request.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        serve_connection(self.server.agent, self.request)
