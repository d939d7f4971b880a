"""The launcher, the icon Rockly draws itself, and the program file type."""
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree
from pathlib import Path

from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtSvg import QSvgRenderer

REPO = Path(__file__).resolve().parents[1]
ICON = REPO / "resources" / "icons" / "rockly.svg"


def test_desktop_file_passes_desktop_file_validate():
    validator = shutil.which("desktop-file-validate")
    assert validator, "desktop-file-validate is missing: scripts/setup-system.sh installs desktop-file-utils"
    result = subprocess.run([validator, str(REPO / "rockly.desktop")], capture_output=True, text=True)
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")


def test_desktop_file_launches_the_gui_with_the_icon_and_file_type():
    entries = dict(line.split("=", 1) for line in (REPO / "rockly.desktop").read_text().splitlines() if "=" in line)
    assert entries["Exec"] == "rockly-gui %f" and entries["Icon"] == "rockly"
    assert entries["MimeType"] == "application/x-rockly-program;"
    assert "GenericName[de]" in entries and "Comment[de]" in entries


def test_icon_is_self_contained_svg():
    root = ElementTree.parse(ICON).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg" and root.get("viewBox") == "0 0 256 256"
    text = ICON.read_text()
    assert "http:" not in text.replace("http://www.w3.org/2000/svg", "") and "<image" not in text and "<text" not in text


def test_icon_renders_with_colour_at_small_and_large_sizes(qapp):
    renderer = QSvgRenderer(str(ICON))
    assert renderer.isValid()
    for size in (32, 256):
        image = QImage(size, size, QImage.Format.Format_ARGB32)
        image.fill(QColor(0, 0, 0, 0))
        painter = QPainter(image)
        renderer.render(painter)
        painter.end()
        colours = {image.pixel(x, y) for x in range(0, size, max(1, size // 32)) for y in range(0, size, max(1, size // 32))}
        assert len(colours) > 3, f"the icon at {size}px is nearly blank"


def test_program_file_type_is_declared_for_dot_rockly():
    root = ElementTree.parse(REPO / "resources" / "mime" / "rockly.xml").getroot()
    namespace = "{http://www.freedesktop.org/standards/shared-mime-info}"
    mime = root.find(f"{namespace}mime-type")
    assert mime.get("type") == "application/x-rockly-program"
    assert mime.find(f"{namespace}glob").get("pattern") == "*.rockly"
