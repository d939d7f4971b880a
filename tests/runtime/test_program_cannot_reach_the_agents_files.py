"""A program the agent runs neither reads nor changes the agent's files (issue 30, ``program_process.isolate``): a
paired student's hand-made program that reads the agent's pairings (every laptop's key) and TLS key, lists the
other programs and writes into the library and over the robot's own limits finds an empty, read-only folder, and
the agent's files are as they were after it ran."""
import json
import re

import pytest
from agent_tools import AgentProcess
from program_builder import block, number, stack
from standalone_tools import exported_program
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.runtime.agent.pairings import agent_folder

PRYING = """import os
for path in {paths!r}:
    try:
        with open(path) as opened:
            print('read ' + path + ': ' + opened.read()[:40])
    except OSError as error:
        print('cannot read ' + path + ': ' + type(error).__name__)
for folder in {folders!r}:
    try:
        print('listed ' + folder + ': ' + ' '.join(sorted(os.listdir(folder))))
    except OSError as error:
        print('cannot list ' + folder + ': ' + type(error).__name__)
    try:
        with open(os.path.join(folder, 'planted.json'), 'w') as planted:
            planted.write('{{}}')
        print('wrote into ' + folder)
    except OSError as error:
        print('cannot write into ' + folder + ': ' + type(error).__name__)
"""


@pytest.fixture
def prying_program(tmp_path):
    """The standalone text of a short program (its code is replaced by the prying one)."""
    standalone, _source = exported_program(tmp_path, stack(block("hobbit_wait", inputs={"seconds": number(0)})))
    return standalone.read_text()


def test_a_program_finds_the_agents_library_keys_and_limits_empty_and_read_only(tmp_path, prying_program):
    library, limits = tmp_path / "library", tmp_path / "robot" / "robot-limits.json"
    limits.parent.mkdir()
    limits.write_text(json.dumps({"max_speed": 0.2}))
    agent = AgentProcess(library, "--robot-limits", limits)
    secrets = agent_folder(library)
    try:
        paths = [str(secrets / "pairings.json"), str(limits)] + [str(path) for path in secrets.glob("*.pem")]
        code = PRYING.format(paths=paths, folders=[str(library), str(secrets), str(limits.parent)])
        text = re.sub(r'RUN_CODE = """.*?"""', lambda _: f'RUN_CODE = """{code}"""', prying_program, flags=re.S)
        events = []
        client = AgentClient("127.0.0.1", agent.port, on_event=events.append)
        try:
            client.send("other", prying_program)
            client.send("prying", text)
            before = {path: path.read_bytes() for path in [*library.rglob("*"), limits] if path.is_file()}
            client.attach()
            client.start("prying")
            eventually(lambda: any(event.get("event") == "run" and event.get("state") == "ended"
                                   for event in list(events)), 60)
        finally:
            client.close()
        printed = [event["text"] for event in events if event.get("event") == "print"]
        assert len(printed) == len(paths) + 6, printed
        assert all(line.startswith("cannot read ") for line in printed[:len(paths)]), printed
        assert all(line.startswith("listed ") and line.endswith(": ")
                   or line.startswith(("cannot list ", "cannot write into ")) for line in printed[len(paths):]), printed
        after = {path: path.read_bytes() for path in [*library.rglob("*"), limits] if path.is_file()}
        changed = {path for path in set(before) | set(after) if before.get(path) != after.get(path)}
        assert all(path.name in ("about.json", "pairings.json") or "pairing-codes" in path.parts
                   for path in changed), changed  # the agent's own notes; nothing the program wrote
        assert not [path for path in after if path.name == "planted.json"]
    finally:
        agent.stop()
