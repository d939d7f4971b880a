"""The agent's messages: JSON objects, one per line over TCP (UTF-8, ``\\n`` at its end), one per std_msgs/String
over ROS 1 and ROS 2 (``agent.ros_transport``).

A client sends requests ``{"op": OP, "id": N, ...}``; the agent answers each with
``{"reply": N, "ok": true, ...}`` or ``{"reply": N, "ok": false, "error": KEY, "message": TEXT}`` (TEXT in the
language the client named in its ``hello``). An attached client also gets the run's events as they happen:
the lines of ``runtime.event_stream`` (``{"event": "block", ...}``) and the agent's own
``{"event": "run", "state": ...}``, ``{"event": "control", "controller": BOOL}``.

Every ``ALIVE_SECONDS`` the agent says ``{"alive": true}`` to every client (over ROS sealed per line): neither an
answer nor an event, so a client older than it drops it unread (its ``reply`` names no request it waits for). The
agent's ``hello`` answer says ``"alive_seconds"``; a client that got it ends its line as lost after
``AGENT_SILENT_SECONDS`` without a word from the agent (a hung or frozen agent, a cut network close nothing: a TCP
connection stays open, a ROS publisher stays in the graph). A client of an older agent (no ``alive_seconds``)
keeps hearing a lost agent only from its transport.
"""
import json

# Of this protocol: 2 since pairing (TLS over TCP, sealed messages over ROS); 1 before it. An agent and a client of
# other formats say so and stop; a client of an older format is told to update and pair (``client_before_pairing``).
FORMAT = 2
DEFAULT_PORT = 11411
HEARTBEAT_SECONDS = 0.2  # how often an attached client says it is there (well inside any time to decide)
ALIVE = {"alive": True}
ALIVE_SECONDS = 0.5  # how often the agent says it is there
# a client not hearing the agent this long has lost it: ten beats missed, so a loaded machine or a short Wi-Fi
# drop does not end a line that works (as long as the agent waits for a silent client), and a window stops
# showing a run that is gone within a few seconds
AGENT_SILENT_SECONDS = 5.0
LOST_EDITOR_CHOICES = ("keep_going", "stop")
DEFAULT_DECIDE_SECONDS = 2.0
# A program's texts travel in one line: a 10,000-block program is some 3 MB as .rockly and as much again as its
# standalone file; JSON's escapes make that up to twice as long.
MAX_LINE_BYTES = 16 * 1024 * 1024
DEFAULT_NAMESPACE = "/rockly_agent"  # of the agent's topics over ROS 1


def encode(message: dict) -> bytes:
    """``message`` as one line."""
    return (json.dumps(message, ensure_ascii=False) + "\n").encode("utf-8")


def decode(line: bytes):
    """The object of one line; None for a line that is not a JSON object."""
    try:
        message = json.loads(line.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError):
        return None
    return message if isinstance(message, dict) else None


class AgentError(Exception):
    """The agent refused a request, or could not be reached: ``key`` and a ``message`` for people (a client's
    side; ``AgentRefusal`` is the agent's)."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key
        self.message = message


class AgentRefusal(Exception):
    """A request the agent refuses: ``key`` names the catalogue text, ``values`` fill it."""

    def __init__(self, key: str, **values):
        super().__init__(key)
        self.key = key
        self.values = values


def older_format(value) -> bool:
    """Whether a client saying ``format`` ``value`` speaks a format older than this one (from before pairing)."""
    return isinstance(value, int) and not isinstance(value, bool) and value < FORMAT


def client_before_pairing(client_version) -> AgentRefusal:
    """The refusal for a client from before pairing (Rockly ``client_version``): update it, then pair it."""
    from rockly_desktop import __version__

    return AgentRefusal("agent_client_before_pairing", agent=__version__, client=str(client_version)[:40])


def refusal_text(refusal: AgentRefusal, language: str) -> str:
    """What ``refusal`` says, in ``language`` (a value given per language is taken in it)."""
    from rockly_desktop.core.app_texts import app_text

    values = {key: value.get(language, value.get("en")) if isinstance(value, dict) else value
              for key, value in refusal.values.items()}
    return app_text(refusal.key, language, **values)
