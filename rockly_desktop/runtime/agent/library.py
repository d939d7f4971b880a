"""The agent's library: the programs kept on the robot, one folder each in the library folder.

    LIBRARY/NAME/program.py      the standalone export that runs (``rockly export --standalone``)
    LIBRARY/NAME/program.rockly  the program as the window opens it (when the sender had it)
    LIBRARY/NAME/about.json      name, profile and its version, when it came, what a lost editor means, who sent it,
                                 whether its code is what its blocks generate (``agent.source_match``)

A program is checked before it is kept, as a file Rockly opens is: its ``.rockly`` text must parse and name
the same profile; the standalone file must hold a program of a profile installed here, in a version not
newer than the installed one, and of a format this runtime reads.
"""
import ast
import json
import os
import re
import secrets
import shutil
import tempfile
import threading
from datetime import datetime, timezone
from pathlib import Path

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.program import parse_program
from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.core.workspace_checks import workspace_problem
from rockly_desktop.recording.mcap_file import disk_full
from rockly_desktop.runtime import standalone
from rockly_desktop.runtime.agent.program_check import standalone_parts
from rockly_desktop.runtime.agent.protocol import DEFAULT_DECIDE_SECONDS, LOST_EDITOR_CHOICES, AgentRefusal
from rockly_desktop.runtime.agent.source_match import first_state

NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.\- ]{0,63}$")
STANDALONE, SOURCE, ABOUT = "program.py", "program.rockly", "about.json"
VERSION = re.compile(r"^[0-9A-Za-z][0-9A-Za-z.+\-]{0,39}$")
DEFAULT_QUOTA_BYTES = 256 * 1024 * 1024  # the library's programs in all: some 80 programs of 10,000 blocks


def standalone_program(text: str) -> tuple:
    """``(PROGRAM, RUN_CODE)`` of a standalone file's text, read as data (nothing in it runs)."""
    try:
        tree = parse_python(text)
    except (SyntaxError, ValueError):
        raise AgentRefusal("agent_not_standalone") from None
    found = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            try:
                found[node.targets[0].id] = ast.literal_eval(node.value)
            except ValueError:
                continue
    program, run_code = found.get("PROGRAM"), found.get("RUN_CODE")
    if not isinstance(program, dict) or not isinstance(run_code, str) or not isinstance(program.get("profile"), dict):
        raise AgentRefusal("agent_not_standalone")
    return program, run_code


def version_tuple(version: str) -> tuple:
    """``"1.2.0"`` as ``(1, 2, 0)`` for comparing (parts that are not numbers count as 0)."""
    return tuple(int(part) if part.isdigit() else 0 for part in str(version).split("."))


