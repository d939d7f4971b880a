"""Who may use the agent (issue 30): the agent (``rockly agent`` in a process of its own on 127.0.0.1) against a
stranger speaking its wire protocol directly, pairing codes that are wrong, expired, used or guessed at, a
revoked laptop, a student's laptop beside the teacher's, an old plain-TCP client, and a laptop meeting a
certificate other than the one it paired with."""
import os
import stat
import subprocess
import sys
import threading
import time

import pytest
from agent_tools import REPO, AgentProcess
from agent_wire import answers, closed_by_agent, hello, plain_connection, say, tls_connection
from program_builder import block, number
from standalone_tools import exported_program
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.pairings import CODE_SECONDS, WRONG_GUESSES_PER_MINUTE, Pairings, agent_folder
from rockly_desktop.runtime.agent.protocol import AgentRefusal
from rockly_desktop.runtime.agent.robot_keys import RobotKey, RobotKeys, tcp_address

GATED = [{"op": "send", "name": "innocent", "standalone": "PROGRAM = {}\nRUN_CODE = 'open(\"/tmp/x\", \"w\")'\n"},
         {"op": "start", "name": "demo"}, {"op": "list"}, {"op": "source", "name": "demo"},
         {"op": "delete", "name": "demo"}, {"op": "attach", "control": True, "breakpoints": []},
         {"op": "control", "what": "pause"}, {"op": "breakpoints", "blocks": []}, {"op": "stop"},
         {"op": "detach"}, {"op": "heartbeat"}, {"op": "pairing_code"}, {"op": "robot_limits"}]


@pytest.fixture(scope="module")
def program(tmp_path_factory):
    """The standalone text of a program that drives for a while (4 s of simulated time)."""
    path, _ = exported_program(tmp_path_factory.mktemp("pairing-program"), block(
        "hobbit_move", {"direction": "+"}, {"speed": number(0.25)}, id="drive"))
    return path.read_text()


@pytest.fixture
def agent(tmp_path):
    agent = AgentProcess(tmp_path / "library")
    yield agent
    agent.stop()


@pytest.fixture
def fresh_agent(tmp_path):
    """An agent nobody is paired with."""
    agent = AgentProcess(tmp_path / "library", paired=False)
    yield agent
    agent.stop()


def stranger(agent, key=None):
    """A TLS connection that has said hello (proving ``key`` when given)."""
    connection, nonce = tls_connection(agent.port)
    say(connection, hello(nonce, key))
    assert answers(connection, 1)[0]["ok"]
    return connection


def ask(connection, request: dict, number: int = 1) -> dict:
    say(connection, {**request, "id": number})
    return answers(connection, 1)[0]


def pair_on_the_wire(connection, code: str, number: int = 1) -> dict:
    return ask(connection, {"op": "pair", "code": code, "name": "stranger"}, number)


def test_before_pairing_only_hello_and_pair_are_answered(agent):
    connection = stranger(agent)
    with connection:
        for number, request in enumerate(GATED, start=1):
            answer = ask(connection, request, number)
            assert (answer["reply"], answer["ok"], answer["error"]) == (number, False, "agent_not_paired"), request
            assert "rockly agent pair" in answer["message"]
    teacher = AgentClient("127.0.0.1", agent.port)
    try:
        assert teacher.programs() == {"programs": [], "run": None}  # the stranger's send kept nothing
    finally:
        teacher.close()


def test_a_hello_with_a_wrong_proof_pairs_nothing(agent):
    forged = RobotKey("", "", agent.key.client, b"x" * 32, "teacher", "")
    connection, nonce = tls_connection(agent.port)
    with connection:
        say(connection, hello(nonce, forged))
        assert answers(connection, 1)[0]["paired"] is None
        assert ask(connection, {"op": "list"})["error"] == "agent_not_paired"
    connection, _ = tls_connection(agent.port)  # a proof over another connection's nonce: a replay
    with connection:
        say(connection, hello(nonce, agent.key))
        assert answers(connection, 1)[0]["paired"] is None


def test_a_wrong_code_is_refused_and_five_wrong_guesses_end_the_code(fresh_agent):
    code = fresh_agent.new_code()
    connection = stranger(fresh_agent)
    with connection:
        for number in range(1, 6):
            assert pair_on_the_wire(connection, "ZZZ-ZZZ" if code != "ZZZ-ZZZ" else "YYY-YYY", number)["error"] == (
                "agent_pair_wrong_code")
        refused = pair_on_the_wire(connection, code, 6)
    assert refused["error"] == "agent_pair_too_many_guesses" and "Wait a minute" in refused["message"]


def test_wrong_guesses_are_capped_per_minute_whatever_the_codes(fresh_agent):
    connection = stranger(fresh_agent)
    with connection:
        for number in range(1, WRONG_GUESSES_PER_MINUTE + 1):
            fresh_agent.new_code()  # a new code every time: the cap per code never ends one
            assert pair_on_the_wire(connection, "222-222", number)["error"] == "agent_pair_wrong_code"
        assert pair_on_the_wire(connection, fresh_agent.new_code(), 99)["error"] == "agent_pair_too_many_guesses"


