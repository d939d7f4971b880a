"""Every goal kind, each with a program that passes it and one that fails it, on the real simulators in
stepped time (the programs are generated code, as the editor writes it)."""
import pytest
from lesson_tools import check
from program_builder import block, number, stack, workspace

from rockly_desktop.lessons.stepping import BLOCK_SECONDS

CORNER = {"corner": {"rect": [2.5, -1.5, 3.5, -0.5], "name": {"en": "the corner", "de": "der Ecke"}}}
TURTLE = {"robot": "turtlebot", "start": [0, -1.0, 0], "areas": CORNER}
KITCHEN = {"kitchen": {"rect": [2.6, -0.6, 4.4, 0.6], "name": {"en": "the kitchen", "de": "der Küche"}}}


def only(result):
    """The one goal's result (and the run ended by itself)."""
    assert result.ending == "finished", result.ending_text
    [goal] = result.goals
    return goal


def words(result):
    return [goal.words("en") for goal in result.goals]


@pytest.mark.parametrize("metres, passed", [(3.0, True), (1.0, False)])
def test_ends_in_an_area(tmp_path, profiles, metres, passed):
    goal = only(check(tmp_path, profiles, [f"robot.drive({metres})"], goals=[{"kind": "ends_in", "area": "corner"}],
                      **TURTLE))
    assert goal.passed is passed
    if not passed:
        assert goal.words("en") == "TurtleBot stopped at (1.0 m, -1.0 m), not in the corner."
        assert goal.words("de") == "TurtleBot hat bei (1,0 m, -1,0 m) angehalten, nicht in der Ecke."
        assert goal.block == "b1"


@pytest.mark.parametrize("back, passed", [(2.5, True), (0.5, False)])
def test_passes_an_area_on_the_way(tmp_path, profiles, back, passed):
    goal = only(check(tmp_path, profiles, [f"robot.drive({back + 0.5})", f"robot.drive({back + 0.5}, 'backward')"],
                      goals=[{"kind": "passes", "area": "corner"}], **TURTLE))
    assert goal.passed is passed


@pytest.mark.parametrize("metres, at_least, passed, said", [
    (3.2, 0.15, True, "TurtleBot stopped 20 cm from the wall."),
    (2.5, 0.15, False, "TurtleBot stopped 90 cm from the wall. It should be 25 cm or closer."),
    (3.2, 0.22, False, "TurtleBot stopped 20 cm from the wall. That is too close: it should be 22 cm or more."),
])
def test_ends_near_a_thing_neither_too_far_nor_too_close(tmp_path, profiles, metres, at_least, passed, said):
    goal = only(check(tmp_path, profiles, [f"robot.drive({metres})"], goals=[
        {"kind": "ends_near", "thing": "wall_front", "within": 0.25, "at_least": at_least}], **TURTLE))
    assert goal.passed is passed
    assert goal.words("en") == said
    assert goal.words("de").startswith("TurtleBot hat angehalten: ")
    assert (goal.block, goal.time is not None) == ((None, False) if passed else ("b1", True))


def test_ends_near_touching_the_thing_is_not_near_unless_the_lesson_allows_it(tmp_path, profiles):
    """A robot at the wall (the drive stopped by the contact) is 0 cm from it: not "near" by default."""
    touching = ["robot.drive_for(0.2, 30)"]   # further than the wall: the simulator stops the robot at it
    near = {"kind": "ends_near", "thing": "wall_front", "within": 0.25}
    result = check(tmp_path / "a", profiles, touching, goals=[near, {"kind": "no_bump"}], **TURTLE)
    assert [goal.passed for goal in result.goals] == [False, False]
    assert result.goals[0].words("en") == ("TurtleBot stopped 0 cm from the wall. That is too close: it should "
                                           "be 2 cm or more.")
    allowed = check(tmp_path / "b", profiles, touching, goals=[dict(near, at_least=0)], **TURTLE)
    assert allowed.goals[0].passed


def test_no_bump_passes_a_careful_drive_and_names_what_was_hit(tmp_path, profiles):
    careful = check(tmp_path / "a", profiles, ["robot.drive(1.0)"], goals=[{"kind": "no_bump"}], **TURTLE)
    assert only(careful).passed
    bumped = check(tmp_path / "b", profiles, ["robot.drive(1.0)", "robot.drive(1.0)"], goals=[{"kind": "no_bump"}],
                   robot="turtlebot", start=[0, 0, 0])
    assert bumped.ending == "error"   # the drive itself says it bumped
    [goal] = bumped.goals
    assert not goal.passed
    assert goal.words("en").startswith("TurtleBot bumped into the red box after ")
    assert goal.words("de").startswith("TurtleBot ist nach ")
    assert goal.block == "b2" and 9 < goal.time < 12.5
    assert bumped.failing == (goal.time, "b2")


