"""Goals: what a lesson checks during a run, one class per kind, fed by the check's observer.

A goal is told the run as it happens (``see`` every tick, ``heard`` for what the robot's topics and
services carried, ``printed`` for the program's lines) and gives its ``verdict`` at the end. A goal met at
a moment keeps it in ``met_at`` (simulated seconds), which order and timing goals compare. A robot
profile adds kinds by subclassing ``LessonGoal`` (the SDK exports it) and naming the list in its
manifest's ``lesson_goals``.
"""
from dataclasses import dataclass, field

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.lessons.schema import Field


class Words:
    """A name in several languages ({en: ..., de: ...}), put into a text in the text's language."""

    def __init__(self, by_language: dict):
        self.by_language = dict(by_language)

    def in_language(self, language: str) -> str:
        """The name in ``language`` (English where it has none)."""
        return self.by_language.get(language) or self.by_language.get("en") or next(iter(self.by_language.values()))

    def __str__(self):
        return self.in_language("en")


@dataclass(frozen=True)
class Area:
    """A named rectangle of a lesson's world: ``rect`` (x0, y0, x1, y1) in map metres, ``label`` its Words."""

    rect: tuple
    label: Words

    def holds(self, x: float, y: float) -> bool:
        """True when (x, y) lies in it."""
        x0, y0, x1, y1 = self.rect
        return x0 <= x <= x1 and y0 <= y <= y1


@dataclass
class Moment:
    """The run at one moment: simulated ``time``, the simulator's ``snapshot``, the ``block`` running,
    the metres ``travelled`` since the start, and ``order``: which moment it is (several share a tick)."""

    time: float
    snapshot: dict
    block: str = None
    travelled: float = 0.0
    order: int = 0

    @property
    def x(self) -> float:
        return float(self.snapshot.get("x", 0.0))

    @property
    def y(self) -> float:
        return float(self.snapshot.get("y", 0.0))


@dataclass
class Verdict:
    """A goal's result: ``passed``, what to tell the child (a LocalText), and the failing moment
    (simulated ``time`` and ``block``; None when the failure has no moment, e.g. a goal never met)."""

    passed: bool
    text: object
    time: float = None
    block: str = None


@dataclass
class GoalContext:
    """What goals may know of the lesson: the robot's ``robot`` name, the world (a World), the lesson's
    ``areas`` ({name: Area}), the other goals by id (filled once all are made), the workspace JSON and the
    profile (block types, toolbox categories)."""

    robot: str
    world: object
    areas: dict
    profile: object
    goals: dict = field(default_factory=dict)
    workspace: dict = field(default_factory=dict)


class ThingName:
    """A world obstacle's name, in the language of the text it goes into."""

    def __init__(self, obstacle):
        self.obstacle = obstacle

    def in_language(self, language: str) -> str:
        return self.obstacle.name(language)


class LessonGoal:
    """One kind of goal. Subclasses set ``kind`` (the ``kind:`` a lesson writes), ``fields`` (schema
    ``Field``s), ``meaning`` (one sentence for the reference) and override what they need of ``spec_problem``
    (fields that must fit together), ``see``, ``heard``, ``printed`` and ``verdict``. ``self.spec`` is the
    goal's data, already validated."""

    kind = ""
    fields = ()
    meaning = ""

    def __init__(self, spec: dict, context: GoalContext):
        self.spec = spec
        self.context = context
        self.id = spec.get("id")
        self.met_at = None   # simulated seconds of the first moment the goal was met
        self.met_moment = None

    @property
    def met_order(self):
        """(time, order) of the first moment the goal was met, to put two goals in order; None if never met."""
        moment = self.met_moment
        return None if moment is None else (moment.time, moment.order)

    @classmethod
    def spec_problem(cls, spec: dict):
        """None when the goal's fields, each already fine, fit together; else (the field to point at, what was
        expected: a LocalText), e.g. a lower bound above the upper one. ``spec`` holds the fields given."""
        return None

    def see(self, moment: Moment):
        """Look at the run after a tick."""

    def heard(self, topic: str, message: dict, moment: Moment):
        """Something went over the robot's topics or services (a service as ``{request, response}``); not
        the streams its profile names (odometry, laser...), which the snapshots show."""

    def printed(self, text: str, moment: Moment):
        """The program printed ``text``."""

    def verdict(self, end: Moment) -> Verdict:
        """The result once the run ended at ``end``."""
        raise NotImplementedError

    @property
    def label(self):
        """What a child reads for this goal when another names it: its ``name`` (Words), else its id."""
        return Words(self.spec["name"]) if self.spec.get("name") else self.id

    def met(self, moment: Moment):
        """Note that the goal is met now (the first time counts)."""
        if self.met_at is None:
            self.met_at = moment.time
            self.met_moment = moment

    def thing(self, thing_id: str):
        """The world's obstacle ``thing_id`` as a name for a text."""
        return ThingName(self.context.world.obstacle(thing_id))


