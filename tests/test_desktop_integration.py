"""Desktop integration files: the launcher, the app icon and the program mime type."""
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DESKTOP_FILE = ROOT / "rockly.desktop"
ICON = ROOT / "resources" / "icons" / "rockly.svg"
MIME_XML = ROOT / "resources" / "mime" / "rockly.xml"

SVG_NS = "{http://www.w3.org/2000/svg}"
MIME_NS = "{http://www.freedesktop.org/standards/shared-mime-info}"
VALIDATOR = "desktop-file-validate"


def _desktop_entries(group="Desktop Entry"):
    """The key=value pairs of a group of the desktop file ([Desktop Entry] unless said)."""
    entries, current = {}, None
    for line in DESKTOP_FILE.read_text(encoding="utf-8").splitlines():
        if line.startswith("["):
            current = line.strip("[] ")
        elif current == group and "=" in line and not line.startswith("#"):
            key, value = line.split("=", 1)
            entries[key.strip()] = value.strip()
    return entries


# --- rockly.desktop ---------------------------------------------------------------------------


def test_desktop_file_passes_desktop_file_validate():
    validator = shutil.which(VALIDATOR) or ("/usr/bin/" + VALIDATOR if Path("/usr/bin", VALIDATOR).exists() else None)
    if validator is None:
        pytest.fail(f"{VALIDATOR} is missing; it belongs to our set-up: "
                    "scripts/setup-system.sh installs desktop-file-utils")
    result = subprocess.run([validator, str(DESKTOP_FILE)], capture_output=True, text=True, timeout=30)
    output = (result.stdout + result.stderr).strip()
    assert output == "", f"{VALIDATOR} complained:\n{output}"
    assert result.returncode == 0


def test_desktop_file_launches_the_gui_with_our_icon_and_mime_type():
    entries = _desktop_entries()
    assert entries["Type"] == "Application"
    assert entries["Name"] == "Rockly"
    # %f, not %F: rockly-gui opens one program, so the launcher starts one window per file.
    assert entries["Exec"] == "rockly-gui %f"
    assert entries["Icon"] == "rockly"
    assert entries["Terminal"] == "false"
    assert "application/x-rockly-program" in entries["MimeType"].split(";")
    for key in ("GenericName", "Comment", "Keywords"):
        assert entries.get(f"{key}[de]"), f"{key}[de] is missing"


def test_the_desktop_file_has_a_kiosk_action_the_gui_understands():
    from rockly_desktop.cli import _gui_parser

    assert _desktop_entries()["Actions"] == "kiosk;"
    kiosk = _desktop_entries("Desktop Action kiosk")
    assert kiosk["Exec"] == "rockly-gui --kiosk" and kiosk["Name"] and kiosk["Name[de]"]
    assert _gui_parser().parse_args(kiosk["Exec"].split()[1:]).kiosk


def test_desktop_exec_names_an_existing_gui_entry_point():
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert "rockly-gui = " in pyproject


# --- resources/icons/rockly.svg ---------------------------------------------------------------


def test_icon_is_a_well_formed_256_svg():
    root = ET.parse(ICON).getroot()
    assert root.tag in (SVG_NS + "svg", "svg")
    assert root.get("viewBox", "").split() == ["0", "0", "256", "256"]


def test_icon_is_self_contained():
    text = ICON.read_text(encoding="utf-8")
    # The namespace declaration is the only URL allowed.
    without_namespace = text.replace('xmlns="http://www.w3.org/2000/svg"', "")
    assert "http" not in without_namespace
    assert "<image" not in text
    assert "<text" not in text
    assert "href" not in text


@pytest.mark.parametrize("size", [256, 32])
def test_icon_renders_to_a_colourful_image(qapp, size):
    from PySide6.QtCore import Qt
    from PySide6.QtGui import QImage, QPainter
    from PySide6.QtSvg import QSvgRenderer

    renderer = QSvgRenderer(str(ICON))
    assert renderer.isValid()
    image = QImage(size, size, QImage.Format_ARGB32)
    image.fill(Qt.transparent)
    painter = QPainter(image)
    renderer.render(painter)
    painter.end()

    colours = set()
    opaque = 0
    for y in range(size):
        for x in range(size):
            pixel = image.pixel(x, y)
            if (pixel >> 24) & 0xFF:
                opaque += 1
                colours.add(pixel)
    assert opaque > size * size // 4, "the icon should fill a good part of its canvas"
    assert len(colours) > 3


# --- resources/mime/rockly.xml ----------------------------------------------------------------


def test_mime_xml_declares_rockly_programs():
    root = ET.parse(MIME_XML).getroot()
    assert root.tag == MIME_NS + "mime-info"
    mime_types = root.findall(MIME_NS + "mime-type")
    assert [m.get("type") for m in mime_types] == ["application/x-rockly-program"]
    mime_type = mime_types[0]
    assert [g.get("pattern") for g in mime_type.findall(MIME_NS + "glob")] == ["*.rockly"]
    assert [s.get("type") for s in mime_type.findall(MIME_NS + "sub-class-of")] == ["application/json"]
    languages = {c.get("{http://www.w3.org/XML/1998/namespace}lang") for c in mime_type.findall(MIME_NS + "comment")}
    assert languages == {None, "de"}


def test_mime_glob_matches_the_program_suffix():
    from rockly_desktop.core.program import PROGRAM_SUFFIX

    assert f'pattern="*{PROGRAM_SUFFIX}"' in MIME_XML.read_text(encoding="utf-8")
