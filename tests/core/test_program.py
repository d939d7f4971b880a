"""The .rockly program file: round trips on disk, atomic saving, and a clear error for every bad file."""
import errno
import json
import os
import stat
import tempfile
import threading
from pathlib import Path

import pytest

from rockly_desktop.core import program as program_module
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.program import (
    FORMAT_NAME,
    FORMAT_VERSION,
    Program,
    load_program,
    parse_program,
    save_program,
    write_text_atomically,
)

REPO = Path(__file__).resolve().parents[2]

TRICKY_TEXTS = [
    'He said "hello" and left',
    "it's HOBBIT's turn",
    "line one\nline two\r\nline three\ttabbed",
    "Grüße aus Wien, ß, Ä, 日本語, emoji 😀🤖",
    "back\\slash C:\\Users\\hobbit\\n (not a newline)",
    "</script><!-- --> & <xml>",
    "line\u2028separator and \u2029paragraph",
    "",
    "{not: json}, [also not]",
]


def hobbit_workspace(texts=TRICKY_TEXTS) -> dict:
    """A Blockly JSON workspace: a chain of show-info blocks whose texts are ``texts``."""
    chain = None
    for value in reversed(texts):
        block = {"type": "hobbit_show_info",
                 "inputs": {"text": {"shadow": {"type": "text", "fields": {"TEXT": value}}}}}
        if chain:
            block["next"] = {"block": chain}
        chain = block
    return {"blocks": {"languageVersion": 0, "blocks": [dict(chain, x=20, y=30)]},
            "variables": [{"name": "Grüße \"x\"", "id": "v1"}]}


def valid_document(**overrides) -> dict:
    document = {"format": FORMAT_NAME, "version": FORMAT_VERSION, "profile": "hobbit",
                "workspace": hobbit_workspace(["hello"])}
    document.update(overrides)
    return document


def snapshot(path: Path):
    """What must not change when a file is only read: its bytes and its modification time."""
    return path.read_bytes(), path.stat().st_mtime_ns


def files_in(folder: Path) -> list:
    return sorted(child.name for child in folder.iterdir())


# --- saving and loading -------------------------------------------------------------------


def test_saved_program_loads_back_equal_with_unicode_quotes_and_newlines(tmp_path):
    path = tmp_path / "tricky.rockly"
    original = Program("hobbit", hobbit_workspace())

    save_program(path, original)
    loaded = load_program(path)

    assert loaded == original
    texts = []
    block = loaded.workspace["blocks"]["blocks"][0]
    while block:
        texts.append(block["inputs"]["text"]["shadow"]["fields"]["TEXT"])
        block = (block.get("next") or {}).get("block")
    assert texts == TRICKY_TEXTS


def test_saved_file_is_readable_utf8_json_with_the_envelope_first(tmp_path):
    path = tmp_path / "hello.rockly"
    save_program(path, Program("hobbit", hobbit_workspace(["Grüße 😀"])))

    raw = path.read_bytes()
    assert "Grüße 😀".encode() in raw, "non-ASCII text is stored as itself, not as \\u escapes"
    assert raw.endswith(b"\n")
    document = json.loads(raw.decode("utf-8"))
    assert list(document) == ["format", "version", "profile", "workspace", "breakpoints"]
    assert (document["format"], document["version"], document["profile"]) == ("rockly-program", 1, "hobbit")


def test_saving_the_same_program_twice_gives_identical_bytes(tmp_path):
    first, second = tmp_path / "a.rockly", tmp_path / "b.rockly"
    save_program(first, Program("hobbit", hobbit_workspace()))
    save_program(second, Program("hobbit", hobbit_workspace()))
    assert first.read_bytes() == second.read_bytes()


def test_saving_over_an_existing_program_replaces_it(tmp_path):
    path = tmp_path / "prog.rockly"
    save_program(path, Program("hobbit", hobbit_workspace(["old"])))
    save_program(path, Program("hobbit", hobbit_workspace(["new"])))

    assert load_program(path).workspace == hobbit_workspace(["new"])
    assert files_in(tmp_path) == ["prog.rockly"]


