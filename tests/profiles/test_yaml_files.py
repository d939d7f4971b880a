"""Profile YAML files: aliases are refused before they can expand (a 'billion laughs' in blocks.yaml)."""
import pytest

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.yaml_files import read_yaml_mapping

BOMB = "\n".join(["a: &a [x, x, x, x, x, x, x, x, x]"]
                 + [f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]" for i in range(8)])


def test_an_alias_bomb_is_refused_naming_the_first_alias(tmp_path):
    path = tmp_path / "blocks.yaml"
    path.write_text(BOMB, encoding="utf-8")

    with pytest.raises(ManifestError, match=r"aliases \(\*name\) are not allowed .*line 2, column 8"):
        read_yaml_mapping(path)


def test_stars_and_ampersands_in_text_are_fine(tmp_path):
    path = tmp_path / "profile.yaml"
    path.write_text('name: "Tom & Jerry *bot*"\nnote: 2 * 3\n', encoding="utf-8")

    assert read_yaml_mapping(path) == {"name": "Tom & Jerry *bot*", "note": "2 * 3"}
