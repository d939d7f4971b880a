"""Every German text a person reads is German: Rockly's catalogue, HOBBIT's and the TurtleBot's
(their catalogues: command errors, world names; their manifests, blocks and toolboxes; their
simulator views' words) and the shared toolboxes. A German text may use no English word but
the few both languages share (ALLOWED)."""
import ast
import re
from pathlib import Path

import yaml

from rockly_desktop.core.app_texts import app_catalogue
from rockly_desktop.core.catalogue import Catalogue
from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.i18n import is_localized

REPO = Path(__file__).resolve().parents[1]
PROFILES = ("hobbit", "turtlebot")

# Words German uses as they are, or names (of robots, tools, ROS things, Python).
ALLOWED = {
    "rockly", "python", "hobbit", "turtlebot", "ros", "ros_master_uri", "ros_ip", "ros_hostname", "ros_ipv6",
    "roscore", "rospy", "genpy", "actionlib", "blockly", "xml", "json", "csv", "png", "utf", "ipv", "ok",
    "topic", "topics", "publisher", "plot", "master", "tablet", "laser", "laserscans", "arm", "start", "stopp",
    "pause", "pin", "sos", "odometrie", "odom", "esc", "strg", "hz", "id", "ids", "on", "format", "workspace",
    "profile", "rockly-program", "answer", "breakpoints", "mb", "m", "s", "x", "y", "z", "w", "b", "rate",
    "quaternion", "simulator", "simulatoransicht", "editor", "block", "blöcke", "pipe", "socket", "details",
    "app", "ball", "code", "computer", "element", "info", "navigation", "parameter", "person", "pose", "position",
    "problem", "sofa", "text", "variable", "version", "pins",
    "min", "ms",  # minutes, milliseconds
    "cm", "sensor",  # centimetres; der Sensor
    "make", "setup",  # the set-up command, „make setup“, typed as it is
    "tab", "enter",  # keys, as German keyboards and manuals name them
    "distribution", "distributionen", "jazzy", "twiststamped",  # ROS 2's own names
    "debian", "ubuntu", "noetic", "firewall",  # a robot computer's system, ROS 1's distribution; German says Firewall
    "force",  # the command line's option --force, typed as it is
}
# Common English words and this app's own English vocabulary (the English texts, below) that are not German.
COMMON_ENGLISH = set("""
a about after again all also always an and any are as ask at back be because before being both but by can
cannot could did do does done down each either else end every few first for from get give go good has have
he her here his how if in into is it its just keep know last left less let like little look make many may
me more most much must my near need never new next no none not nothing now of off old on once one only
open or other our out over own place please put read right same say see set shall she should show so some
something still such take than that the their them then there these they thing this those through time to
too try turn two under up us use very wait want was way we well were what when where which while who why
will with without would yes you your
""".split())
GERMAN_TOO = {"die", "hat", "was", "will", "so", "an", "in", "also", "bald", "rate", "man", "war", "fast", "kind",
              "gift", "hell", "rock", "bad", "bitte", "wand", "arm", "hand", "name", "end", "still", "neutral",
              "ding", "kiosk", "agent", "listen", "laptop", "laptops", "minute", "codes"}


def _german_and_english(catalogue: Catalogue):
    english = {key: entry.english for key, entry in catalogue.entries().items()}
    german = {key: catalogue.template(key, "de") for key in english}
    return german, english


def _localized(value, found):
    """Every {en: ..., de: ...} text inside ``value`` (YAML data), as (English, German or None) pairs."""
    if is_localized(value):
        found.append((value["en"], value.get("de")))
    elif isinstance(value, dict):
        for item in value.values():
            _localized(item, found)
    elif isinstance(value, list):
        for item in value:
            _localized(item, found)
    return found


def _view_texts(profile):
    """The simulator view's words (``view/texts.py``'s TEXTS), read without importing Qt: (English, German) pairs."""
    source = (REPO / "profiles" / profile / f"rockly_{profile}" / "view" / "texts.py").read_text(encoding="utf-8")
    for node in parse_python(source).body:
        if isinstance(node, ast.Assign) and any(getattr(target, "id", None) == "TEXTS" for target in node.targets):
            texts = ast.literal_eval(node.value)
            return list(zip(_leaves(texts["en"]), _leaves(texts["de"]), strict=True))
    raise AssertionError(f"{profile}: no TEXTS in view/texts.py")