def test_load_accepts_a_str_path_and_a_utf8_byte_order_mark(tmp_path):
    path = tmp_path / "bom.rockly"
    path.write_bytes(b"\xef\xbb\xbf" + json.dumps(valid_document()).encode("utf-8"))
    assert load_program(str(path)) == Program("hobbit", hobbit_workspace(["hello"]))


def test_example_program_from_the_repository_survives_a_round_trip(tmp_path):
    example = REPO / "examples" / "hobbit" / "tidy-up.rockly"
    if not example.is_file():
        pytest.skip("the example program is not in this checkout")
    program = load_program(example)
    assert program.profile_id == "hobbit"

    copy = tmp_path / "tidy-up.rockly"
    save_program(copy, program)
    assert load_program(copy) == program


def test_loading_a_good_file_does_not_change_it_or_its_folder(tmp_path):
    path = tmp_path / "prog.rockly"
    save_program(path, Program("hobbit", hobbit_workspace()))
    before = snapshot(path)

    load_program(path)

    assert snapshot(path) == before
    assert files_in(tmp_path) == ["prog.rockly"]


# --- atomic saving ----------------------------------------------------------------------


@pytest.fixture
def old_program(tmp_path):
    """An existing program file with known bytes, the only file in its folder."""
    path = tmp_path / "prog.rockly"
    save_program(path, Program("hobbit", hobbit_workspace(["the old program"])))
    return path


def test_failed_rename_leaves_old_file_byte_identical_and_no_temp_file(old_program, monkeypatch):
    old_bytes = old_program.read_bytes()

    def refuse(source, target):
        raise OSError(errno.EXDEV, "Invalid cross-device link")

    monkeypatch.setattr(program_module.os, "replace", refuse)
    with pytest.raises(ProgramFileError) as caught:
        save_program(old_program, Program("hobbit", hobbit_workspace(["the new program"])))

    assert old_program.read_bytes() == old_bytes
    assert files_in(old_program.parent) == ["prog.rockly"]
    assert caught.value.path == str(old_program)
    assert "could not be saved" in str(caught.value)
    assert "Invalid cross-device link" in str(caught.value)


def test_disk_full_while_writing_leaves_old_file_and_no_temp_file(old_program, monkeypatch):
    old_bytes = old_program.read_bytes()

    def disk_full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(program_module.os, "fsync", disk_full)
    with pytest.raises(ProgramFileError, match="No space left on device"):
        save_program(old_program, Program("hobbit", hobbit_workspace(["new"])))

    assert old_program.read_bytes() == old_bytes
    assert files_in(old_program.parent) == ["prog.rockly"]


