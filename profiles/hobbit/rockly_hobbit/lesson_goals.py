"""What lessons can ask of HOBBIT beyond driving: a face, a look, the arm and gripper, the tablet.

Named in profile.yaml's ``lesson_goals``; each kind is met at the first moment the simulated HOBBIT
shows it (its snapshot after a tick) or the tablet is asked (the ``/MMUI`` service), so order and
timing goals can compare them.
"""
from rockly_desktop.sdk import LessonField, LessonGoal, Verdict, option_words, profile_texts

from .sim import EMOTIONS, HEAD_POSITIONS

TEXTS = profile_texts(__file__)
ARM_POSES = ("home", "candle", "floor", "table", "tray", "learning")
ARM_OPTIONS = {"home": "MoveToHome", "candle": "MoveToCandle", "floor": "MoveToPreGraspFloor",
               "table": "MoveToPreGraspTable", "tray": "MoveToTray", "learning": "MoveToLearning"}
QUESTIONS = ("D_OK", "D_YES_NO", "D_NAME")


class _Shown(LessonGoal):
    """Met when the snapshot's ``key`` is the goal's value."""

    key = ""
    field_name = ""

    def see(self, moment):
        if moment.snapshot.get(self.key) == self.spec[self.field_name]:
            self.met(moment)

    def words(self):
        raise NotImplementedError

    def verdict(self, end):
        passed = self.met_at is not None
        key = f"lesson_{self.kind}_{'passed' if passed else 'failed'}"
        return Verdict(passed, TEXTS(key, what=self.words(), time=self.met_at or 0.0))


class ShowsEmotion(_Shown):
    kind = "shows_emotion"
    key = field_name = "emotion"
    fields = (LessonField("emotion", "choice", True, "The face.", tuple(sorted(EMOTIONS))),)
    meaning = "HOBBIT shows this face (emotion) at some moment."

    def words(self):
        return option_words(self.context.profile, "hobbit_emo", "emotion", self.spec["emotion"])


class Looks(_Shown):
    kind = "looks"
    key, field_name = "head", "position"
    fields = (LessonField("position", "choice", True, "The head position.", tuple(sorted(HEAD_POSITIONS))),)
    meaning = "HOBBIT's head looks this way at some moment."

    def words(self):
        return option_words(self.context.profile, "hobbit_head", "head_position", self.spec["position"])


class ArmAt(_Shown):
    kind = "arm_at"
    key, field_name = "arm", "pose"
    fields = (LessonField("pose", "choice", True, "Where the arm is.", ARM_POSES),)
    meaning = "HOBBIT's arm reaches this pose at some moment."

    def words(self):
        return option_words(self.context.profile, "hobbit_arm_move", "movement", ARM_OPTIONS[self.spec["pose"]])


class Gripper(_Shown):
    kind = "gripper"
    key, field_name = "gripper", "state"
    fields = (LessonField("state", "choice", True, "Open or closed.", ("open", "closed")),)
    meaning = "HOBBIT's gripper is open (or closed) at some moment; it starts closed."

    def words(self):
        return TEXTS(f"gripper_{self.spec['state']}")


class _Tablet(LessonGoal):
    """Met when the tablet (``/MMUI``) is sent a request of ``types`` whose text holds ``contains``."""

    types = ()

    def heard(self, topic, message, moment):
        if topic != "/MMUI":
            return
        params = {param.get("name"): param.get("value") for param in (message.get("request") or {}).get("params") or []}
        text = str(params.get("text", ""))
        if params.get("type") in self.types and self.spec.get("contains", "").casefold() in text.casefold():
            self.met(moment)

    def verdict(self, end):
        passed = self.met_at is not None
        key = f"lesson_{self.kind}_{'passed' if passed else 'failed'}"
        return Verdict(passed, TEXTS(key, text=self.spec.get("contains", ""), time=self.met_at or 0.0))


class Asks(_Tablet):
    kind = "asks"
    types = QUESTIONS
    fields = (LessonField("contains", "text", False, "A text the question must contain."),)
    meaning = "HOBBIT asks a question on its tablet (yes/no, a name, or OK) that contains the text."


class ShowsText(_Tablet):
    kind = "shows_text"
    types = ("D_PLAIN",)
    fields = (LessonField("contains", "text", True, "A text the message must contain."),)
    meaning = "HOBBIT shows a message on its tablet that contains the text."


GOALS = [ShowsEmotion, Looks, ArmAt, Gripper, Asks, ShowsText]
