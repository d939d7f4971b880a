"""One message of the agent's ROS topics sealed with a key, and opened again (docs/decisions/036).

A box is AES-256-GCM (``cryptography``'s ``AESGCM``) with a random 96-bit nonce per message. Its associated data
binds it to where it belongs (``Binding``: the namespace, the direction, the paired client, the client's line and
the agent's session), so a box cannot be moved to another client, line, direction or agent run. Inside is
``{"n": COUNTER, "m": MESSAGE}``; the counter rises strictly on each line and direction (``LineCounter``), and the
receiver refuses one that does not (``Replays`` on the agent, ``LineCounter.heard`` on a client): a recorded box
is not taken twice.

Pairing over ROS (``PairingExchange``) derives a one-time key from an X25519 exchange with the agent's session key
(HKDF-SHA256), so that a node that listens to the topics learns neither the code nor the pair's key.

    box = seal(key, binding, counter, message)
    counter, message = unseal(key, binding, box)        # Unsealable when it does not open

``cryptography`` (pinned) is imported when first used: the runtime's other parts, and a client that never speaks
over ROS, do without it (a robot's Python may lack it: ``RosOffer`` then says so, and TCP still serves).
"""
import base64
import binascii
import json
import secrets
import time

PURPOSE = "rockly-agent-ros/1"  # the associated data's first word: a box of another protocol never opens here
TO_AGENT, FROM_AGENT = "to_agent", "from_agent"
NONCE_BYTES = 12
KEY_BYTES = 32
ENDED_LINES_SECONDS = 600.0  # how long the agent keeps an ended line's counter (see Replays)


class Unsealable(ValueError):
    """A box that does not open: another key or binding, changed on the way, or not a box at all."""


class Binding:
    """What one box belongs to, bound into it as associated data: the agent's ``namespace``, the ``direction``
    (``TO_AGENT`` or ``FROM_AGENT``), the paired ``client``'s id, the client's ``line`` (one per connection) and
    the agent's ``session`` (one per run of the agent)."""

    def __init__(self, namespace: str, direction: str, client: str, line: str, session: str):
        self.associated = json.dumps([PURPOSE, namespace, direction, client, line, session]).encode("utf-8")


def seal(key: bytes, binding: Binding, counter: int, message: dict) -> str:
    """``message`` with its ``counter`` sealed with ``key`` for ``binding``: base64 text."""
    from cryptography.hazmat.primitives.ciphers.aead import AESGCM

    nonce = secrets.token_bytes(NONCE_BYTES)
    plain = json.dumps({"n": counter, "m": message}, ensure_ascii=False).encode("utf-8")
    return base64.b64encode(nonce + AESGCM(key).encrypt(nonce, plain, binding.associated)).decode("ascii")


def unseal(key: bytes, binding: Binding, box) -> tuple:
    """``(counter, message)`` of ``box`` sealed with ``key`` for ``binding``; Unsealable when it does not open."""
    from cryptography.exceptions import InvalidTag
    from cryptography.hazmat.primitives.ciphers.aead import AESGCM

    try:
        raw = base64.b64decode(box.encode("ascii"), validate=True)
        plain = AESGCM(key).decrypt(raw[:NONCE_BYTES], raw[NONCE_BYTES:], binding.associated)
        inside = json.loads(plain.decode("utf-8"))
    except (AttributeError, UnicodeError, binascii.Error, ValueError, InvalidTag, RecursionError):
        raise Unsealable() from None
    if not (isinstance(inside, dict) and isinstance(inside.get("n"), int) and isinstance(inside.get("m"), dict)):
        raise Unsealable()
    return inside["n"], inside["m"]


def time_counter() -> int:
    """Microseconds since 1970: a counter that a restarted client takes up above where it was."""
    return time.time_ns() // 1000


