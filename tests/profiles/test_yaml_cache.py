"""Profile YAML read through the cache: the same data as parsing, and never stale."""
import datetime

import pytest

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles import yaml_files
from rockly_desktop.profiles.yaml_files import read_yaml_mapping


@pytest.fixture(autouse=True)
def own_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    return tmp_path / "cache"


@pytest.fixture
def parses(monkeypatch):
    """The YAML files actually parsed (not read from the cache), in order."""
    parsed = []
    parse = yaml_files._parse

    def counting(path, text):
        parsed.append(path.name)
        return parse(path, text)

    monkeypatch.setattr(yaml_files, "_parse", counting)
    return parsed


def test_a_file_read_again_comes_from_the_cache_with_the_same_data(tmp_path, parses):
    path = tmp_path / "blocks.yaml"
    path.write_text("blocks:\n  - type: hobbit_move\n    colour: '#3d7fd6'\n    inputsInline: true\n    speed: 0.5\n")
    first = read_yaml_mapping(path)
    assert read_yaml_mapping(path) == first == {
        "blocks": [{"type": "hobbit_move", "colour": "#3d7fd6", "inputsInline": True, "speed": 0.5}]}
    assert parses == ["blocks.yaml"]


def test_a_changed_file_is_parsed_again(tmp_path, parses):
    path = tmp_path / "profile.yaml"
    path.write_text("name: HOBBIT\n")
    read_yaml_mapping(path)
    path.write_text("name: HOBBIT 2\n")
    assert read_yaml_mapping(path) == {"name": "HOBBIT 2"}
    assert parses == ["profile.yaml", "profile.yaml"]


def test_what_json_cannot_hold_exactly_is_parsed_each_time(tmp_path, parses):
    path = tmp_path / "profile.yaml"
    path.write_text("released: 2024-05-01\n1: one\n")
    assert read_yaml_mapping(path) == read_yaml_mapping(path) == {"released": datetime.date(2024, 5, 1), 1: "one"}
    assert parses == ["profile.yaml", "profile.yaml"]


def test_a_broken_cache_entry_is_ignored(tmp_path, own_cache, parses):
    path = tmp_path / "toolbox.yaml"
    path.write_text("categories: [drive]\n")
    read_yaml_mapping(path)
    for entry in (own_cache / "rockly" / "yaml").iterdir():
        entry.write_text('{"format": 1, "sha')
    assert read_yaml_mapping(path) == {"categories": ["drive"]}
    assert parses == ["toolbox.yaml", "toolbox.yaml"]


def test_a_cache_that_cannot_be_written_is_no_error(tmp_path, own_cache, parses):
    own_cache.mkdir()
    (own_cache / "rockly").write_text("a file where the cache folder would be")
    path = tmp_path / "profile.yaml"
    path.write_text("name: HOBBIT\n")
    assert read_yaml_mapping(path) == read_yaml_mapping(path) == {"name": "HOBBIT"}


def test_bad_yaml_is_still_reported_with_its_line(tmp_path):
    path = tmp_path / "blocks.yaml"
    path.write_text("blocks:\n  - type: [unclosed\n")
    with pytest.raises(ManifestError, match="not valid YAML at line"):
        read_yaml_mapping(path)