def test_an_expired_code_is_refused(fresh_agent):
    made_long_ago = Pairings(agent_folder(fresh_agent.library), clock=lambda: time.monotonic() - CODE_SECONDS - 1)
    code = made_long_ago.new_code().shown
    connection = stranger(fresh_agent)
    with connection:
        refused = pair_on_the_wire(connection, code)
        assert refused["error"] == "agent_pair_code_expired" and "2 minutes" in refused["message"]
        assert ask(connection, {"op": "list"}, 2)["error"] == "agent_not_paired"


def test_a_code_works_once_and_the_first_laptop_is_a_teacher(fresh_agent):
    code = fresh_agent.new_code()
    first = stranger(fresh_agent)
    with first:
        paired = pair_on_the_wire(first, code)
        assert paired["ok"] and paired["role"] == "teacher" and len(paired["key"]) == 44  # 32 bytes, base64
        assert ask(first, {"op": "list"}, 2)["ok"]  # the connection that paired is paired
    second = stranger(fresh_agent)
    with second:
        assert pair_on_the_wire(second, code.lower().replace("-", ""))["error"] == "agent_pair_code_used"
        assert pair_on_the_wire(second, fresh_agent.new_code(), 2)["role"] == "student"  # a teacher is paired


def test_a_revoked_laptop_is_refused_at_once_and_its_open_connection_closed(agent):
    student = agent.pair(role="student", keys=RobotKeys(agent.library.parent / "student-keys.json"))
    connection = stranger(agent, student)
    assert ask(connection, {"op": "attach", "control": False})["ok"]
    revoked = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(agent.library),
                              "--language", "de", "revoke", student.client], capture_output=True, text=True,
                             timeout=120, cwd=REPO)
    assert revoked.returncode == 0, revoked.stderr
    assert "ist nicht mehr gekoppelt" in revoked.stdout
    started = time.monotonic()
    assert closed_by_agent(connection)
    assert time.monotonic() - started < 5
    again = stranger(agent, student)
    with again:
        assert ask(again, {"op": "list"})["error"] == "agent_not_paired"
    teacher = AgentClient("127.0.0.1", agent.port)  # the teacher's key still works
    try:
        assert teacher.programs()["programs"] == []
    finally:
        teacher.close()


def test_a_student_cannot_replace_the_teachers_demo_nor_pair_others_nor_lift_limits(agent, program):
    teacher = AgentClient("127.0.0.1", agent.port)
    student = AgentClient("127.0.0.1", agent.port, keys=RobotKeys(agent.library.parent / "student-keys.json"))
    try:
        teacher.send("demo", program)
        assert student.pair(teacher.pairing_code(role="student")["code"]).role == "student"
        for refused_call in (lambda: student.send("demo", program), lambda: student.delete("demo")):
            with pytest.raises(AgentError) as refused:
                refused_call()
            assert refused.value.key == "agent_not_yours" and "'demo' is not yours" in refused.value.message
        for op in ("pairing_code", "robot_limits"):
            with pytest.raises(AgentError) as refused:
                student.request(op, max_speed=None)
            assert refused.value.key == "agent_teacher_only"
        assert [about["owner"]["role"] for about in teacher.programs()["programs"]] == ["teacher"]
        student.send("mine", program)  # its own: sent, replaced, deleted
        student.send("mine", program)
        student.delete("mine")
        student.send("mine", program)
        teacher.delete("mine")  # a teacher may delete anyone's
        student.start("demo")  # the teacher's programs a student may start, and stop
        assert student.stop() is True
        eventually(lambda: teacher.programs()["run"] is None, 60)
        teacher.start("demo")  # a run the teacher started the student watches, and may stop, but not control
        assert student.attach(control=True)["controller"] is False
        with pytest.raises(AgentError) as refused:
            student.control("pause")
        assert refused.value.key == "agent_not_yours"
        assert student.stop() is True
    finally:
        student.close()
        teacher.close()


def test_a_plain_tcp_client_from_before_pairing_is_told_to_update_and_pair(agent):
    """What a format-1 Rockly sends first: its hello in plain JSON."""
    connection = plain_connection(agent.port)
    with connection:
        say(connection, hello(language="de", id=1, format=1, rockly="0.0.9"))
        answer = answers(connection, 1)
        assert answer and (answer[0]["reply"], answer[0]["error"]) == (1, "agent_client_before_pairing")
        assert answer[0]["message"].startswith("dieses Rockly (0.0.9) ist älter als der Agent des Roboters (Rockly ")
        assert "aktualisiere Rockly auf diesem Laptop und kopple ihn dann mit dem Roboter" in answer[0]["message"]
        assert closed_by_agent(connection)


def test_a_laptop_refuses_an_agent_whose_certificate_is_not_the_one_it_paired_with(agent, tmp_path):
    impostor = AgentProcess(tmp_path / "other-library", paired=False)  # another agent where the robot was
    try:
        keys = RobotKeys()
        keys.save(RobotKey(tcp_address("127.0.0.1", impostor.port), agent.key.agent, agent.key.client, agent.key.key,
                           agent.key.role, agent.key.fingerprint))
        with pytest.raises(AgentError) as refused:
            AgentClient("127.0.0.1", impostor.port)
        assert refused.value.key == "agent_other_certificate"
        assert "is not the one you paired with" in refused.value.message and "pair again" in refused.value.message
        assert impostor.process.poll() is None
    finally:
        impostor.stop()


