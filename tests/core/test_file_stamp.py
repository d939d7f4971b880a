"""A program file's stamp: what a window wrote is recognised as its own, anything else is a change."""
import os

from rockly_desktop.core.file_stamp import FileStamp, stamp_file
from rockly_desktop.core.program import write_text_atomically


def test_the_stamp_of_a_save_is_the_file_as_it_is_then(tmp_path):
    path = tmp_path / "a.rockly"
    written = write_text_atomically(path, "one\n")
    assert written == stamp_file(path) and stamp_file(path, written) is written
    other = write_text_atomically(path, "two\n")
    assert other != written and other.sha256 != written.sha256


def test_a_change_in_place_with_the_same_size_is_seen(tmp_path):
    path = tmp_path / "a.rockly"
    written = write_text_atomically(path, "one\n")
    with open(path, "r+", encoding="utf-8") as stream:
        stream.write("two\n")
    os.utime(path, ns=(written.mtime_ns + 1, written.mtime_ns + 1))
    now = stamp_file(path, written)
    assert now.inode == written.inode and now.size == written.size and now.sha256 != written.sha256


def test_a_missing_file_or_a_fifo_has_no_stamp_and_is_never_opened(tmp_path):
    assert stamp_file(tmp_path / "missing.rockly") is None
    fifo = tmp_path / "fifo.rockly"
    os.mkfifo(fifo)
    assert stamp_file(fifo) is None  # returns at once: a FIFO's open would wait for a writer


def test_a_stamp_kept_as_json_comes_back_and_damaged_data_gives_none(tmp_path):
    path = tmp_path / "a.rockly"
    written = write_text_atomically(path, "one\n")
    assert FileStamp.from_json(written.to_json()) == written
    assert FileStamp.from_json(None) is None and FileStamp.from_json({"inode": "x"}) is None