def test_interrupted_save_removes_its_temp_file_and_lets_the_interrupt_through(old_program, monkeypatch):
    old_bytes = old_program.read_bytes()

    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(program_module.os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        save_program(old_program, Program("hobbit", hobbit_workspace(["new"])))

    assert old_program.read_bytes() == old_bytes
    assert files_in(old_program.parent) == ["prog.rockly"]


def test_half_an_emoji_is_saved_escaped_and_reads_back_the_same(old_program):
    lone_surrogate = "half an emoji \ud83d and a whole one \U0001f916"
    program = Program("hobbit", hobbit_workspace([lone_surrogate]))

    save_program(old_program, program)

    assert "\\ud83d" in old_program.read_text(encoding="utf-8")
    assert load_program(old_program).workspace == program.workspace
    assert files_in(old_program.parent) == ["prog.rockly"]


def test_folder_that_refuses_new_files_gives_a_clear_error(old_program, monkeypatch):
    old_bytes = old_program.read_bytes()

    def refuse(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(program_module.tempfile, "mkstemp", refuse)
    with pytest.raises(ProgramFileError, match=r"cannot write in this folder \(Permission denied\)"):
        save_program(old_program, Program("hobbit", {}))
    assert old_program.read_bytes() == old_bytes


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write into read-only folders")
def test_read_only_folder_keeps_the_old_file(old_program):
    old_bytes = old_program.read_bytes()
    folder = old_program.parent
    folder.chmod(0o555)
    try:
        with pytest.raises(ProgramFileError, match="cannot write in this folder"):
            save_program(old_program, Program("hobbit", hobbit_workspace(["new"])))
    finally:
        folder.chmod(0o755)
    assert old_program.read_bytes() == old_bytes
    assert files_in(folder) == ["prog.rockly"]


def test_saving_into_a_missing_folder_names_the_problem(tmp_path):
    target = tmp_path / "no such folder" / "prog.rockly"
    with pytest.raises(ProgramFileError, match=r"cannot write in this folder \(No such file or directory\)") as caught:
        save_program(target, Program("hobbit", {}))
    assert caught.value.path == str(target)
    assert not target.parent.exists()


def test_saving_onto_a_folder_fails_cleanly(tmp_path):
    target = tmp_path / "prog.rockly"
    target.mkdir()
    with pytest.raises(ProgramFileError, match="could not be saved"):
        save_program(target, Program("hobbit", {}))
    assert target.is_dir()
    assert files_in(tmp_path) == ["prog.rockly"]


@pytest.fixture
def temp_file_folders(monkeypatch) -> list:
    """The folders the program module makes its temporary files in, as it makes them."""
    folders = []
    real_mkstemp = tempfile.mkstemp

    def spy(*args, **kwargs):
        folders.append(Path(kwargs["dir"]))
        return real_mkstemp(*args, **kwargs)

    monkeypatch.setattr(program_module.tempfile, "mkstemp", spy)
    return folders


def test_temp_file_is_made_next_to_the_target_so_the_rename_is_atomic(tmp_path, temp_file_folders):
    save_program(tmp_path / "prog.rockly", Program("hobbit", {}))
    assert temp_file_folders == [tmp_path]


def test_existing_file_keeps_its_permission_bits(old_program):
    old_program.chmod(0o640)
    save_program(old_program, Program("hobbit", hobbit_workspace(["new"])))
    assert stat.S_IMODE(old_program.stat().st_mode) == 0o640

    old_program.chmod(0o604)
    write_text_atomically(old_program, "text")
    assert stat.S_IMODE(old_program.stat().st_mode) == 0o604


def test_new_file_gets_the_usual_permissions_not_private_temp_file_ones(tmp_path):
    previous = os.umask(0o022)
    try:
        save_program(tmp_path / "new.rockly", Program("hobbit", {}))
        os.umask(0o027)
        save_program(tmp_path / "group.rockly", Program("hobbit", {}))
    finally:
        os.umask(previous)
    assert stat.S_IMODE((tmp_path / "new.rockly").stat().st_mode) == 0o644
    assert stat.S_IMODE((tmp_path / "group.rockly").stat().st_mode) == 0o640


# --- links, FIFOs and devices: written through, never replaced -----------------------------


def test_saving_through_a_symlink_replaces_its_target_and_keeps_the_link(tmp_path):
    real_folder = tmp_path / "programs"
    real_folder.mkdir()
    target = real_folder / "real.rockly"
    save_program(target, Program("hobbit", hobbit_workspace(["old"])))
    target.chmod(0o640)
    link_folder = tmp_path / "desktop"
    link_folder.mkdir()
    link = link_folder / "link.rockly"
    link.symlink_to(Path("..") / "programs" / "real.rockly")  # relative, as `ln -s` makes them

    save_program(link, Program("hobbit", hobbit_workspace(["new"])))

    assert link.is_symlink() and os.readlink(link) == str(Path("..") / "programs" / "real.rockly")
    assert load_program(target).workspace == hobbit_workspace(["new"])
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert files_in(link_folder) == ["link.rockly"] and files_in(real_folder) == ["real.rockly"]


def test_a_chain_of_links_is_followed_to_the_file_and_the_temp_file_is_made_beside_it(tmp_path, temp_file_folders):
    target = tmp_path / "a" / "real.py"
    target.parent.mkdir()
    target.write_text("old\n")
    first, second = tmp_path / "first.py", tmp_path / "second.py"
    second.symlink_to(target)
    first.symlink_to(second)
    write_text_atomically(first, "new\n")
    assert target.read_text() == "new\n"
    assert first.is_symlink() and second.is_symlink()
    assert temp_file_folders == [target.parent]


def test_a_dangling_link_gets_its_target_made(tmp_path):
    link = tmp_path / "out.py"
    link.symlink_to(tmp_path / "made.py")
    write_text_atomically(link, "text\n")
    assert link.is_symlink() and (tmp_path / "made.py").read_text() == "text\n"


def test_a_link_loop_is_refused_and_stays_a_loop(tmp_path):
    first, second = tmp_path / "first.py", tmp_path / "second.py"
    first.symlink_to(second)
    second.symlink_to(first)
    with pytest.raises(ProgramFileError, match="could not be saved") as caught:
        write_text_atomically(first, "text")
    assert caught.value.path == str(first)
    assert os.readlink(first) == str(second) and os.readlink(second) == str(first)
    assert files_in(tmp_path) == ["first.py", "second.py"]


def test_a_fifo_is_written_into_not_replaced(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()), daemon=True)
    reader.start()
    write_text_atomically(fifo, "print('hi') # Grüße\n")
    reader.join(10)
    assert received == ["print('hi') # Grüße\n".encode()]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert files_in(tmp_path) == ["pipe"]


def test_a_link_to_a_fifo_is_written_through(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    link = tmp_path / "out.py"
    link.symlink_to(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()), daemon=True)
    reader.start()
    save_program(link, Program("hobbit", {}))
    reader.join(10)
    assert json.loads(received[0])["profile"] == "hobbit"
    assert link.is_symlink() and stat.S_ISFIFO(os.stat(fifo).st_mode)


# --- bad files ----------------------------------------------------------------------------

VALID_TEXT = json.dumps(valid_document(), indent=1)

BAD_CONTENTS = [
    ("empty", b"", "the file is empty"),
    ("only whitespace", b" \n\t\n", "the file is empty"),
    ("truncated", VALID_TEXT[: len(VALID_TEXT) // 2].encode("utf-8"),
     "not a complete Rockly program (broken JSON at line"),
    ("latin-1 bytes", json.dumps(valid_document(profile="Grüße"), ensure_ascii=False).encode("latin-1"),
     "the file is not text (it is not UTF-8)"),
    ("binary", bytes(range(256)), "not UTF-8"),
    ("package.json",
     json.dumps({"name": "my-app", "version": "1.0.0", "dependencies": {"left-pad": "^1.3.0"}}).encode(),
     'this is not a Rockly program (no "format": "rockly-program")'),
    ("json list", b'[{"format": "rockly-program"}]', "this is not a Rockly program"),
    ("json string", b'"rockly-program"', "this is not a Rockly program"),
    ("json number", b"1", "this is not a Rockly program"),
    ("other format", json.dumps(valid_document(format="scratch-project")).encode(), "this is not a Rockly program"),
    ("newer version", json.dumps(valid_document(version=2)).encode(),
     "saved by a newer Rockly (format version 2; this Rockly reads up to 1)"),
    ("version missing", json.dumps({k: v for k, v in valid_document().items() if k != "version"}).encode(),
     "no valid format version"),
    ("version as text", json.dumps(valid_document(version="1")).encode(), "no valid format version"),
    ("version as boolean", json.dumps(valid_document(version=True)).encode(), "no valid format version"),
    ("version as float", json.dumps(valid_document(version=1.0)).encode(), "no valid format version"),
    ("version zero", json.dumps(valid_document(version=0)).encode(), "no valid format version"),
    ("version negative", json.dumps(valid_document(version=-1)).encode(), "no valid format version"),
    ("profile missing", json.dumps({k: v for k, v in valid_document().items() if k != "profile"}).encode(),
     'does not say which robot profile it is for ("profile")'),
    ("profile empty", json.dumps(valid_document(profile="")).encode(), "which robot profile"),
    ("profile a number", json.dumps(valid_document(profile=7)).encode(), "which robot profile"),
    ("profile null", json.dumps(valid_document(profile=None)).encode(), "which robot profile"),
    ("workspace missing", json.dumps({k: v for k, v in valid_document().items() if k != "workspace"}).encode(),
     'the program has no workspace ("workspace" must be an object)'),
    ("workspace a list", json.dumps(valid_document(workspace=[])).encode(), '"workspace" must be an object'),
    ("workspace a string", json.dumps(valid_document(workspace="<xml/>")).encode(), '"workspace" must be an object'),
    ("workspace null", json.dumps(valid_document(workspace=None)).encode(), '"workspace" must be an object'),
    ("nested too deeply", b"[" * 200_000, "nested too deeply"),
    ("NaN", json.dumps(valid_document(workspace={"x": float("nan")})).encode(), "NaN is not a number JSON allows"),
    ("Infinity", json.dumps(valid_document(workspace={"x": float("inf")})).encode(), "Infinity is not a number"),
    ("1e400", json.dumps(valid_document(workspace={"x": 1})).replace('1}', '1e400}').encode(), "1e400 is too large"),
]


@pytest.mark.parametrize("content, problem", [case[1:] for case in BAD_CONTENTS],
                         ids=[case[0] for case in BAD_CONTENTS])
def test_bad_file_gives_program_file_error_naming_the_problem_and_is_left_untouched(tmp_path, content, problem):
    path = tmp_path / "bad.rockly"
    path.write_bytes(content)
    before = snapshot(path)

    with pytest.raises(ProgramFileError) as caught:
        load_program(path)

    assert problem in caught.value.problem
    assert caught.value.path == str(path)
    assert str(caught.value) == f"{path}: {caught.value.problem}"
    assert snapshot(path) == before
    assert files_in(tmp_path) == ["bad.rockly"]


def test_truncated_json_error_names_the_line(tmp_path):
    path = tmp_path / "cut.rockly"
    path.write_text('{\n "format": "rockly-program",\n "version": 1,\n "profile": "hob', encoding="utf-8")
    with pytest.raises(ProgramFileError, match=r"broken JSON at line 4, column 13"):
        load_program(path)


def test_missing_file_says_it_does_not_exist(tmp_path):
    path = tmp_path / "gone.rockly"
    with pytest.raises(ProgramFileError) as caught:
        load_program(path)
    assert caught.value.problem == "the file does not exist"
    assert caught.value.path == str(path)
    assert files_in(tmp_path) == []


def test_folder_instead_of_file_says_so(tmp_path):
    path = tmp_path / "folder.rockly"
    path.mkdir()
    mtime = path.stat().st_mtime_ns
    with pytest.raises(ProgramFileError) as caught:
        load_program(path)
    assert caught.value.problem == "this is a folder, not a file"
    assert path.stat().st_mtime_ns == mtime
    assert list(path.iterdir()) == []


@pytest.mark.skipif(os.geteuid() == 0, reason="root may read any file")
def test_unreadable_file_says_it_cannot_be_read(tmp_path):
    path = tmp_path / "secret.rockly"
    path.write_text(VALID_TEXT, encoding="utf-8")
    path.chmod(0)
    try:
        with pytest.raises(ProgramFileError, match=r"the file cannot be read \(Permission denied\)"):
            load_program(path)
    finally:
        path.chmod(0o644)


def test_parse_program_without_a_file_names_the_text():
    with pytest.raises(ProgramFileError) as caught:
        parse_program("{}")
    assert caught.value.path == "<text>"
    assert parse_program(VALID_TEXT) == Program("hobbit", hobbit_workspace(["hello"]))


def test_unknown_extra_keys_in_the_envelope_are_ignored(tmp_path):
    path = tmp_path / "extra.rockly"
    path.write_text(json.dumps(valid_document(saved_by="Rockly 0.1", comment="hi")), encoding="utf-8")
    assert load_program(path) == Program("hobbit", hobbit_workspace(["hello"]))


def test_breakpoints_are_saved_with_the_program(tmp_path):
    path = tmp_path / "with-breakpoints.rockly"
    save_program(path, Program("hobbit", {"blocks": {"blocks": []}}, ["a'b", "c"]))
    assert load_program(path).breakpoints == ["a'b", "c"]


def test_breakpoints_that_are_not_block_ids_are_refused(tmp_path):
    path = tmp_path / "bad-breakpoints.rockly"
    path.write_text('{"format": "rockly-program", "version": 1, "profile": "hobbit", "workspace": {}, '
                    '"breakpoints": [1]}')
    with pytest.raises(ProgramFileError, match="breakpoints"):
        load_program(path)
