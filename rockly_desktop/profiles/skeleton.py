"""``rockly profiles new NAME``: a small robot profile that works, as a starting point.

The profile's files are templates kept here as data (``SKELETON_FILES``) and rendered
with the name: ``$name`` (the profile id), ``$Title`` (shown to people) and ``$Class``
(the start of its Python class names). The robot it describes has one command,
``robot.say(text)``, which publishes a ``std_msgs/String`` on ``/NAME/say`` (and refuses an
empty text with an error from the profile's own catalogue, ``locale/``, in English and German);
its simulator remembers the last text said and its view (``rockly_NAME/view/``, the layout of
the built-in profiles) shows it. A folder that cannot be written completely is
removed again.
"""
import importlib.util
import re
import shutil
import string
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.profiles.registry import ProfileRegistry

# The manifest's rule for ``id`` (profiles/manifest.py), said once more to refuse a name before writing.
_PROFILE_ID = re.compile(r"[a-z][a-z0-9_]{0,39}")

SKELETON_FILES = {
    "profile.yaml": '''\
# The $Title robot profile, made by `rockly profiles new $name`.
# Every field is explained in Rockly's docs/writing-a-robot-profile.md.
schema: 1
id: "$name"
name: "$Title"
version: "0.1.0"
description:
  en: "$Title says what it is told."
  de: "$Title sagt, was man ihm sagt."
languages: [en, de]
blocks: blocks.yaml
toolbox: toolbox.yaml
api: rockly_$name.api:${Class}Commands
simulator: rockly_$name.sim:Sim$Class
simulator_view: rockly_$name.view:${Class}View
ros_interface:
  subscribes:
    /$name/say: std_msgs/String
    /$name/stop: std_msgs/Empty
safe_stop:
  - publish: {topic: /$name/stop, type: std_msgs/Empty, message: {}}
state:
  - panel: {en: Speech, de: Sprache}
    rows:
      - {label: {en: Last said, de: Zuletzt gesagt}, topic: /$name/say, field: data}
''',
    "blocks.yaml": '''\
# $Title's blocks. Each block's `python` is the command it becomes (see rockly_$name/api.py).

blocks:
  - type: ${name}_say
    message0: {en: "say %1", de: "sage %1"}
    args0:
      - {type: input_value, name: text, check: String}
    previousStatement: null
    nextStatement: null
    colour: "#3d7fd6"
    tooltip: {en: "$Title says this text.", de: "$Title sagt diesen Text."}
    python:
      code: "robot.say({text})"
      defaults: {text: ""}
''',
    "toolbox.yaml": '''\
categories:
  - name: "$Title"
    colour: "#3d7fd6"
    blocks:
      - type: ${name}_say
        inputs: {text: {shadow: {type: text, fields: {TEXT: {en: "Hello!", de: "Hallo!"}}}}}
  - shared: logic
  - shared: loops
  - shared: math
  - shared: text
  - shared: variables
''',
    "locale/messages.pot": '''\
# $Title's texts in English: every key (msgctxt) with its English text (msgid).
# Each other language is one file beside this one (de.po); Poedit or Weblate make a new one from this.
msgid ""
msgstr ""
"Project-Id-Version: Rockly profile $name\\n"
"Content-Type: text/plain; charset=UTF-8\\n"

msgctxt "nothing_to_say"
msgid "there is nothing to say: the text is empty"
msgstr ""
''',
    "locale/de.po": '''\
# $Title's texts in German.
msgid ""
msgstr ""
"Project-Id-Version: Rockly profile $name\\n"
"Language: de\\n"
"Content-Type: text/plain; charset=UTF-8\\n"

msgctxt "nothing_to_say"
msgid "there is nothing to say: the text is empty"
msgstr "es gibt nichts zu sagen: Der Text ist leer"
''',
    "rockly_$name/__init__.py": '''\
"""$Title: a Rockly robot profile."""
''',
    "rockly_$name/api.py": '''\
"""$Title's commands, bound as ``robot`` in programs::

    robot.say('Hello!')
"""
from rockly_desktop.sdk import RobotCommandError, RobotCommands, profile_texts

SAY_TOPIC, SAY_TYPE = "/$name/say", "std_msgs/String"
# The profile's words: locale/ beside profile.yaml (messages.pot in English, de.po in German, ...).
# An error made of them is shown in the language of the run.
TEXTS = profile_texts(__file__)


class ${Class}Commands(RobotCommands):
    """Commands for $Title."""

    def say(self, text):
        """Say ``text`` (published as a std_msgs/String on /$name/say); an empty text is an error."""
        if text is None or str(text) == "":
            raise RobotCommandError(TEXTS("nothing_to_say"))
        self.backend.publish(SAY_TOPIC, SAY_TYPE, {"data": str(text)})
''',
    "rockly_$name/sim.py": '''\
"""The simulated $Title: it listens where the real robot listens and remembers what it heard.

``RobotSimulator`` brings the lock, the clock thread, ordered publishing, ``start()`` and
``shutdown()``; see "A simulator, and its view" in Rockly's docs/writing-a-robot-profile.md.
"""
from rockly_desktop.sdk import RobotSimulator

SAY_TOPIC = "/$name/say"
STOP_TOPIC = "/$name/stop"


class Sim$Class(RobotSimulator):
    """A simulated $Title in a SimWorld; ``tablet`` and ``speed`` are not needed by this robot yet."""

    NAME = "simulated $Title"

    def __init__(self, world, tablet=None, speed=1.0):
        super().__init__(world, tablet, speed)
        self._said = None
        self._stops = 0

    def connect(self):
        """Listen on the robot's topics (until ``shutdown()``)."""
        self.subscribe(SAY_TOPIC, self._on_say)
        self.subscribe(STOP_TOPIC, self._on_stop)

    # A robot that changes by itself also overrides advance(dt) (simulated seconds pass) and
    # queue_sensors() (queue what its sensors publish); both are called holding self.lock.

    def snapshot(self) -> dict:
        """The robot's state: the last text said (None before the first) and how often it was stopped."""
        with self.lock:
            return {"said": self._said, "stops": self._stops}

    def reset(self):
        """Put the robot back as it started (the window's Put back button, Ctrl+R)."""
        with self.lock:
            self._said = None
            self._stops = 0

    def _on_say(self, message):
        with self.lock:
            self._said = message.get("data", "")

    def _on_stop(self, message):
        with self.lock:
            self._stops += 1
''',
    "rockly_$name/view/__init__.py": '''\
"""The simulated $Title, drawn in the Simulator dock from the snapshots ``Sim$Class.snapshot()`` returns.

Modules: widget (the QWidget), texts (its words in each language). A bigger view adds its
painters here, one module each (a palette, a layout, the room, the robot...).
"""
from .widget import ${Class}View

__all__ = ["${Class}View"]
''',
    "rockly_$name/view/texts.py": '''\
"""The view's words in each language; English is used for any other."""
TEXTS = {
    "en": {"silent": "(nothing said yet)", "stops": "stopped {count} times"},
    "de": {"silent": "(noch nichts gesagt)", "stops": "{count}-mal gestoppt"},
}
''',
    "rockly_$name/view/widget.py": '''\
"""${Class}View, the QWidget: the last text $Title said on a card, and how often it was stopped."""
from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF, QPainter
from PySide6.QtWidgets import QWidget

from rockly_desktop.sdk import as_number, with_defaults
from rockly_desktop.sdk_view import card, sized_font, wrap_lines

from .texts import TEXTS

DEFAULTS = {"said": None, "stops": 0}
BACKGROUND, INK = QColor("#EEF0FA"), QColor("#27304D")


class ${Class}View(QWidget):
    """Draws the snapshot dicts ``Sim$Class.snapshot()`` returns; it never talks to the simulator."""

    def __init__(self, parent=None, language="en"):
        super().__init__(parent)
        self._texts = TEXTS.get(language, TEXTS["en"])
        self._snapshot = dict(DEFAULTS)
        self.setMinimumSize(200, 150)

    def snapshot(self) -> dict:
        """The snapshot drawn now (with defaults for what it left out)."""
        return dict(self._snapshot)

    def set_snapshot(self, snapshot):
        """Show ``snapshot``; called about 30 times a second while the Simulator dock is shown."""
        snapshot = with_defaults(snapshot, DEFAULTS)
        if snapshot != self._snapshot:
            self._snapshot = snapshot
            self.update()

    def paintEvent(self, event):
        """Qt override: the card with the text said, the stops below it."""
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), BACKGROUND)
        unit = min(self.width(), self.height()) / 200
        box = QRectF(self.rect()).adjusted(12 * unit, 12 * unit, -12 * unit, -40 * unit)
        card(painter, box, 10 * unit)
        said = self._snapshot["said"]
        font = sized_font(self.font(), 18 * unit, bold=said is not None)
        painter.setFont(font)
        painter.setPen(INK)
        text = self._texts["silent"] if said is None else str(said)
        fitting = max(1, int(box.height() // QFontMetricsF(font).lineSpacing()))
        lines = wrap_lines(text, font, box.width() - 20 * unit)[:fitting]
        painter.drawText(box.adjusted(10 * unit, 10 * unit, -10 * unit, -10 * unit), Qt.AlignmentFlag.AlignCenter,
                         "\\n".join(lines))
        painter.setFont(sized_font(self.font(), 12 * unit))
        stops = int(as_number(self._snapshot["stops"], 0, 0, 1e9))
        painter.drawText(QRectF(0, box.bottom(), self.width(), 40 * unit), Qt.AlignmentFlag.AlignCenter,
                         self._texts["stops"].format(count=stops))
        painter.end()
''',
    "tests/test_$name.py": '''\
"""$Title's profile works: it loads, its blocks call real commands, and the simulator hears them.

Run it with the Python that has Rockly installed: ``python -m pytest tests``.
"""
from pathlib import Path

import pytest

from rockly_desktop.core import paths
from rockly_desktop.profiles.checks import check_commands
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.sdk import RobotCommandError

PROFILE_DIR = Path(__file__).resolve().parents[1]


def load():
    return load_profile(PROFILE_DIR, paths.shared_toolboxes_dir())


def test_the_profile_loads_and_its_blocks_call_real_commands():
    profile = load()
    assert profile.id == "$name"
    check_commands(profile)


def test_the_simulator_hears_what_the_robot_is_told_to_say_and_the_safe_stop():
    profile = load()
    world = SimWorld()
    simulator = profile.load_object("simulator")(world, tablet=None, speed=1.0)
    simulator.start()
    try:
        backend = SimBackend(world, Interrupt())
        robot = profile.load_object("api")(backend)
        robot.say("Hello!")
        assert simulator.snapshot() == {"said": "Hello!", "stops": 0}
        assert run_safe_stop(profile.safe_stop, backend) == []
        assert simulator.snapshot() == {"said": "Hello!", "stops": 1}
    finally:
        simulator.shutdown()


def test_an_error_is_said_in_the_language_of_the_run():
    robot = load().load_object("api")(None)
    with pytest.raises(RobotCommandError) as refused:
        robot.say("")
    assert str(refused.value) == "there is nothing to say: the text is empty"
    assert refused.value.in_language("de") == "es gibt nichts zu sagen: Der Text ist leer"
''',
}