def test_the_keys_are_kept_for_their_owner_only(agent):
    folder = agent_folder(agent.library)
    for path in (folder / "pairings.json", folder / "tls-key.pem", RobotKeys().path):
        assert stat.S_IMODE(os.stat(path).st_mode) == 0o600, path
    assert stat.S_IMODE(os.stat(folder).st_mode) == 0o700
    assert agent.key.client in (folder / "pairings.json").read_text()


def test_rockly_agent_pair_shows_a_code_and_the_fingerprint_rockly_robot_pair_takes_while_the_agent_runs(agent):
    made = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(agent.library),
                           "--language", "en", "pair", "--role", "student"], capture_output=True, text=True,
                          timeout=120, cwd=REPO)
    assert made.returncode == 0, made.stderr
    code = made.stdout.split("Pairing code: ")[1].split(" ")[0]
    fingerprint = made.stdout.split("This agent's certificate: ")[1][:19]
    assert "valid 2 minutes, once; the laptop pairs as student" in made.stdout
    RobotKeys().forget(agent.key.address)
    paired = agent.robot("pair", code, "--name", "pupil laptop", language="de")
    assert paired.returncode == 0, paired.stderr
    assert f"als Schüler. Sein Zertifikat: {fingerprint} " in paired.stdout
    assert agent.robot("list").returncode == 0
    listed = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(agent.library),
                             "--language", "en", "clients"], capture_output=True, text=True, timeout=120, cwd=REPO)
    assert [line.split("  ")[:2] for line in listed.stdout.splitlines()] == [["test laptop", "teacher"],
                                                                             ["pupil laptop", "student"]]
    again = agent.robot("pair", code)
    assert again.returncode == 1 and "this pairing code was used already" in again.stderr


def test_an_unpaired_rockly_robot_says_how_to_pair(fresh_agent):
    refused = fresh_agent.robot("list", language="de")
    assert refused.returncode == 1
    assert "dieser Laptop ist nicht mit dem Agenten des Roboters gekoppelt" in refused.stderr


def test_pairings_in_memory_expire_on_their_clock_and_the_guesses_cap_opens_after_a_minute(tmp_path):
    now = [1000.0]
    pairings = Pairings(tmp_path, clock=lambda: now[0])
    code = pairings.new_code()
    now[0] += CODE_SECONDS + 1
    with pytest.raises(AgentRefusal) as expired:
        pairings.pair(code.code, "late")
    assert expired.value.key == "agent_pair_code_expired"
    for _ in range(WRONG_GUESSES_PER_MINUTE):
        with pytest.raises(AgentRefusal):
            pairings.pair("2222", "guesser")
    fresh = pairings.new_code()
    with pytest.raises(AgentRefusal) as capped:
        pairings.pair(fresh.code, "teacher")
    assert capped.value.key == "agent_pair_too_many_guesses"
    now[0] += 61
    assert pairings.pair(fresh.code, "teacher").role == "teacher"
    kiosk = pairings.new_code("teacher")
    assert pairings.pair(kiosk.code, "kiosk", role="student").role == "student"  # less than the code gives
    pupil = pairings.new_code("student")
    assert pairings.pair(pupil.code, "pupil", role="teacher").role == "student"  # never more


def test_every_answer_arrives_over_tls_while_both_sides_read_and_write_at_once(agent):
    """Each side reads on one thread while others write (four threads' calls and the heartbeats; the agent's
    answers and beats). OpenSSL's connection object must not be used by two threads at once: a plain SSLSocket
    read and written so (benchmarks/agent_under_attack.py's client) lost an answer in some thousand; AgentClient
    and the agent take turns on it (tls.LockedTls)."""
    client = AgentClient("127.0.0.1", agent.port, timeout=5)
    answered = []

    def ask_many():
        for _ in range(1000):
            answered.append(client.programs() == {"programs": [], "run": None})
    try:
        client.attach(control=True)  # its heartbeats go out meanwhile
        askers = [threading.Thread(target=ask_many) for _ in range(4)]
        for asker in askers:
            asker.start()
        for asker in askers:
            asker.join(120)
        assert answered == [True] * 4000
    finally:
        client.close()


@pytest.mark.skipif(os.geteuid() != 0, reason="giving a folder to another user needs root")
def test_rockly_agent_pair_as_another_user_than_the_agents_is_refused(tmp_path):
    """root making a code for a service's agent (its own user): the agent could not read the code file."""
    library = tmp_path / "library"
    library.mkdir()
    os.chown(library, 65534, 65534)
    made = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(library), "--language",
                           "en", "pair"], capture_output=True, text=True, timeout=120, cwd=REPO)
    assert made.returncode == 1 and "run this command as that user ('sudo -u " in made.stderr, made.stderr
    assert not agent_folder(library).exists()
