"""Recovery files: written atomically, found only when their Rockly is gone, claimed by one Rockly at a time."""
import json
import os
from datetime import datetime, timedelta, timezone

import pytest
from recovery_tools import LiveProcess, left_by_killed_process

from rockly_desktop.core import paths
from rockly_desktop.core.program import Program, load_program
from rockly_desktop.core.recovery import RecoverySession, claim_abandoned, read_recovery

PROGRAM = Program("hobbit", {"blocks": {"languageVersion": 0, "blocks": [{"type": "hobbit_sos", "id": "a"}]}}, ["a"])


@pytest.fixture
def session():
    session = RecoverySession()
    yield session
    session.close()


def test_recovery_files_live_in_the_users_data_folder(isolated_user_folders):
    assert paths.recovery_dir() == isolated_user_folders / "data" / "rockly" / "recovery"
    assert RecoverySession().path.parent == paths.recovery_dir()


def test_nothing_is_made_on_disk_before_the_first_write():
    RecoverySession()
    assert not paths.recovery_dir().exists()


def test_a_written_copy_is_a_program_that_says_which_file_it_belongs_to_and_when(session, tmp_path):
    before = datetime.now(timezone.utc).replace(microsecond=0)
    session.write(PROGRAM, tmp_path / "square.rockly")
    assert session.path.name.startswith(f"{os.getpid()}-")
    assert oct(paths.recovery_dir().stat().st_mode & 0o777) == "0o700"
    assert load_program(session.path) == PROGRAM  # any Rockly can open it as a program
    recovery = read_recovery(session.path)
    assert recovery.program == PROGRAM
    assert recovery.program_path == str(tmp_path / "square.rockly")
    assert before <= recovery.saved_at <= datetime.now(timezone.utc) + timedelta(seconds=1)
    assert json.loads(session.path.read_text())["recovery"]["pid"] == os.getpid()


def test_writing_again_replaces_the_copy_and_leaves_no_temporary_file(session):
    session.write(PROGRAM)
    session.write(Program("hobbit", {}, []))
    assert read_recovery(session.path).program.workspace == {}
    assert read_recovery(session.path).program_path is None
    assert sorted(path.name for path in paths.recovery_dir().iterdir()) == sorted(
        [session.path.name, session.lock_path.name])


def test_remove_deletes_the_copy_and_close_the_lock_as_well(session):
    session.write(PROGRAM)
    session.remove()
    assert not session.path.exists() and session.lock_path.exists()
    session.close()
    assert list(paths.recovery_dir().iterdir()) == []


def test_the_copy_of_a_running_rockly_is_not_claimed(session):
    session.write(PROGRAM)
    assert claim_abandoned() is None  # held by this process's session


def test_the_copy_of_a_rockly_running_in_another_process_is_not_claimed():
    other = LiveProcess(PROGRAM)
    try:
        assert other.path.exists()
        assert claim_abandoned() is None
    finally:
        other.end()
    recovery = claim_abandoned()  # its process is gone now (it never cleaned up)
    assert recovery is not None and recovery.path == other.path
    recovery.discard()


def test_the_copy_of_a_killed_rockly_is_claimed_by_one_rockly_at_a_time(tmp_path):
    path = left_by_killed_process(PROGRAM, str(tmp_path / "square.rockly"))
    recovery = claim_abandoned()
    assert recovery.path == path and recovery.program == PROGRAM
    assert recovery.program_path == str(tmp_path / "square.rockly")
    assert claim_abandoned() is None  # being offered here: nobody else offers it meanwhile
    recovery.release()
    again = claim_abandoned()
    assert again.path == path
    again.discard()
    assert list(paths.recovery_dir().iterdir()) == []
    assert claim_abandoned() is None


def test_the_newest_abandoned_copy_is_offered_first_and_the_others_wait():
    older = left_by_killed_process(Program("hobbit", {}, []))
    os.utime(older, (1_000_000_000, 1_000_000_000))
    newer = left_by_killed_process(PROGRAM)
    first = claim_abandoned()
    assert first.path == newer
    first.discard()
    second = claim_abandoned()
    assert second.path == older
    second.release()


def test_a_broken_recovery_file_is_passed_over_and_kept(session):
    session.write(PROGRAM)
    broken = paths.recovery_dir() / "1-deadbeef.rockly"
    broken.write_text('{"format": "rockly-program", "version": 1, "profile": "hobbit", "workspace": {}}')
    assert claim_abandoned() is None
    assert broken.exists()


def test_lock_files_nobody_holds_and_nothing_needs_are_removed(session):
    session.write(PROGRAM)
    session.remove()  # this session's lock stays: it is held
    orphan = paths.recovery_dir() / "1-0badf00d.lock"
    orphan.write_text("")
    assert claim_abandoned() is None
    assert not orphan.exists() and session.lock_path.exists()