class ProfileNameRefused(RocklyError):
    """The name cannot be a new profile's id; the message says why."""


def _check_name(name: str) -> None:
    if not _PROFILE_ID.fullmatch(name):
        raise ProfileNameRefused(f"'{name}' is not a profile id: use lower-case letters, digits and '_', "
                                 f"starting with a letter (at most 40), e.g. my_robot")
    package = f"rockly_{name}"
    if importlib.util.find_spec(package) is not None:
        raise ProfileNameRefused(f"'{name}' would name the profile's package {package}, which is already "
                                 f"importable here; choose another name")
    installed = ProfileRegistry.discover().profiles.get(name)
    if installed is not None:
        raise ProfileNameRefused(f"a profile with the id '{name}' is already installed ({installed.source}, "
                                 f"{installed.root}); choose another name")


def render(name: str) -> dict:
    """The skeleton's files for the profile ``name``: {relative path: text}."""
    words = [part for part in name.split("_") if part]
    names = {"name": name, "Title": " ".join(word.capitalize() for word in words),
             "Class": "".join(word.capitalize() for word in words)}
    return {string.Template(path).substitute(names): string.Template(text).substitute(names)
            for path, text in SKELETON_FILES.items()}


def create_profile(name: str, parent: Path = None) -> Path:
    """Write the skeleton profile ``name`` to ``parent/name`` (default: the user's profile folder).

    Raises ProfileNameRefused for a name that cannot be a new profile's id, and
    RocklyError when the folder exists already or cannot be written.
    """
    _check_name(name)
    parent = Path(parent) if parent is not None else paths.user_profiles_dir()
    target = parent / name
    if target.exists():
        raise RocklyError(f"{target} exists already; nothing was changed (choose another name or folder)")
    created = False
    try:
        parent.mkdir(parents=True, exist_ok=True)
        target.mkdir()
        created = True
        for relative, text in render(name).items():
            path = target / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
    except OSError as error:
        if created:
            shutil.rmtree(target, ignore_errors=True)
        raise RocklyError(f"cannot create {target}: {error}") from None
    return target


def next_steps(folder: Path) -> str:
    """What to tell the person who just made the profile in ``folder``."""
    lines = [f"Created the robot profile '{folder.name}' in {folder}", "Next:",
             f"  rockly profiles validate {folder}", f"  python -m pytest {folder / 'tests'}"]
    if folder.parent.resolve() != paths.user_profiles_dir().resolve():
        lines.append(f"Rockly finds it once the folder is in {paths.user_profiles_dir()} "
                     f"(see docs/writing-a-robot-profile.md)")
    return "\n".join(lines)