@pytest.mark.parametrize("metres, passed", [(1.0, True), (3.0, False)])
def test_stays_in_an_area(tmp_path, profiles, metres, passed):
    areas = {"start": {"rect": [-0.5, -1.5, 1.5, -0.5], "name": {"en": "the start", "de": "dem Start"}}}
    goal = only(check(tmp_path, profiles, [f"robot.drive({metres})"], goals=[{"kind": "stays_in", "area": "start"}],
                      **dict(TURTLE, areas=areas)))
    assert goal.passed is passed


@pytest.mark.parametrize("speed, passed", [(0.1, True), (0.2, False)])
def test_speed_below(tmp_path, profiles, speed, passed):
    goal = only(check(tmp_path, profiles, [f"robot.drive_for({speed}, 2)"],
                      goals=[{"kind": "speed_below", "speed": 0.15}], **TURTLE))
    assert goal.passed is passed
    if not passed:
        assert goal.words("en").startswith("TurtleBot drove 0.20 m/s after ")


@pytest.mark.parametrize("line, passed", [("print('Hello robot')", True), ("print('Bye')", False)])
def test_prints(tmp_path, profiles, line, passed):
    goal = only(check(tmp_path, profiles, [line], goals=[{"kind": "prints", "text": "hello"}], **TURTLE))
    assert goal.passed is passed


@pytest.mark.parametrize("order, passed", [(("print('one')", "print('two')"), True),
                                           (("print('two')", "print('one')"), False)])
def test_before(tmp_path, profiles, order, passed):
    goals = [{"kind": "prints", "text": "one", "id": "one"}, {"kind": "prints", "text": "two", "id": "two"},
             {"kind": "before", "first": "one", "then": "two"}]
    result = check(tmp_path, profiles, list(order), goals=goals, **TURTLE)
    assert result.goals[2].passed is passed
    if not passed:
        assert result.goals[2].block == "b1"


@pytest.mark.parametrize("wait, passed", [(1, True), (25, False)])
def test_within_seconds(tmp_path, profiles, wait, passed):
    goals = [{"kind": "ends_in", "area": "corner", "id": "corner"}, {"kind": "within", "goal": "corner", "seconds": 30}]
    result = check(tmp_path, profiles, [f"robot.wait({wait})", "robot.drive(3.0)"], goals=goals, **TURTLE)
    assert result.goals[1].passed is passed
    if not passed:
        assert result.goals[1].words("en").startswith("“corner” happened only after 4")


def _shape(tmp_path, profiles, goal, blocks):
    return only(check(tmp_path, profiles, ["pass"], workspace=workspace(blocks), goals=[goal], **TURTLE))


def test_uses_loop(tmp_path, profiles):
    loop = block("controls_repeat_ext", inputs={"TIMES": number(4), "DO": block("turtlebot_stop")})
    assert _shape(tmp_path / "a", profiles, {"kind": "uses_loop"}, loop).passed
    assert not _shape(tmp_path / "b", profiles, {"kind": "uses_loop"}, block("turtlebot_stop")).passed


def test_at_most_blocks(tmp_path, profiles):
    two = stack(block("turtlebot_stop"), block("turtlebot_stop"))
    assert _shape(tmp_path / "a", profiles, {"kind": "at_most_blocks", "count": 2}, two).passed
    three = stack(block("turtlebot_stop"), block("turtlebot_stop"), block("turtlebot_stop"))
    result = _shape(tmp_path / "b", profiles, {"kind": "at_most_blocks", "count": 2}, three)
    assert not result.passed and result.words("en") == "The program has 3 blocks. Can you do it with 2?"


def test_uses_variable(tmp_path, profiles):
    setting = block("variables_set", fields={"VAR": {"id": "v"}}, inputs={"VALUE": number(1)})
    assert _shape(tmp_path / "a", profiles, {"kind": "uses_variable"}, setting).passed
    assert not _shape(tmp_path / "b", profiles, {"kind": "uses_variable"}, block("turtlebot_stop")).passed


def test_uses_sensor(tmp_path, profiles):
    asking = block("controls_if", inputs={"IF0": block("turtlebot_obstacle", {"direction": "ahead"},
                                                         {"metres": number(0.3)})})
    assert _shape(tmp_path / "a", profiles, {"kind": "uses_sensor"}, asking).passed
    assert not _shape(tmp_path / "b", profiles, {"kind": "uses_sensor"}, block("turtlebot_stop")).passed


