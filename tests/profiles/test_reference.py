"""The manifest reference: generated from MANIFEST_FIELDS, printed by ``rockly profiles reference``,
and the same text in docs/writing-a-robot-profile.md."""
import re
import subprocess
import sys

from profile_copies import REPO

from rockly_desktop.profiles.manifest import MANIFEST_FIELDS
from rockly_desktop.profiles.reference import REFERENCE_END, REFERENCE_START, manifest_reference_markdown

GUIDE = REPO / "docs" / "writing-a-robot-profile.md"


def cells(row: str) -> list:
    """The cells of one Markdown table row (an escaped ``\\|`` stays inside its cell)."""
    return [cell.strip() for cell in re.split(r"(?<!\\)\|", row.strip())[1:-1]]


def test_the_table_has_one_row_per_manifest_field():
    header, rule, *rows = manifest_reference_markdown().splitlines()
    assert cells(header) == ["Field", "Required", "Meaning"]
    assert cells(rule) == ["---", "---", "---"]
    assert [cells(row)[:2] for row in rows] == [[f"`{spec.name}`", "yes" if spec.required else "no"]
                                                for spec in MANIFEST_FIELDS]
    meanings = {cells(row)[0]: cells(row)[2] for row in rows}
    assert meanings["`messages`"] == ("Folder with ROS definitions the robot needs: "
                                      "&lt;package&gt;/msg\\|srv\\|action/*.")


def test_the_guide_holds_the_generated_reference_exactly():
    text = GUIDE.read_text(encoding="utf-8")
    assert text.count(REFERENCE_START) == text.count(REFERENCE_END) == 1
    section = text.split(REFERENCE_START + "\n", 1)[1].split(REFERENCE_END, 1)[0]
    assert section == manifest_reference_markdown(), (
        "docs/writing-a-robot-profile.md is out of date: put the output of "
        "`rockly profiles reference` between its manifest-reference markers")


def test_profiles_reference_prints_it():
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "profiles", "reference"],
                            capture_output=True, text=True, timeout=60, cwd=REPO)
    assert result.returncode == 0, result.stderr
    assert result.stdout == manifest_reference_markdown()
