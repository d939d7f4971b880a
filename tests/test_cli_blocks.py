"""``rockly blocks``: blocks made from the command line into a block pack run on HOBBIT's simulator
(real processes, real files in the test's own XDG data folder), and the pack validates, exports,
imports and travels with the programs that use it."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from program_builder import block, number, rockly_document, stack, text

REPO = Path(__file__).resolve().parents[1]
PACK = "hobbit_made"


def rockly(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=REPO, env={**os.environ})


def make(*options):
    result = rockly("blocks", "make", "--profile", "hobbit", "--pack", PACK, "--colour", "#4c97ff",
                    "--category-en", "Made", "--category-de", "Gemacht", "--language", "en", *options)
    assert result.returncode == 0, result.stderr
    return result


def pack_dir():
    return Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / PACK


@pytest.fixture
def made_pack():
    """A pack with a block of every kind, each made by ``rockly blocks make``."""
    make("--id", "drive_at", "--kind", "publish", "--interface", "/cmd_vel", "--type", "geometry_msgs/Twist",
         "--input", "speed=linear.x", "--range", "speed=0:0.3", "--default", "speed=0.1", "--unit", "speed=m/s",
         "--fixed", "angular.z=0", "--sentence-en", "drive at %1", "--sentence-de", "fahre mit %1")
    make("--id", "x_position", "--kind", "sensor_value", "--interface", "/odom", "--type", "nav_msgs/Odometry",
         "--read-field", "pose.pose.position.x", "--sentence-en", "x position", "--sentence-de", "x-Position")
    make("--id", "wait_x_above", "--kind", "wait_until", "--interface", "/odom", "--type", "nav_msgs/Odometry",
         "--read-field", "pose.pose.position.x", "--comparison", "above", "--input", "metres",
         "--sentence-en", "wait until x is above %1", "--sentence-de", "warte bis x über %1 ist")
    make("--id", "louder", "--kind", "call_service", "--interface", "/MMUI", "--type", "hobbit_msgs/Request",
         "--fixed", "params=[{name: type, value: F_LOUDER}]", "--sentence-en", "louder", "--sentence-de", "lauter")
    make("--id", "arm_to", "--kind", "send_goal", "--interface", "hobbit_arm", "--type", "hobbit_msgs/ArmServerAction",
         "--input", "movement=command.data", "--default", "movement=OpenGripper", "--result", "outcome",
         "--sentence-en", "outcome of moving the arm to %1", "--sentence-de", "Ergebnis der Armbewegung zu %1")
    make("--id", "set_level", "--kind", "set_param", "--interface", "/made/level", "--input", "level:number",
         "--sentence-en", "set the level to %1")
    make("--id", "level", "--kind", "get_param", "--interface", "/made/level", "--sentence-de", "Stufe")
    return pack_dir()


def printed(result):
    return [line.split(None, 1)[1] for line in result.stdout.splitlines() if line.startswith("print ")]


def test_made_blocks_of_every_kind_run_on_the_simulator_and_do_what_they_say(tmp_path, made_pack):
    program = tmp_path / "made.rockly"
    program.write_text(rockly_document([stack(
        block("drive_at", inputs={"speed": number(0.2)}, id="drive"),
        block("wait_x_above", inputs={"metres": number(0.05)}, id="wait"),
        block("drive_at", inputs={"speed": number(0)}, id="halt"),
        block("text_print", inputs={"TEXT": block("x_position")}, id="x"),
        block("louder", id="louder"),
        block("text_print", inputs={"TEXT": block("arm_to", inputs={"movement": text("OpenGripper")})}, id="arm"),
        block("set_level", inputs={"level": number(7)}, id="set"),
        block("text_print", inputs={"TEXT": block("level")}, id="get"),
    )]))
    result = rockly("run", program, "--speed", "20", "--language", "en")
    assert result.returncode == 0, result.stderr
    x, outcome, level = printed(result)
    assert float(x) > 0.05  # the Twist the made block published moved the simulated robot, the sensor read it
    assert outcome == "succeeded"
    assert level == "7"
    assert "tablet  notice: 'volume" in result.stdout  # the service call reached the simulated tablet


def test_a_made_input_outside_its_range_stops_the_program_on_its_block(tmp_path, made_pack):
    program = tmp_path / "fast.rockly"
    program.write_text(rockly_document([block("drive_at", inputs={"speed": number(5)}, id="fast")]))
    result = rockly("run", program, "--speed", "20", "--language", "de")
    assert result.returncode == 1
    assert "Die Eingabe 'speed' muss von 0 bis 0,3 gehen, nicht 5" in result.stderr


def test_the_pack_validates_lists_and_survives_export_and_import(tmp_path, made_pack):
    validated = rockly("profiles", "validate", made_pack)
    assert validated.returncode == 0, validated.stderr
    assert f"OK  block pack {PACK}" in validated.stdout and "7 blocks" in validated.stdout
    listed = rockly("blocks", "list", PACK, "--language", "de")
    assert listed.returncode == 0, listed.stderr
    assert "louder" in listed.stdout and "call_service /MMUI hobbit_msgs/Request" in listed.stdout
    assert "fahre mit %1" in listed.stdout and "set the level to %1" in listed.stdout  # no German: the English
    installed = rockly("blocks", "list")
    assert installed.returncode == 0 and installed.stdout.split()[:3] == [PACK, "1.0.6", "hobbit"]
    archive = tmp_path / "made.zip"
    assert rockly("blocks", "export", PACK, "-o", archive).returncode == 0
    files = {path.name: path.read_bytes() for path in made_pack.iterdir()}
    again = rockly("blocks", "import", archive, "--language", "en")
    assert again.returncode == 1 and "is installed already; nothing was imported" in again.stderr
    for path in made_pack.iterdir():
        path.unlink()
    made_pack.rmdir()
    imported = rockly("blocks", "import", archive)
    assert imported.returncode == 0, imported.stderr
    assert {path.name: path.read_bytes() for path in made_pack.iterdir()} == files


def test_a_program_records_its_pack_exports_and_without_the_pack_says_which_is_missing(tmp_path, made_pack):
    from rockly_desktop.core.program import load_program, save_program
    from rockly_desktop.profiles.registry import ProfileRegistry

    workspace = {"blocks": {"languageVersion": 0, "blocks": [
        block("drive_at", inputs={"speed": number(0.2)}, id="drive")]}}
    profile = ProfileRegistry.discover().get("hobbit")
    from rockly_desktop.core.program import Program

    path = tmp_path / "uses_pack.rockly"
    save_program(path, Program("hobbit", workspace, [], profile.packs_used(workspace)))
    version = (made_pack / "pack.yaml").read_text().split("version: ")[1].split()[0].strip("'\"")
    assert json.loads(path.read_text())["packs"] == {PACK: version}
    assert load_program(path).packs == {PACK: version}
    out = tmp_path / "uses_pack.py"
    exported = rockly("export", path, "-o", out)
    assert exported.returncode == 0, exported.stderr
    assert ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', "
            "{'angular': {'z': 0}, 'linear': {'x': ros.number_in(0.2, 0, 0.3, 'speed')}})") in out.read_text()
    for child in made_pack.iterdir():
        child.unlink()
    made_pack.rmdir()
    before = path.read_bytes()
    refused = rockly("export", path, "-o", out, "--language", "de")
    assert refused.returncode == 1
    assert f"Blockpaket '{PACK}' {version}, das nicht installiert ist" in refused.stderr
    assert path.read_bytes() == before


def test_bad_choices_each_say_what_is_wrong_and_write_nothing(made_pack):
    files = {path.name: path.read_bytes() for path in made_pack.iterdir()}
    cases = [
        (["--id", "drive_at", "--kind", "get_param", "--interface", "/x", "--sentence-en", "x"],
         "the block pack 'hobbit_made' already has a block 'drive_at'"),
        (["--id", "hobbit_move", "--kind", "get_param", "--interface", "/x", "--sentence-en", "x"],
         "the robot profile 'hobbit' already has a block 'hobbit_move'"),
        (["--id", "say", "--kind", "publish", "--interface", "/say", "--type", "std_msgs/String",
          "--input", "words=data", "--sentence-en", "say %1 and %2"],
         "must have each of %1 to %1 once, one per input (it has: %1, %2)"),
        (["--id", "gone", "--kind", "publish", "--interface", "/gone", "--type", "gone_msgs/Gone",
          "--sentence-en", "gone"], "Rockly does not know the type 'gone_msgs/Gone'"),
        (["--id", "typo", "--kind", "publish", "--interface", "/cmd_vel", "--type", "geometry_msgs/Twist",
          "--input", "s=linear.q", "--sentence-en", "go %1"], "geometry_msgs/Twist has no field 'linear.q'"),
    ]
    for options, message in cases:
        result = rockly("blocks", "make", "--profile", "hobbit", "--pack", PACK, "--colour", "#4c97ff",
                        "--category-en", "Made", "--language", "en", *options)
        assert result.returncode == 1, options
        assert message in result.stderr, result.stderr
    german = rockly("blocks", "make", "--profile", "hobbit", "--pack", PACK, "--colour", "red", "--language", "de",
                    "--id", "x2", "--kind", "get_param", "--interface", "/x", "--sentence-en", "x")
    assert german.returncode == 1
    assert "'red' ist keine Farbe" in german.stderr and "nenne die Kategorie" in german.stderr
    elsewhere = rockly("blocks", "make", "--profile", "nobody", "--pack", "other", "--id", "x", "--kind", "get_param",
                       "--interface", "/x", "--sentence-en", "x", "--colour", "#4c97ff", "--category-en", "M",
                       "--language", "en")
    assert elsewhere.returncode == 1
    assert "adds to the robot profile 'nobody', which is not installed" in elsewhere.stderr
    assert {path.name: path.read_bytes() for path in made_pack.iterdir()} == files
    assert sorted(path.name for path in made_pack.parent.iterdir()) == [PACK]


def test_a_teachers_limits_hold_for_made_blocks_as_for_every_block(tmp_path, made_pack, isolated_user_folders):
    from rockly_desktop.settings.app_settings import AppSettings

    make("--id", "speed", "--kind", "sensor_value", "--interface", "/odom", "--type", "nav_msgs/Odometry",
         "--read-field", "twist.twist.linear.x", "--sentence-en", "speed")
    make("--id", "wait_moving", "--kind", "wait_until", "--interface", "/odom", "--type", "nav_msgs/Odometry",
         "--read-field", "twist.twist.linear.x", "--comparison", "above", "--target", "0.05",
         "--sentence-en", "wait until moving")
    settings = AppSettings(isolated_user_folders / "config" / "Rockly" / "Rockly.conf")  # where the window keeps them
    settings.teacher.set_limits("hobbit", max_speed=0.1, switched_off={"arm"})
    settings.sync()
    program = tmp_path / "limited.rockly"
    program.write_text(rockly_document([stack(
        block("drive_at", inputs={"speed": number(0.3)}, id="drive"),
        block("wait_moving", id="moving"),
        block("hobbit_wait", inputs={"seconds": number(1)}, id="wait"),
        block("text_print", inputs={"TEXT": block("speed")}, id="speed"),
        block("text_print", inputs={"TEXT": block("arm_to", inputs={"movement": text("OpenGripper")})}, id="arm"),
    )]))
    result = rockly("run", program, "--speed", "5", "--language", "en")
    assert result.returncode == 1
    speed = float(next(text for text in printed(result) if "limit" not in text.lower()))
    assert 0.05 < speed <= 0.1  # the made block asked for 0.3 m/s; the simulated base got the teacher's 0.1
    assert "error in block arm (text_print)" in result.stderr and "switched off" in result.stderr