# --- where the robot is or passed --------------------------------------------------------


NEAR_AT_LEAST = 0.02  # metres: an ``ends_near`` goal's lower bound when the lesson gives none


class EndsIn(LessonGoal):
    kind = "ends_in"
    fields = (Field("area", "area", True, "The area."),)
    meaning = "When the program ends, the robot stands in the area."

    def verdict(self, end):
        area = self.context.areas[self.spec["area"]]
        if area.holds(end.x, end.y):
            self.met(end)
            return Verdict(True, app_local_text("lesson_ends_in_passed", robot=self.context.robot, area=area.label))
        return Verdict(False, app_local_text("lesson_ends_in_failed", robot=self.context.robot, area=area.label,
                                             x=end.x, y=end.y), end.time, end.block)


class Passes(LessonGoal):
    kind = "passes"
    fields = (Field("area", "area", True, "The area."),)
    meaning = "At some moment of the run the robot is in the area."

    def see(self, moment):
        if self.met_at is None and self.context.areas[self.spec["area"]].holds(moment.x, moment.y):
            self.met(moment)

    def verdict(self, end):
        area = self.context.areas[self.spec["area"]].label
        if self.met_at is not None:
            return Verdict(True, app_local_text("lesson_passes_passed", robot=self.context.robot, area=area,
                                                time=self.met_at))
        return Verdict(False, app_local_text("lesson_passes_failed", robot=self.context.robot, area=area))


class EndsNear(LessonGoal):
    kind = "ends_near"
    fields = (Field("thing", "thing", True, "The thing."),
              Field("within", "positive", True, "Metres between the robot's edge and the thing at most."),
              Field("at_least", "not_negative", False, "Metres between the robot's edge and the thing at least."))
    meaning = (f"When the program ends, the robot's edge is at most `within` and at least `at_least` metres "
               f"from the thing (`at_least` below `within`; default {NEAR_AT_LEAST}: touching it is not near, "
               f"it is a bump; 0 lets the robot touch it).")

    @classmethod
    def spec_problem(cls, spec):
        at_least, within = spec.get("at_least", NEAR_AT_LEAST), spec["within"]
        if at_least >= within:
            field = "at_least" if "at_least" in spec else "within"
            return field, app_local_text("lesson_expect_apart", at_least=at_least, within=within)
        return None

    def gap(self, moment) -> float:
        world = self.context.world
        return max(0.0, world.obstacle(self.spec["thing"]).distance(moment.x, moment.y) - world.radius)

    def verdict(self, end):
        gap, within = self.gap(end), float(self.spec["within"])
        at_least = float(self.spec.get("at_least", NEAR_AT_LEAST))
        values = dict(robot=self.context.robot, thing=self.thing(self.spec["thing"]), gap=gap * 100,
                      within=within * 100, at_least=at_least * 100)
        if gap > within + 1e-6:
            return Verdict(False, app_local_text("lesson_ends_near_failed", **values), end.time, end.block)
        if gap < at_least - 1e-6:
            return Verdict(False, app_local_text("lesson_ends_near_too_close", **values), end.time, end.block)
        self.met(end)
        return Verdict(True, app_local_text("lesson_ends_near_passed", **values))


# --- what the robot must not do -----------------------------------------------------------


class NoBump(LessonGoal):
    kind = "no_bump"
    fields = ()
    meaning = "The robot bumps into nothing (the simulator's /sim/contact says what it touched)."

    def __init__(self, spec, context):
        super().__init__(spec, context)
        self.bump = None   # (thing id, moment)

    def heard(self, topic, message, moment):
        if topic == "/sim/contact" and self.bump is None:
            self.bump = (str(message.get("data")), moment)

    def verdict(self, end):
        if self.bump is None:
            return Verdict(True, app_local_text("lesson_no_bump_passed", robot=self.context.robot))
        thing_id, moment = self.bump
        try:
            thing = self.thing(thing_id)
        except KeyError:
            thing = app_local_text("lesson_something")
        return Verdict(False, app_local_text("lesson_no_bump_failed", robot=self.context.robot, thing=thing,
                                             time=moment.time, distance=moment.travelled), moment.time, moment.block)


