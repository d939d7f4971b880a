"""The agent's wire protocol spoken directly, as a hostile or a hand-made client would: a TLS connection (the
agent's greeting read), a hello proving a key or not, requests and the agent's answers."""
import json
import socket

from rockly_desktop.runtime.agent.pairings import hello_data, proof_of_key
from rockly_desktop.runtime.agent.protocol import FORMAT
from rockly_desktop.runtime.agent.tls import client_context


def plain_connection(port: int, source_address: str = "127.0.0.1", timeout: float = 60,
                     receive_buffer: int = None) -> socket.socket:
    """A plain TCP connection to the agent on 127.0.0.1 from ``source_address`` (with a kernel receive buffer of
    ``receive_buffer`` bytes where given: a client that takes little is soon full)."""
    connection = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    if receive_buffer is not None:
        connection.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, receive_buffer)
    connection.bind((source_address, 0))
    connection.connect(("127.0.0.1", port))
    connection.settimeout(timeout)
    return connection


def tls_connection(port: int, source_address: str = "127.0.0.1", timeout: float = 60,
                   receive_buffer: int = None) -> tuple:
    """``(connection, nonce)``: a TLS connection to the agent (any certificate taken) and the nonce of its
    greeting, read to its line's end and no further."""
    connection = client_context().wrap_socket(plain_connection(port, source_address, timeout, receive_buffer))
    line = b""
    while not line.endswith(b"\n"):
        byte = connection.recv(1)
        assert byte, f"the agent closed the connection before its greeting ended: {line!r}"
        line += byte
    return connection, json.loads(line)["nonce"]


def hello(nonce: str = None, key=None, language: str = "en", **fields) -> dict:
    """A hello request; with a RobotKey ``key``, proving it over ``nonce``."""
    request = {"op": "hello", "id": 0, "format": FORMAT, "language": language, "client": "stranger", **fields}
    if key is not None:
        request.update(client_id=key.client, proof=proof_of_key(key.key, hello_data(nonce, key.client)))
    return request


def say(connection, message):
    """Send ``message`` (a dict as a JSON line, or bytes as they are)."""
    connection.sendall((json.dumps(message) + "\n").encode() if isinstance(message, dict) else message)


def answers(connection, count: int) -> list:
    """The next ``count`` messages but the alive beats; fewer when the agent closed the connection. Reads whole
    lines only up to the last one it returns (a beat after them may be read and dropped)."""
    found, buffer = [], b""
    while len(found) < count:
        data = connection.recv(1 << 16)
        if not data:
            break
        buffer += data
        *lines, buffer = buffer.split(b"\n")
        found += [message for message in map(json.loads, lines) if "alive" not in message]
    return found


def closed_by_agent(connection) -> bool:
    """True once the agent has closed ``connection`` (what it said before is read and dropped)."""
    try:
        while connection.recv(1 << 16):
            pass
    except OSError:
        pass
    return True
