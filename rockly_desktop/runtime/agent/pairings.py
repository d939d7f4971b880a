"""Who may use the agent: the laptops paired with it, and the one-time codes that pair them.

A laptop pairs once, with a code the robot shows (``rockly agent pair``, a teacher's window, the robot's own UI):
six signs of ``CODE_ALPHABET`` (30 bits), valid ``CODE_SECONDS``, good for one pairing. Guesses are capped:
``WRONG_GUESSES_PER_CODE`` wrong guesses while a code is open end that code, and after ``WRONG_GUESSES_PER_MINUTE``
wrong guesses in a minute no code is taken for the rest of that minute. So a stranger has at most 5 guesses
among 2**30 codes per code made: about one chance in 200 million.

The agent's folder (``agent_folder(library)``) holds, each mode 0600 and written whole or not at all:

    pairings.json        the paired laptops: id, name, role, key (base64), when
    pairing-codes/*.json codes waiting to be taken: made by ``rockly agent pair`` (another process: the agent,
                         running as a service, picks them up at the next ``pair``) or by the agent itself
    pairings.lock        held while pairings.json is read and rewritten (the agent pairs, ``rockly agent revoke``
                         revokes: neither loses the other's change)

Whoever may write that folder is the agent's own user (or root): the folder is the trust anchor, as an ssh
server's host key and authorized_keys are.

A paired laptop proves it holds its key with ``proof_of_key(key, data)`` (HMAC-SHA256) over data the agent chose
(over TCP a nonce per connection, ``hello_data``); ``Pairings.verify`` checks it in constant time.
"""
import base64
import binascii
import collections
import hashlib
import hmac
import json
import os
import secrets
import threading
import time
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Optional

from rockly_desktop.runtime.agent.private_files import held as lock_held
from rockly_desktop.runtime.agent.private_files import private_folder, read_json, write_private_json
from rockly_desktop.runtime.agent.protocol import AgentRefusal

TEACHER, STUDENT = "teacher", "student"
ROLES = (TEACHER, STUDENT)
CODE_ALPHABET = "23456789ABCDEFGHJKLMNPQRSTUVWXYZ"  # 32 signs: no 0 and O, no 1 and I to mistake for each other
CODE_LENGTH = 6  # 6 signs of 32: 30 bits
CODE_SECONDS = 120.0
WRONG_GUESSES_PER_CODE = 5
WRONG_GUESSES_PER_MINUTE = 10
KEEP_SPENT_CODES_SECONDS = 600.0  # a used, expired or guessed-at code is remembered this long: said as such
PAIRINGS, CODES, LOCK = "pairings.json", "pairing-codes", "pairings.lock"


def agent_folder(library: Path) -> Path:
    """The agent's own folder (pairings, codes, its TLS key and certificate) beside its programs: inside the
    library (the one folder the agent's service may write), hidden (no program's name starts with a dot)."""
    return Path(library) / ".agent"


@dataclass(frozen=True)
class PairedClient:
    """A laptop paired with the agent."""

    id: str  # random (``secrets.token_hex(8)``)
    name: str  # the laptop's ``user@host``, or a name the person gave
    role: str  # TEACHER or STUDENT
    key: bytes = field(repr=False)  # 32 random bytes, known to the agent and that laptop only
    paired_at: str  # ISO time


@dataclass(frozen=True)
class PairingCode:
    """A one-time code: ``code`` (as typed, see ``shown``), valid until ``expires`` (``time.monotonic``, which is
    the same clock in every process of the machine), pairing a laptop as ``role``."""

    code: str
    expires: float
    role: str

    @property
    def shown(self) -> str:
        """The code as shown to people: ``K7Q-M2X``."""
        return shown_code(self.code)


