"""Moments of a recording: which block ran when."""
from rockly_desktop.recording import channels
from rockly_desktop.recording.moments import Moments
from rockly_desktop.recording.reading import Entry, Recording


def test_a_pause_shows_the_block_it_holds_at_even_when_its_entry_was_noted_after_it():
    recording = Recording("run.mcap", entries=[
        Entry(0.10, channels.BLOCKS, {"block": "first"}),
        Entry(0.50, channels.RUN, {"event": "pause", "reason": "breakpoint", "block": "second"}),
        Entry(0.51, channels.BLOCKS, {"block": "second"}),
        Entry(0.90, channels.RUN, {"event": "end"}),
    ])
    moments = Moments(recording)
    breakpoint_marker = next(marker for marker in moments.markers() if marker.kind == "breakpoint")
    assert moments.at(breakpoint_marker.time).block == "second"
    assert moments.at(0.2).block == "first"
    assert moments.at(0.05).block is None