class StaysIn(LessonGoal):
    kind = "stays_in"
    fields = (Field("area", "area", True, "The area it must not leave."),)
    meaning = "The robot never leaves the area."

    def __init__(self, spec, context):
        super().__init__(spec, context)
        self.left = None

    def see(self, moment):
        if self.left is None and not self.context.areas[self.spec["area"]].holds(moment.x, moment.y):
            self.left = Moment(moment.time, {}, moment.block, moment.travelled)

    def verdict(self, end):
        area = self.context.areas[self.spec["area"]].label
        if self.left is None:
            return Verdict(True, app_local_text("lesson_stays_in_passed", robot=self.context.robot, area=area))
        return Verdict(False, app_local_text("lesson_stays_in_failed", robot=self.context.robot, area=area,
                                             time=self.left.time), self.left.time, self.left.block)


class SpeedBelow(LessonGoal):
    kind = "speed_below"
    fields = (Field("speed", "positive", True, "Metres per second the robot must never go faster than."),)
    meaning = "The robot never drives faster than `speed` m/s (forward or backward)."

    def __init__(self, spec, context):
        super().__init__(spec, context)
        self.fastest = None

    def see(self, moment):
        speed = abs(float(moment.snapshot.get("linear", 0.0)))
        if speed > float(self.spec["speed"]) + 1e-6 and (self.fastest is None or speed > self.fastest[0]):
            self.fastest = (speed, moment.time, moment.block)

    def verdict(self, end):
        limit = float(self.spec["speed"])
        if self.fastest is None:
            return Verdict(True, app_local_text("lesson_speed_below_passed", robot=self.context.robot, limit=limit))
        speed, time, block = self.fastest
        return Verdict(False, app_local_text("lesson_speed_below_failed", robot=self.context.robot, speed=speed,
                                             limit=limit, time=time), time, block)


# --- what the program said ----------------------------------------------------------------


class Prints(LessonGoal):
    kind = "prints"
    fields = (Field("text", "text", True, "A text the printed line must contain (capitals do not matter)."),)
    meaning = "The program prints a line that contains the text."

    def printed(self, text, moment):
        if self.spec["text"].casefold() in text.casefold():
            self.met(moment)

    def verdict(self, end):
        if self.met_at is not None:
            return Verdict(True, app_local_text("lesson_prints_passed", text=self.spec["text"]))
        return Verdict(False, app_local_text("lesson_prints_failed", text=self.spec["text"]))


# --- order and timing -------------------------------------------------------------------


class Before(LessonGoal):
    kind = "before"
    fields = (Field("first", "goal", True, "The goal met first."),
              Field("then", "goal", True, "The goal met after it."))
    meaning = "Both goals are met, `first` before (or at the same moment as) `then`."

    def verdict(self, end):
        first, then = (self.context.goals[self.spec[name]] for name in ("first", "then"))
        names = {"first": first.label, "then": then.label}
        if first.met_at is not None and then.met_at is not None and first.met_order <= then.met_order:
            return Verdict(True, app_local_text("lesson_before_passed", **names))
        if first.met_at is None or then.met_at is None:
            return Verdict(False, app_local_text("lesson_before_missing", **names))
        return Verdict(False, app_local_text("lesson_before_failed", time=then.met_at, **names), then.met_at,
                       then.met_moment.block)


class Within(LessonGoal):
    kind = "within"
    fields = (Field("goal", "goal", True, "The goal."),
              Field("seconds", "positive", True, "Simulated seconds from the start."))
    meaning = "The goal is met within `seconds` of simulated time."

    def verdict(self, end):
        goal, seconds = self.context.goals[self.spec["goal"]], float(self.spec["seconds"])
        if goal.met_at is not None and goal.met_at <= seconds + 1e-9:
            return Verdict(True, app_local_text("lesson_within_passed", goal=goal.label, time=goal.met_at,
                                                seconds=seconds))
        if goal.met_at is None:
            return Verdict(False, app_local_text("lesson_within_missing", goal=goal.label))
        return Verdict(False, app_local_text("lesson_within_failed", goal=goal.label, time=goal.met_at,
                                             seconds=seconds), goal.met_at, goal.met_moment.block)


# --- the program's shape --------------------------------------------------------------------

LOOP_TYPES = frozenset(("controls_repeat_ext", "controls_repeat", "controls_whileUntil", "controls_for",
                        "controls_forEach"))
VARIABLE_TYPES = frozenset(("variables_set", "variables_get", "math_change"))
SENSOR_CATEGORY = "Sensors"


