"""A recording's timeline as lines of text (``rockly replay``): time, block, outcome.

Each block entered is one line with how long it ran (until the next block began) and
what its commands ended with (a service's response, a goal's outcome, a failure); the
run's own events (pauses, what it printed, the safe stop, the end) are lines of their own.
"""
from rockly_desktop.recording import channels
from rockly_desktop.recording.reading import Recording

_ENDINGS = ("response", "outcome", "failed")


def _ending(entry) -> str:
    data = entry.data
    seconds = f" ({data['seconds']:.2f} s)" if isinstance(data.get("seconds"), (int, float)) else ""
    if data["kind"] == "outcome":
        text = f": {data['text']}" if data.get("text") else ""
        return f"goal {data['name']} {data.get('status') or ''}{text}{seconds}"
    if data["kind"] == "response":
        return f"call {data['name']} answered{seconds}"
    return f"{data['name']} failed: {data.get('text', '')}{seconds}"


def _run_event(data: dict) -> tuple:
    event = data["event"]
    if event == "pause":
        return "pause", data.get("block") or "", data.get("reason") or ""
    if event == "safe_stop":
        failures = data.get("failures") or []
        return "stop", "", "safe stop" + (": " + "; ".join(failures) if failures else " done")
    if event == "end":
        message = f": {data['message']}" if data.get("message") else ""
        return "end", data.get("block") or "", f"{data.get('outcome')}{message}"
    return event, "", ""


def timeline_lines(recording: Recording) -> list:
    """The timeline of ``recording`` as text lines, a header first."""
    meta = recording.metadata
    lines = [f"# {meta.get('program', '?')} on {meta.get('robot', '?')} ({meta.get('profile', '?')}), "
             f"started {meta.get('started', '?')}" + ("" if recording.complete or recording.read_in_part
                                                    else " - cut short, read to its end")]
    blocks = [entry for entry in recording.entries if entry.channel == channels.BLOCKS]
    ends = [entry.time for entry in recording.entries if entry.channel == channels.RUN
            and entry.data.get("event") == "end"]
    endings = [entry for entry in recording.entries if entry.channel == channels.COMMANDS
               and entry.data.get("kind") in _ENDINGS]
    last = ends[0] if ends else recording.duration
    left_at = {id(block): later.time for block, later in zip(blocks, blocks[1:])}
    for entry in recording.entries:
        if entry.channel == channels.BLOCKS:
            left = left_at.get(id(entry), last)
            outcome = "; ".join(_ending(e) for e in endings if entry.time <= e.time < left
                                and e.data.get("block") == entry.data["block"]) or "ok"
            kind = f" {entry.data['type']}" if entry.data.get("type") else ""
            sampled = " (sampled)" if entry.data.get("sampled") else ""
            lines.append(f"{entry.time:9.3f}  block   {entry.data['block']}{kind}{sampled}  "
                         f"{left - entry.time:.3f} s  {outcome}")
        elif entry.channel == channels.RUN:
            what, block, outcome = _run_event(entry.data)
            lines.append(f"{entry.time:9.3f}  {what:<7} {block}  {outcome}".rstrip())
        elif entry.channel == channels.OUTPUT and "skipped" in entry.data:
            lines.append(f"{entry.time:9.3f}  print   ({entry.data['skipped']} more lines printed too fast to record)")
        elif entry.channel == channels.OUTPUT:
            lines.append(f"{entry.time:9.3f}  print   {entry.data.get('text', '')}")
    return lines