def shown_code(code: str) -> str:
    """``code`` in two halves, easier to read out and type."""
    return code[:len(code) // 2] + "-" + code[len(code) // 2:]


def typed_code(text: str) -> str:
    """What a person typed as a code, as codes are kept: upper case, without spaces and dashes."""
    return "".join(sign for sign in text.upper() if sign not in " -")


def proof_of_key(key: bytes, data: bytes) -> str:
    """The proof that whoever sends ``data`` holds ``key``: its HMAC-SHA256, as hex."""
    return hmac.new(key, data, hashlib.sha256).hexdigest()


def hello_data(nonce: str, client_id: str) -> bytes:
    """What a TCP client proves its key over in its ``hello``: the nonce the agent sent that connection, and the
    client's id."""
    return b"rockly-hello\n" + nonce.encode("ascii") + b"\n" + client_id.encode("utf-8")


def message_data(message: dict) -> bytes:
    """What a ROS message's ``proof`` is over: the whole message but its proof, as canonical JSON (the agent
    decodes and encodes it again: keys sorted, no spaces, ASCII)."""
    return json.dumps({key: value for key, value in message.items() if key != "proof"}, sort_keys=True,
                      separators=(",", ":"), ensure_ascii=True).encode("ascii")


class _OpenCode:
    """A code the agent holds: ``wrong`` guesses made while it was open; ``state``: open, used or guessed."""

    def __init__(self, code: PairingCode):
        self.code = code
        self.wrong = 0
        self.state = "open"


class Pairings:
    """The agent's paired clients and codes, in ``folder`` (see above); ``clock``: ``time.monotonic``, or a test's."""

    def __init__(self, folder: Path, clock=time.monotonic):
        self.folder = Path(folder)
        self._clock = clock
        self._codes = {}  # code -> _OpenCode
        self._wrong = collections.deque()  # when each wrong guess of the last minute came
        self._lock = threading.Lock()
        self._known = (None, {})  # (pairings.json's stat, clients by id) as last read

    # -- codes

    def new_code(self, role: str = None) -> PairingCode:
        """A new one-time code pairing a laptop as ``role``: the one given, else a teacher while no teacher is
        paired (a fresh agent), else a student. Works in any process that may write the agent's folder."""
        if role is None:
            role = STUDENT if any(client.role == TEACHER for client in self.clients()) else TEACHER
        if role not in ROLES:
            raise ValueError(role)
        code = PairingCode("".join(secrets.choice(CODE_ALPHABET) for _ in range(CODE_LENGTH)),
                           self._clock() + CODE_SECONDS, role)
        private_folder(self.folder)
        write_private_json(self.folder / CODES / (secrets.token_hex(8) + ".json"),
                           {"code": code.code, "expires": code.expires, "role": code.role, "made": time.time()})
        return code

    def pair(self, code, name, role: str = None) -> PairedClient:
        """Pair a laptop called ``name`` with ``code`` (as typed), in the code's role, or as a student when it asks
        for that (``role``: a kiosk asks for less than a teacher's code gives, never more); AgentRefusal when the
        code is not one the agent gave, was used, has expired, or guessing has gone on too long."""
        typed = typed_code(code) if isinstance(code, str) else ""
        with self._lock:
            self._take_new_codes()
            now = self._clock()
            self._forget_old(now)
            if len(self._wrong) >= WRONG_GUESSES_PER_MINUTE:
                raise AgentRefusal("agent_pair_too_many_guesses")
            held = next((held for known, held in self._codes.items()
                         if hmac.compare_digest(known.encode(), typed.encode("utf-8"))), None)
            if held is None:
                self._guessed_wrong(now)
                raise AgentRefusal("agent_pair_wrong_code")
            if held.state == "guessed":
                raise AgentRefusal("agent_pair_too_many_guesses")
            if held.state == "used":
                raise AgentRefusal("agent_pair_code_used")
            if now > held.code.expires:
                raise AgentRefusal("agent_pair_code_expired")
            held.state = "used"
            granted = STUDENT if role == STUDENT else held.code.role
            client = PairedClient(secrets.token_hex(8), _plain_name(name), granted, secrets.token_bytes(32),
                                  datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"))
            self._change(lambda clients: clients + [client])
            return client

    def _guessed_wrong(self, now: float):
        self._wrong.append(now)
        for held in self._codes.values():
            if held.state == "open" and now <= held.code.expires:
                held.wrong += 1
                if held.wrong >= WRONG_GUESSES_PER_CODE:
                    held.state = "guessed"

    def _forget_old(self, now: float):
        while self._wrong and self._wrong[0] < now - 60:
            self._wrong.popleft()
        for known, held in list(self._codes.items()):
            if now > held.code.expires + KEEP_SPENT_CODES_SECONDS:
                del self._codes[known]

    def _take_new_codes(self):
        """Move the codes written into the folder (by this process or ``rockly agent pair``) into memory."""
        try:
            waiting = sorted((self.folder / CODES).glob("*.json"))
        except OSError:
            return
        for path in waiting:
            if path.name.startswith("."):  # one being written
                continue
            try:
                data = read_json(path, None)
                os.unlink(str(path))
            except (OSError, ValueError):
                continue
            try:
                code = PairingCode(str(data["code"]), float(data["expires"]), str(data["role"]))
                if not 0 <= time.time() - float(data["made"]) <= CODE_SECONDS:  # made before the computer started
                    code = PairingCode(code.code, min(code.expires, self._clock() - 1), code.role)
            except (TypeError, KeyError, ValueError):
                continue
            if code.role in ROLES and code.code not in self._codes:
                self._codes[code.code] = _OpenCode(code)

    # -- paired clients

    def find(self, client_id) -> Optional[PairedClient]:
        """The paired client of ``client_id``; None when there is none (never paired, or revoked)."""
        if not isinstance(client_id, str):
            return None
        return self._read().get(client_id)

    def clients(self) -> list:
        """The paired clients, the first paired first."""
        return sorted(self._read().values(), key=lambda client: client.paired_at)

    def revoke(self, name_or_id: str) -> bool:
        """Forget the clients of that name or id (their keys no longer work, an open connection of theirs is
        closed by the running agent); False when there was none."""
        revoked = []

        def without(clients):
            kept = [client for client in clients if name_or_id not in (client.id, client.name)]
            revoked.extend(client for client in clients if client not in kept)
            return kept
        self._change(without)
        return bool(revoked)

    def verify(self, client_id, given_proof, data: bytes) -> Optional[PairedClient]:
        """The paired client ``client_id`` when ``given_proof`` is its ``proof_of_key`` of ``data``; else None."""
        client = self.find(client_id)
        if client is None or not isinstance(given_proof, str):
            return None
        return client if hmac.compare_digest(proof_of_key(client.key, data).encode(), given_proof.encode("utf-8",
                                                                                                  "replace")) else None

    def version(self):
        """Changes whenever the paired clients change (on disk): for a watch that closes revoked clients."""
        return _stat_of(self.folder / PAIRINGS)

    def _read(self) -> dict:
        path = self.folder / PAIRINGS
        seen = _stat_of(path)
        if seen == self._known[0]:
            return self._known[1]
        try:
            clients = {client.id: client for client in _clients_of(read_json(path, {}))}
        except (OSError, ValueError):
            clients = {}  # a pairings file that cannot be read pairs nobody
        self._known = (seen, clients)
        return clients

    def _change(self, change):
        """Rewrite pairings.json with ``change(clients)``, holding its lock against another process's change."""
        with lock_held(private_folder(self.folder) / LOCK):
            clients = list(_clients_of(read_json(self.folder / PAIRINGS, {})))
            write_private_json(self.folder / PAIRINGS, {"clients": [_stored(client) for client in change(clients)]})


def _stat_of(path: Path):
    try:
        found = os.stat(str(path))
    except OSError:
        return None
    return found.st_ino, found.st_mtime_ns, found.st_size


def _stored(client: PairedClient) -> dict:
    return {"id": client.id, "name": client.name, "role": client.role,
            "key": base64.b64encode(client.key).decode("ascii"), "paired_at": client.paired_at}


def _clients_of(data) -> list:
    found = []
    for entry in data.get("clients", []) if isinstance(data, dict) else []:
        try:
            client = PairedClient(str(entry["id"]), str(entry["name"]), str(entry["role"]),
                                  base64.b64decode(entry["key"], validate=True), str(entry["paired_at"]))
        except (TypeError, KeyError, ValueError, binascii.Error):
            continue
        if client.role in ROLES and len(client.key) >= 16:
            found.append(client)
    return found


def _plain_name(name) -> str:
    """A laptop's name as the agent keeps and shows it: printable, at most 80 signs."""
    text = "".join(sign for sign in str(name if name is not None else "?") if sign.isprintable())
    return text.strip()[:80] or "?"