def blocks_of(workspace: dict):
    """Every block of a workspace JSON (shadows left out), depth first."""
    stack = list(((workspace or {}).get("blocks") or {}).get("blocks") or [])
    while stack:
        block = stack.pop()
        if not isinstance(block, dict):
            continue
        yield block
        for connection in (block.get("inputs") or {}).values():
            if isinstance(connection, dict) and isinstance(connection.get("block"), dict):
                stack.append(connection["block"])
        following = (block.get("next") or {}).get("block")
        if isinstance(following, dict):
            stack.append(following)


class ShapeGoal(LessonGoal):
    """A goal about the program's blocks, not the run: ``verdict`` reads the workspace."""

    def types(self) -> list:
        return [block.get("type") for block in blocks_of(self.context.workspace)]


class UsesLoop(ShapeGoal):
    kind = "uses_loop"
    meaning = "The program uses a loop block (repeat, while, for)."

    def verdict(self, end):
        passed = any(kind in LOOP_TYPES for kind in self.types())
        return Verdict(passed, app_local_text("lesson_uses_loop_passed" if passed else "lesson_uses_loop_failed"))


class UsesVariable(ShapeGoal):
    kind = "uses_variable"
    meaning = "The program sets or reads a variable."

    def verdict(self, end):
        passed = any(kind in VARIABLE_TYPES for kind in self.types())
        return Verdict(passed, app_local_text("lesson_uses_variable_passed" if passed
                                              else "lesson_uses_variable_failed"))


class UsesSensor(ShapeGoal):
    kind = "uses_sensor"
    meaning = "The program uses a block of its robot's Sensors category."

    def verdict(self, end):
        sensors = sensor_blocks(self.context.profile)
        passed = any(kind in sensors for kind in self.types())
        return Verdict(passed, app_local_text("lesson_uses_sensor_passed" if passed else "lesson_uses_sensor_failed"))


class UsesBlock(ShapeGoal):
    kind = "uses_block"
    fields = (Field("block", "block", True, "The block type."),)
    meaning = "The program uses this block."

    def verdict(self, end):
        passed = self.spec["block"] in self.types()
        return Verdict(passed, app_local_text("lesson_uses_block_passed" if passed else "lesson_uses_block_failed",
                                              block=self.spec["block"]))


class AtMostBlocks(ShapeGoal):
    kind = "at_most_blocks"
    fields = (Field("count", "count", True, "The most blocks the program may have (numbers and texts count too)."),)
    meaning = "The program has at most `count` blocks."

    def verdict(self, end):
        count, most = len(self.types()), int(self.spec["count"])
        key = "lesson_at_most_blocks_passed" if count <= most else "lesson_at_most_blocks_failed"
        return Verdict(count <= most, app_local_text(key, count=count, most=most))


def toolbox_blocks(profile, level: str = None) -> set:
    """The block types the profile's toolbox offers at ``level`` (None: the whole toolbox), with the
    numbers and texts its blocks hold (their shadows)."""
    found = set()
    stack = [profile.toolbox("en", level)]
    while stack:
        item = stack.pop()
        if isinstance(item, dict):
            if isinstance(item.get("type"), str) and item.get("kind") in ("block", None):
                found.add(item["type"])
            stack.extend(item.values())
        elif isinstance(item, list):
            stack.extend(item)
    return found


def known_blocks(profile) -> set:
    """Every block type a lesson may name for ``profile``: its own and all its toolbox offers."""
    return set(profile.block_types) | toolbox_blocks(profile)


def sensor_blocks(profile) -> set:
    """The block types of the profile's Sensors category (its English name)."""
    found = set()
    for category in profile.toolbox_categories:
        name = category.get("name") if isinstance(category, dict) else None
        if (name.get("en") if isinstance(name, dict) else name) == SENSOR_CATEGORY:
            found.update(entry["type"] for entry in category.get("contents") or []
                         if isinstance(entry, dict) and entry.get("type"))
    return found


GENERIC_GOALS = (EndsIn, Passes, EndsNear, NoBump, StaysIn, SpeedBelow, Prints, Before, Within,
                 UsesLoop, UsesVariable, UsesSensor, UsesBlock, AtMostBlocks)


def option_words(profile, block_type: str, field_name: str, value: str) -> Words:
    """The words a block's dropdown shows for ``value`` (``{en: happy, de: fröhlich}``), for a goal's text;
    the value itself where the block has no such option."""
    definition = profile.block(block_type).definition
    for key, args in definition.items():
        if key.startswith("args") and isinstance(args, list):
            for arg in args:
                if isinstance(arg, dict) and arg.get("name") == field_name:
                    for label, option in arg.get("options") or []:
                        if option == value:
                            return Words(label if isinstance(label, dict) else {"en": str(label)})
    return Words({"en": str(value)})