class LineCounter:
    """One line's counters: ``next()`` for what it sends (rising strictly, at least the time in microseconds,
    so a new line of a client starts above its old ones), ``heard(n)`` for what it receives (True when ``n``
    is above every counter heard before)."""

    def __init__(self):
        self._sent = 0
        self._heard = 0

    def next(self) -> int:
        self._sent = max(self._sent + 1, time_counter())
        return self._sent

    def heard(self, counter: int) -> bool:
        if counter <= self._heard:
            return False
        self._heard = counter
        return True


class Replays:
    """The agent's memory of the counters its clients' lines sent: a box on a line is taken only when its
    counter is above the line's last. A line that ended (``ended``) is remembered ``keep_seconds`` (a line that
    comes back after a gap goes on where it was); after that only the highest counter of a client's forgotten
    lines is kept, and a line the agent does not know must start above it. A client's counters are the time
    (``LineCounter``), so its new lines do; a recording of an old line does not. The agent's session, bound into
    every box, makes a box of an earlier run of the agent useless: the memory need not outlive the agent."""

    def __init__(self, keep_seconds: float = ENDED_LINES_SECONDS, clock=time.monotonic):
        self._last = {}  # (client, line) -> the last counter taken
        self._ended = {}  # (client, line) -> when it ended, oldest first
        self._floor = {}  # client -> the highest counter of its forgotten lines
        self._keep = keep_seconds
        self._clock = clock

    def fresh(self, client: str, line: str, counter: int) -> bool:
        """True (and remembered) when ``counter`` may be taken on ``client``'s ``line``; False for a replay."""
        self._forget_ended()
        last = self._last.get((client, line), self._floor.get(client, 0))
        if counter <= last:
            return False
        self._last[(client, line)] = counter
        self._ended.pop((client, line), None)
        return True

    def ended(self, client: str, line: str):
        """``client``'s ``line`` has ended (it said bye, or fell silent)."""
        if (client, line) in self._last:
            self._ended.pop((client, line), None)
            self._ended[(client, line)] = self._clock()

    def _forget_ended(self):
        too_old = self._clock() - self._keep
        while self._ended:
            line, when = next(iter(self._ended.items()))
            if when > too_old:
                return
            del self._ended[line]
            self._floor[line[0]] = max(self._floor.get(line[0], 0), self._last.pop(line))


class PairingExchange:
    """The one-time key of a pairing over ROS: X25519 between a client's fresh key and the agent's session key,
    then HKDF-SHA256 over the shared secret, bound to both public keys. Either side makes one with its own
    fresh private key and the other side's public key (``public_text`` gives its own, base64)."""

    def __init__(self):
        from cryptography.hazmat.primitives import serialization
        from cryptography.hazmat.primitives.asymmetric.x25519 import X25519PrivateKey

        self.private = X25519PrivateKey.generate()
        self.public_text = _text(self.private.public_key().public_bytes(serialization.Encoding.Raw,
                                                                        serialization.PublicFormat.Raw))

    def key_with(self, their_public_text, client_side: bool) -> bytes:
        """The shared one-time key with the side whose public key is ``their_public_text``; Unsealable when that
        is not an X25519 public key."""
        from cryptography.hazmat.primitives import hashes
        from cryptography.hazmat.primitives.asymmetric.x25519 import X25519PublicKey
        from cryptography.hazmat.primitives.kdf.hkdf import HKDF

        try:
            theirs = base64.b64decode(their_public_text.encode("ascii"), validate=True)
            shared = self.private.exchange(X25519PublicKey.from_public_bytes(theirs))
        except (AttributeError, UnicodeError, binascii.Error, ValueError):
            raise Unsealable() from None
        client, agent = (self.public_text, their_public_text) if client_side else (their_public_text,
                                                                                   self.public_text)
        info = json.dumps([PURPOSE, "pair", client, agent]).encode("utf-8")
        return HKDF(algorithm=hashes.SHA256(), length=KEY_BYTES, salt=None, info=info).derive(shared)


def new_session() -> str:
    """A random name for one run of the agent."""
    return secrets.token_hex(8)


def new_line() -> str:
    """A random name for one client's line."""
    return secrets.token_hex(8)


def _text(raw: bytes) -> str:
    return base64.b64encode(raw).decode("ascii")