class Library:
    """The programs in ``folder``; ``profiles``: the installed profiles (id -> profile)."""

    def __init__(self, folder: Path, profiles: dict, quota_bytes: int = DEFAULT_QUOTA_BYTES):
        self.folder = Path(folder)
        self.profiles = profiles
        self.quota_bytes = quota_bytes
        self._writing = threading.Lock()  # a program replaced and a note on it written never cross

    def entries(self) -> list:
        """What is known of each kept program (its ``about.json``), by name."""
        found = []
        for about in sorted(self.folder.glob(f"*/{ABOUT}")):
            if about.parent.name.startswith("."):  # one being written or replaced
                continue
            try:
                found.append(json.loads(about.read_text(encoding="utf-8")))
            except (OSError, ValueError):
                continue  # a program half written when the robot lost power: not listed
        return found

    def about(self, name: str) -> dict:
        """The ``about.json`` of program ``name``; refused when there is none."""
        try:
            return json.loads((self._folder_of(name) / ABOUT).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            raise AgentRefusal("agent_no_such_program", name=name) from None

    def standalone_path(self, name: str) -> Path:
        """The standalone file of program ``name``."""
        self.about(name)
        return self._folder_of(name) / STANDALONE

    def keep(self, name: str, standalone_text: str, source_text: str = None, on_lost_editor: str = "stop",
             decide_seconds: float = DEFAULT_DECIDE_SECONDS) -> dict:
        """Check and keep a program (replacing one of the same name); returns its ``about.json``."""
        return self.store(self.check(name, standalone_text, source_text, on_lost_editor, decide_seconds))

    def check(self, name: str, standalone_text: str, source_text: str = None, on_lost_editor: str = "stop",
              decide_seconds: float = DEFAULT_DECIDE_SECONDS) -> dict:
        """What ``store`` keeps of a program, checked (the standalone text read in a child process: see
        ``program_check``); nothing is written. AgentRefusal says what is wrong."""
        self._folder_of(name)
        if not isinstance(on_lost_editor, str) or on_lost_editor not in LOST_EDITOR_CHOICES:
            raise AgentRefusal("agent_bad_lost_editor", choice=str(on_lost_editor)[:40],
                               choices=", ".join(LOST_EDITOR_CHOICES))
        if not isinstance(decide_seconds, (int, float)) or isinstance(decide_seconds, bool) or not (
                0 < decide_seconds <= 600):
            raise AgentRefusal("agent_bad_decide_seconds", seconds=str(decide_seconds)[:40])
        if source_text is not None and not isinstance(source_text, str):
            raise AgentRefusal("agent_bad_request")
        program, _ = standalone_parts(standalone_text)
        profile = self._check_profile(program)
        if source_text is not None:
            self._check_source(source_text, profile.id)
        about = {"name": name, "profile": profile.id, "profile_version": program["profile"]["version"],
                 "received": datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
                 "rockly": program.get("rockly"), "source": program.get("source"),
                 "on_lost_editor": on_lost_editor, "decide_seconds": float(decide_seconds),
                 "has_source": source_text is not None}
        return {"about": about, STANDALONE: standalone_text, SOURCE: source_text}

    def store(self, checked: dict, sender: str = "?", owner: dict = None) -> dict:
        """Keep a program ``check`` gave (replacing one of the same name: its ``about.json`` then says whose it
        replaced and when, ``replaced``), within the library's quota; returns its ``about.json``. ``owner``: the
        paired client that sent it (``{"client": id, "role": role}``), whom the agent lets replace it."""
        about = dict(checked["about"], sender=str(sender)[:80], kept=secrets.token_hex(8),
                     **first_state(checked[SOURCE] is not None))
        if owner is not None:
            about["owner"] = owner
        folder = self._folder_of(about["name"])
        try:
            previous = self.about(about["name"])
            about["replaced"] = {"sender": previous.get("sender", "?"), "received": previous.get("received")}
        except AgentRefusal:
            pass
        texts = {file_name: checked[file_name] for file_name in (STANDALONE, SOURCE)}
        texts[ABOUT] = json.dumps(about, indent=1, ensure_ascii=False) + "\n"
        incoming = sum(len(text.encode("utf-8", "surrogatepass")) for text in texts.values() if text is not None)
        if self._bytes_kept(besides=folder) + incoming > self.quota_bytes:
            raise AgentRefusal("agent_library_full", name=about["name"], megabytes=self.quota_bytes // 2**20)
        with self._writing:
            self._replace(folder, texts)
        return about

    def texts(self, name: str, kept: str):
        """``(standalone text, .rockly text)`` of program ``name`` as it was kept as ``kept`` (its ``about.json``'s
        id of that keeping); None when it was replaced or deleted since, or came without a source."""
        try:
            if self.about(name).get("kept") != kept:
                return None
            folder = self._folder_of(name)
            return ((folder / STANDALONE).read_text(encoding="utf-8"), (folder / SOURCE).read_text(encoding="utf-8"))
        except (AgentRefusal, OSError, ValueError):
            return None

    def note(self, name: str, kept: str, fields: dict) -> bool:
        """Add ``fields`` to the ``about.json`` of program ``name`` if it is still the one kept as ``kept``;
        whether it was."""
        with self._writing:
            try:
                about = self.about(name)
            except AgentRefusal:
                return False
            if about.get("kept") != kept:
                return False
            about.update(fields)
            path = self._folder_of(name) / ABOUT
            incoming = path.with_name("." + ABOUT + ".incoming")
            try:
                incoming.write_text(json.dumps(about, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
                os.replace(incoming, path)
            except OSError:
                return False
            return True

    def _bytes_kept(self, besides: Path) -> int:
        """The bytes of every file in the library but those of ``besides`` (the folder a program replaces)."""
        total = 0
        for path in self.folder.glob("*/*"):
            if path.parent == besides:
                continue
            try:
                total += path.stat().st_size
            except OSError:
                continue
        return total

    def source(self, name: str):
        """The ``.rockly`` text of program ``name`` (None when it came without one)."""
        self.about(name)
        path = self._folder_of(name) / SOURCE
        return path.read_text(encoding="utf-8") if path.exists() else None

    def delete(self, name: str):
        """Remove program ``name`` from the library."""
        self.about(name)
        shutil.rmtree(self._folder_of(name))

    def _replace(self, folder: Path, texts: dict):
        """Make ``folder`` hold ``texts`` (file name -> text, None: no such file) whole or not at all: they are
        written into a new folder beside it first, which then takes its place."""
        incoming = None
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            incoming = Path(tempfile.mkdtemp(prefix=".incoming-", dir=self.folder))
            for file_name, text in texts.items():
                if text is not None:
                    with open(incoming / file_name, "w", encoding="utf-8") as stream:
                        stream.write(text)
                        stream.flush()
                        os.fsync(stream.fileno())
            previous = folder.with_name(".previous-" + incoming.name) if folder.exists() else None
            if previous is not None:
                os.rename(folder, previous)
            os.rename(incoming, folder)
            incoming = None
            if previous is not None:
                shutil.rmtree(previous, ignore_errors=True)
        except OSError as error:
            if disk_full(error):
                raise AgentRefusal("agent_disk_full", name=folder.name) from None
            raise AgentRefusal("agent_cannot_keep", name=folder.name, reason=error.strerror or str(error)) from None
        except UnicodeEncodeError as error:  # half an emoji: not UTF-8
            raise AgentRefusal("agent_cannot_keep", name=folder.name, reason=error.reason) from None
        finally:
            if incoming is not None:
                shutil.rmtree(incoming, ignore_errors=True)

    def _folder_of(self, name) -> Path:
        if (not isinstance(name, str) or not NAME.match(name) or name != name.strip() or name.strip(". ") != name
                or ".." in name):  # "demo " beside "demo" would look like one program and be two
            raise AgentRefusal("agent_bad_name", name=str(name)[:80])
        return self.folder / name

    def _check_profile(self, program: dict):
        if not isinstance(program.get("format", standalone.FORMAT), int):
            raise AgentRefusal("agent_not_standalone")
        if program.get("format", standalone.FORMAT) > standalone.FORMAT:
            raise AgentRefusal("agent_newer_format", rockly=program.get("rockly", "?"))
        wanted = program["profile"]
        if not isinstance(wanted.get("id"), str) or not isinstance(wanted.get("version"), str) or not (
                VERSION.match(wanted["version"])):
            raise AgentRefusal("agent_not_standalone")
        profile = self.profiles.get(wanted.get("id"))
        if profile is None:
            raise AgentRefusal("agent_no_profile", profile=wanted.get("id"), version=wanted.get("version"),
                               installed=", ".join(f"{p.id} {p.version}" for p in self.profiles.values()) or "-")
        if version_tuple(wanted.get("version")) > version_tuple(profile.version):
            raise AgentRefusal("agent_newer_profile", profile=profile.id, version=wanted.get("version"),
                               installed=profile.version)
        return profile

    @staticmethod
    def _check_source(text: str, profile_id: str):
        try:
            program = parse_program(text, "program.rockly")
        except RocklyError as error:
            raise AgentRefusal("agent_source_broken",
                               problem={"en": error.in_language("en"), "de": error.in_language("de")}) from None
        problem = workspace_problem(program.workspace)
        if problem is not None:
            raise AgentRefusal("agent_source_broken", problem=str(problem))
        if program.profile_id != profile_id:
            raise AgentRefusal("agent_other_profile", profile=program.profile_id, exported=profile_id)
