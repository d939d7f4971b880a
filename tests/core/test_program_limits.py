"""What a program file may be: regular, of a sane size; and what an interrupted save leaves behind is cleaned up."""
import os
import time

import pytest

from rockly_desktop.core import program as program_module
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.program import Program, load_program, read_text_file, remove_stale_temp_files, save_program


def test_a_fifo_is_refused_at_once_instead_of_waiting_for_a_writer(tmp_path):
    fifo = tmp_path / "pipe.rockly"
    os.mkfifo(fifo)

    with pytest.raises(ProgramFileError, match="not a regular file"):
        load_program(fifo)


def test_a_link_to_an_endless_device_is_refused(tmp_path):
    link = tmp_path / "zero.rockly"
    link.symlink_to("/dev/zero")

    with pytest.raises(ProgramFileError, match="not a regular file"):
        load_program(link)


def test_a_file_larger_than_any_program_is_refused_without_reading_it_all(tmp_path):
    big = tmp_path / "big.rockly"
    with open(big, "wb") as stream:
        stream.truncate(2 * 1024 * 1024)  # sparse: no disk used

    with pytest.raises(ProgramFileError, match="larger than 1 MB"):
        read_text_file(big, max_bytes=1024 * 1024)


def make_temp_file(folder, name, age_seconds):
    path = folder / name
    path.write_text("half a program")
    then = time.time() - age_seconds
    os.utime(path, (then, then))
    return path


def test_saving_removes_the_temp_files_of_earlier_interrupted_saves(tmp_path):
    target = tmp_path / "prog.rockly"
    stale = make_temp_file(tmp_path, ".prog.rockly.ab12cd34.tmp", age_seconds=3600)
    in_progress = make_temp_file(tmp_path, ".prog.rockly.ef56gh78.tmp", age_seconds=1)
    other_program = make_temp_file(tmp_path, ".other.rockly.ab12cd34.tmp", age_seconds=3600)
    not_ours = make_temp_file(tmp_path, ".prog.rockly.backup.tmp", age_seconds=3600)

    save_program(target, Program("hobbit", {}))

    assert not stale.exists()
    assert in_progress.exists() and other_program.exists() and not_ours.exists()
    assert load_program(target).profile_id == "hobbit"


def test_cleaning_up_counts_what_it_removed(tmp_path):
    make_temp_file(tmp_path, ".p.rockly.a1b2c3d4.tmp", age_seconds=program_module.STALE_TEMP_SECONDS + 5)
    assert remove_stale_temp_files(tmp_path / "p.rockly") == 1
    assert remove_stale_temp_files(tmp_path / "p.rockly") == 0
