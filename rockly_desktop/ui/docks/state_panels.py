"""The robot's live state panels, as the profile's manifest declares them (``state:``).

Each panel is a group of rows "label: value"; a row reads one field of one topic from
the StateStore, optionally transformed (heading from a quaternion, radians to degrees,
percent, the state of an action goal, the nearest laser reading ahead as the SDK defines
"ahead") and formatted: numbers with the decimal point and digit grouping of the window's
language (1,60 m in German; a zero never has a minus), the rest of the format as written.
A row's ``values`` name the robot's own values for people ("center_center" is "straight
ahead"); a value it does not name is shown as it comes, and ``nothing`` is what a reading
of nothing (an endless distance) says. The widget redraws from the store on a timer, never
from a robot thread.
"""
import math

from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QFormLayout, QGroupBox, QScrollArea, QVBoxLayout, QWidget

from rockly_desktop.core.numbers import number_format
from rockly_desktop.core.state_store import field_value
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.robot.laser import nearest_in_scan
from rockly_desktop.ui.plain_text import mnemonic_free, plain_label
from rockly_desktop.ui.texts import tr

REFRESH_MS = 100
NO_VALUE = "–"
GOAL_STATES = {0: "goal_pending", 1: "goal_active", 2: "goal_preempted", 3: "goal_succeeded", 4: "goal_aborted",
               5: "goal_rejected", 8: "goal_preempted", 9: "goal_lost"}


def _yaw_degrees(orientation):
    x, y, z, w = (orientation.get(axis, 0.0) for axis in "xyzw")
    return math.degrees(math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


def row_text(store, row: dict, language: str) -> str:
    """The text a row shows now."""
    message = store.latest(row["topic"])
    if message is None:
        return NO_VALUE
    try:
        value = field_value(message, row["field"])
    except KeyError:
        return NO_VALUE
    transform = row.get("transform")
    try:
        if transform == "yaw_degrees":
            value = _yaw_degrees(value)
        elif transform == "degrees":
            value = math.degrees(value)
        elif transform == "percent":
            value = value * 100
        elif transform == "goal_state":
            return tr(GOAL_STATES.get(value, "goal_lost"), language)
        elif transform == "nearest_ahead":
            value = nearest_in_scan(message)
        if isinstance(value, float) and math.isinf(value) and "nothing" in row:
            return localize(row["nothing"], language)
        if isinstance(value, str) and value in row.get("values", {}):
            return localize(row["values"][value], language)
        return number_format(language).format(row.get("format", "{}"), value)
    except (TypeError, ValueError, AttributeError, IndexError, KeyError):
        return str(value)


class StatePanels(QScrollArea):
    """All of a profile's state panels over one StateStore; ``set_store`` switches robots."""

    def __init__(self, panels: list, language: str, parent=None):
        super().__init__(parent)
        self.setWidgetResizable(True)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.store = None
        self._language = language
        self._rows = []
        body = QWidget(self)
        layout = QVBoxLayout(body)
        for panel in panels:
            box = QGroupBox(mnemonic_free(localize(panel["panel"], language)), body)
            form = QFormLayout(box)
            for row in panel["rows"]:
                value = plain_label(NO_VALUE, box)  # a robot's text, as it comes
                value.setObjectName(f"state:{row['topic']}:{row['field']}")
                value.setWordWrap(True)     # a long value (a question) wraps, never cut off
                form.addRow(plain_label(localize(row["label"], language), box), value)
                self._rows.append((row, value))
            layout.addWidget(box)
        layout.addStretch(1)
        self.setWidget(body)
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self.refresh)

    def set_store(self, store):
        """Show ``store`` (None: nothing to show)."""
        self.store = store
        self.refresh()
        if store is None:
            self._timer.stop()
        else:
            self._timer.start()

    def refresh(self):
        """Update every row from the store."""
        for row, label in self._rows:
            text = row_text(self.store, row, self._language) if self.store is not None else NO_VALUE
            if label.text() != text:
                label.setText(text)

    def values(self) -> dict:
        """Row label -> shown text (for tests and screen readers)."""
        return {localize(row["label"], self._language): label.text() for row, label in self._rows}