def test_uses_block(tmp_path, profiles):
    goal = {"kind": "uses_block", "block": "turtlebot_turn"}
    assert _shape(tmp_path / "a", profiles, goal, block("turtlebot_turn", {"direction": "left"})).passed
    assert not _shape(tmp_path / "b", profiles, goal, block("turtlebot_stop")).passed


# --- HOBBIT's own kinds (its profile's lesson_goals) ---------------------------------------------

HOBBIT = {"robot": "hobbit", "answers": ["yes"]}


@pytest.mark.parametrize("emotion, passed", [("HAPPY", True), ("SAD", False)])
def test_shows_emotion(tmp_path, profiles, emotion, passed):
    goal = only(check(tmp_path, profiles, [f"robot.show_emotion('{emotion}')"],
                      goals=[{"kind": "shows_emotion", "emotion": "HAPPY"}], **HOBBIT))
    assert goal.passed is passed
    assert ("fröhlich" in goal.words("de")) and ("happy" in goal.words("en"))


@pytest.mark.parametrize("position, passed", [("up_center", True), ("down_center", False)])
def test_looks(tmp_path, profiles, position, passed):
    goal = only(check(tmp_path, profiles, [f"robot.look('{position}')"],
                      goals=[{"kind": "looks", "position": "up_center"}], **HOBBIT))
    assert goal.passed is passed


@pytest.mark.parametrize("pose, passed", [("table", True), ("floor", False)])
def test_arm_at(tmp_path, profiles, pose, passed):
    goal = only(check(tmp_path, profiles, [f"robot.move_arm('{pose}')"], goals=[{"kind": "arm_at", "pose": "table"}],
                      **HOBBIT))
    assert goal.passed is passed
    if passed:
        assert "after 4.0 s" in goal.words("en")   # the arm server's 4 s, in simulated time


@pytest.mark.parametrize("movement, passed", [("open", True), ("close", False)])
def test_gripper(tmp_path, profiles, movement, passed):
    goal = only(check(tmp_path, profiles, [f"robot.gripper('{movement}')"],
                      goals=[{"kind": "gripper", "state": "open"}], **HOBBIT))
    assert goal.passed is passed


@pytest.mark.parametrize("line, passed", [("robot.ask_yes_no('Shall I bring tea?')", True),
                                          ("robot.show_info('Shall I bring tea?')", False)])
def test_asks(tmp_path, profiles, line, passed):
    goal = only(check(tmp_path, profiles, [line], goals=[{"kind": "asks", "contains": "tea"}], **HOBBIT))
    assert goal.passed is passed


@pytest.mark.parametrize("line, passed", [("robot.show_info('Hello!')", True), ("robot.show_info('Bye')", False)])
def test_shows_text(tmp_path, profiles, line, passed):
    goal = only(check(tmp_path, profiles, [line], goals=[{"kind": "shows_text", "contains": "hello"}], **HOBBIT))
    assert goal.passed is passed


@pytest.mark.parametrize("first, then, passed", [("show_emotion('HAPPY')", "ask_yes_no('Tea?')", True),
                                                 ("ask_yes_no('Tea?')", "show_emotion('HAPPY')", False)])
def test_a_face_before_a_question_in_the_same_tick(tmp_path, profiles, first, then, passed):
    goals = [{"kind": "shows_emotion", "emotion": "HAPPY", "id": "smile"}, {"kind": "asks", "id": "ask"},
             {"kind": "before", "first": "smile", "then": "ask"}]
    result = check(tmp_path, profiles, [f"robot.{first}", f"robot.{then}"], goals=goals, **HOBBIT)
    assert result.goals[2].passed is passed


@pytest.mark.parametrize("x, passed", [(3.5, True), (1.0, False)])
def test_hobbit_navigates_into_the_kitchen(tmp_path, profiles, x, passed):
    goal = only(check(tmp_path, profiles, [f"robot.navigate_to({x}, 0, 0)"],
                      goals=[{"kind": "ends_in", "area": "kitchen"}], areas=KITCHEN, **HOBBIT))
    assert goal.passed is passed


# --- the TurtleBot's own kind ---------------------------------------------------------------


def test_follows_wall(tmp_path, profiles):
    goal = {"kind": "follows_wall", "side": "right", "metres": 1.5, "gap": 0.4}
    along = only(check(tmp_path / "a", profiles, ["robot.drive(2.0)"], goals=[goal], robot="turtlebot",
                       start=[0, -1.2, 0]))
    assert along.passed
    away = only(check(tmp_path / "b", profiles, ["robot.drive(2.0)"], goals=[goal], robot="turtlebot",
                      start=[0, -0.6, 0]))
    assert not away.passed and away.words("en").startswith("TurtleBot followed the wall for only 0.0 m")


def test_a_block_costs_simulated_time():
    assert 0 < BLOCK_SECONDS <= 0.01