def _leaves(value):
    if isinstance(value, dict):
        return [leaf for key in sorted(value) for leaf in _leaves(value[key])]
    return [value] if isinstance(value, str) else []


def german_texts():
    """(where, German text, its English text) of everything the tests here check."""
    texts = []
    catalogues = [("rockly", app_catalogue())] + [(profile, Catalogue(REPO / "profiles" / profile / "locale"))
                                                  for profile in PROFILES]
    for name, catalogue in catalogues:
        german, english = _german_and_english(catalogue)
        texts += [(f"{name} catalogue: {key}", german[key], english[key]) for key in german]
    files = [REPO / "profiles" / profile / name for profile in PROFILES
             for name in ("profile.yaml", "blocks.yaml", "toolbox.yaml")]
    files += sorted((REPO / "toolboxes").rglob("*.yaml"))
    for path in files:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        texts += [(str(path.relative_to(REPO)), german, english) for english, german in _localized(data, [])]
    for profile in PROFILES:
        texts += [(f"{profile} view texts", german, english) for english, german in _view_texts(profile)]
    return texts


TEXTS = german_texts()
ENGLISH_WORDS = set()
for _where, _german, _english in TEXTS:
    ENGLISH_WORDS.update(re.findall(r"[a-zäöüß]+", re.sub(r"\{[^}]*\}|%\d", " ", str(_english).lower())))


def english_words_in(german: str) -> list:
    """The English words of ``german`` (placeholders, quoted values, field paths, file patterns and keys left out)."""
    text = re.sub(r"\{[^}]*\}|%\d|'[^']*'|\"[^\"]*\"|<[^>]*>|\w+(?:\.\w+)+|\*\.\w+|\bF\d+\b|Strg\+\w", " ", german)
    words = re.findall(r"[A-Za-zÄÖÜäöüß_]+(?:-[A-Za-zÄÖÜäöüß_]+)*", text)
    english = (ENGLISH_WORDS | COMMON_ENGLISH) - GERMAN_TOO - ALLOWED
    return [word for word in words
            if word.lower() in english and word.lower() not in ALLOWED
            and not any(part in ALLOWED for part in word.lower().split("-"))]


def test_the_walk_finds_the_texts_it_is_about():
    places = {where.split(":")[0] for where, _german, _english in TEXTS}
    assert {"rockly catalogue", "hobbit catalogue", "turtlebot catalogue", "hobbit view texts",
            "turtlebot view texts", "profiles/hobbit/blocks.yaml", "profiles/turtlebot/profile.yaml"} <= places
    assert len(TEXTS) > 600


def test_every_profile_text_has_a_german_one():
    missing = [(where, english) for where, german, english in TEXTS if not german]
    assert missing == []


def test_no_english_word_is_left_in_a_german_text():
    left = [f"{where}: {german!r} has {english_words_in(german)} (English: {english!r})"
            for where, german, english in TEXTS if english_words_in(german or "")]
    assert left == []


def test_the_check_finds_english_in_german():
    assert english_words_in("Das konnte der Roboter nicht tun: the distance must be a number") == [
        "the", "distance", "must", "be", "a", "number"]
    assert english_words_in("Die Strecke muss eine Zahl sein, nicht 'ten'") == []


def _profile_code(profile):
    """The profile's commands and what they say about its world (sim.py's own tablet errors are not yet here)."""
    package = REPO / "profiles" / profile / f"rockly_{profile}"
    return [(path, parse_python(path.read_text(encoding="utf-8"))) for path in sorted(package.glob("*.py"))
            if path.name != "sim.py"]


def test_the_profiles_command_errors_are_texts_of_their_catalogues():
    for profile in PROFILES:
        catalogue = Catalogue(REPO / "profiles" / profile / "locale")
        for path, tree in _profile_code(profile):
            for call in (node for node in ast.walk(tree) if isinstance(node, ast.Call)):
                name = getattr(call.func, "id", None)
                if name in ("RobotCommandError", "RobotTimeout") and call.args:
                    assert not isinstance(call.args[0], (ast.Constant, ast.JoinedStr)), \
                        f"{path.name}:{call.lineno}: an English-only error"
                if name == "TEXTS" and call.args and isinstance(call.args[0], ast.Constant):
                    assert call.args[0].value in catalogue, f"{path.name}:{call.lineno}: {call.args[0].value}"
