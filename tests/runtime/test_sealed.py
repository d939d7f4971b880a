"""Sealing one message of the agent's ROS topics (``agent.sealed``): a box opens only with its key and for what it
was bound to, a changed box does not open, counters refuse a recording, and both sides of a pairing agree on a key
that a listener cannot work out."""
import base64
import secrets

import pytest

from rockly_desktop.runtime.agent import sealed
from rockly_desktop.runtime.agent.sealed import (
    FROM_AGENT,
    TO_AGENT,
    Binding,
    LineCounter,
    PairingExchange,
    Replays,
    Unsealable,
    seal,
    unseal,
)

KEY = bytes(range(32))
BOUND = ("/rockly_agent", TO_AGENT, "c0ffee", "line1", "session1")


def test_a_sealed_message_opens_with_its_key_and_binding():
    box = seal(KEY, Binding(*BOUND), 7, {"op": "start", "name": "demo"})
    assert unseal(KEY, Binding(*BOUND), box) == (7, {"op": "start", "name": "demo"})
    assert "demo" not in base64.b64decode(box).decode("latin-1")  # nothing of it is readable


def test_each_box_has_its_own_nonce():
    first, second = (seal(KEY, Binding(*BOUND), 1, {"op": "stop"}) for _ in range(2))
    assert first != second and base64.b64decode(first)[:12] != base64.b64decode(second)[:12]


@pytest.mark.parametrize("place", range(len(BOUND)))
def test_a_box_does_not_open_for_anything_else_it_could_be_moved_to(place):
    box = seal(KEY, Binding(*BOUND), 1, {"op": "stop"})
    other = list(BOUND)
    other[place] = FROM_AGENT if place == 1 else other[place] + "x"
    with pytest.raises(Unsealable):
        unseal(KEY, Binding(*other), box)


def test_a_box_with_another_key_or_a_changed_byte_does_not_open():
    box = seal(KEY, Binding(*BOUND), 1, {"op": "stop"})
    with pytest.raises(Unsealable):
        unseal(secrets.token_bytes(32), Binding(*BOUND), box)
    raw = bytearray(base64.b64decode(box))
    raw[20] ^= 1
    with pytest.raises(Unsealable):
        unseal(KEY, Binding(*BOUND), base64.b64encode(bytes(raw)).decode())


@pytest.mark.parametrize("box", ["", "not base64!", base64.b64encode(b"short").decode(), None, 5, ["x"]])
def test_what_is_not_a_box_does_not_open(box):
    with pytest.raises(Unsealable):
        unseal(KEY, Binding(*BOUND), box)


def test_a_lines_counters_rise_and_a_counter_heard_again_is_refused(monkeypatch):
    now = [1_000_000]
    monkeypatch.setattr(sealed, "time_counter", lambda: now[0])
    counter = LineCounter()
    sent = [counter.next() for _ in range(1000)]  # faster than the clock: still rising
    assert sent == list(range(1_000_000, 1_001_000))
    now[0] = 2_000_000  # the client started again a second later
    assert LineCounter().next() == 2_000_000 and counter.next() == 2_000_000  # both go on above
    assert counter.heard(5) and counter.heard(9) and not counter.heard(9) and not counter.heard(6)


class Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_the_agent_refuses_a_counter_not_above_the_lines_last():
    replays = Replays(clock=Clock())
    assert replays.fresh("c", "l1", 10) and replays.fresh("c", "l1", 11)
    assert not replays.fresh("c", "l1", 11) and not replays.fresh("c", "l1", 3)
    assert replays.fresh("c", "l2", 5)  # another line of the same client (another window) has its own counters
    assert replays.fresh("d", "l1", 1)  # and so has another client


def test_an_ended_line_is_not_taken_again_and_a_new_line_must_start_above_the_old_ones():
    clock = Clock()
    replays = Replays(keep_seconds=600, clock=clock)
    assert replays.fresh("c", "old", 1000)
    replays.ended("c", "old")
    assert not replays.fresh("c", "old", 1000)  # a recording of the line, just ended
    assert replays.fresh("c", "old", 1001)  # the line itself, back after a gap, goes on
    replays.ended("c", "old")
    clock.now += 601  # forgotten: only the client's highest counter is kept
    assert not replays.fresh("c", "old", 1001)
    assert not replays.fresh("c", "recorded", 999)  # a line of its own from before: below the old ones
    assert replays.fresh("c", "new", 2000)  # a new line starts at the time: above


def test_both_sides_of_a_pairing_agree_on_a_key_a_listener_cannot_have():
    agent, client = PairingExchange(), PairingExchange()
    key = client.key_with(agent.public_text, client_side=True)
    assert key == agent.key_with(client.public_text, client_side=False) and len(key) == 32
    listener = PairingExchange()  # knows both public keys, not a private one
    assert listener.key_with(agent.public_text, client_side=True) != key
    assert listener.key_with(client.public_text, client_side=False) != key


@pytest.mark.parametrize("public", [None, "", "!!", base64.b64encode(b"x" * 31).decode(), 3])
def test_a_pairing_with_no_public_key_does_not_go(public):
    with pytest.raises(Unsealable):
        PairingExchange().key_with(public, client_side=False)
