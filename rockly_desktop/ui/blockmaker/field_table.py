"""The fields of a message, request or goal as a table: each one an input of the block, a fixed value,
or left at its type's default (nested fields by path, ``linear.x``, as the Plot names them)."""
import json

import yaml
from PySide6.QtCore import Signal
from PySide6.QtWidgets import QAbstractItemView, QComboBox, QHeaderView, QLineEdit, QTableWidget, QTableWidgetItem

from rockly_desktop.core.numbers import read_number
from rockly_desktop.profiles.packs.spec import VALUE_KINDS, BlockInput
from rockly_desktop.ui.blockmaker.editing import value_text
from rockly_desktop.ui.texts import tr

FIELD, TYPE, USE, PLACE, VALUE, UNIT, MINIMUM, MAXIMUM = range(8)
HEADERS = ("maker_field", "maker_type", "maker_use", "maker_place", "maker_value", "maker_unit",
           "maker_minimum", "maker_maximum")
USES = ("default", "input", "fixed")


def input_name(path: str) -> str:
    """The input's name for the field ``path``: ``linear.x`` → ``linear_x``."""
    return path.replace(".", "_").lower()


def read_value(text: str, kind: str, language: str):
    """The value a person typed for a field of ``kind``: a text as it is, a number as ``language`` writes it
    ("0,3" in German), anything else as YAML (``true``, ``[1, 2]``); None for nothing typed."""
    if not text.strip():
        return None
    if kind == "text":
        return text
    if kind == "number":
        try:
            return read_number(text, language)
        except ValueError:
            return text  # shown to the person as a value that does not fit
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError:
        return text  # shown to the person as a value that does not fit


def _default_text(entry, language: str) -> str:
    """The field's default as typed in the table (a text's in quotes, so an empty one shows)."""
    if entry.kind == "text":
        return json.dumps(entry.default or "", ensure_ascii=False)
    return value_text(entry.default, entry.kind, language)


class FieldTable(QTableWidget):
    """The fields (``InterfaceField``s) of one type; ``sig_changed`` after every edit."""

    sig_changed = Signal()

    def __init__(self, language: str, parent=None):
        super().__init__(0, len(HEADERS), parent)
        self.setObjectName("maker_fields")
        self._language = language
        self._fields = []
        self.setHorizontalHeaderLabels([tr(key, language) for key in HEADERS])
        self.verticalHeader().hide()
        self.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        self.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        header = self.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(VALUE, QHeaderView.ResizeMode.Stretch)
        narrow = self.fontMetrics().horizontalAdvance("-0.000") + 24
        for column in (UNIT, MINIMUM, MAXIMUM):
            header.setSectionResizeMode(column, QHeaderView.ResizeMode.Interactive)
            header.resizeSection(column, max(narrow, self.fontMetrics().horizontalAdvance(tr(HEADERS[column], language))
                                             + 24))

    def set_fields(self, fields):
        """Show ``fields``, each left at its default."""
        self._fields = list(fields)
        self.setRowCount(len(self._fields))
        for row, entry in enumerate(self._fields):
            self.setItem(row, FIELD, QTableWidgetItem(entry.path))
            self.setItem(row, TYPE, QTableWidgetItem(entry.ros_type))
            self.setItem(row, PLACE, QTableWidgetItem(""))
            use = QComboBox(self)
            use.setObjectName(f"use_{entry.path}")
            for key in USES:
                if key != "input" or entry.kind in VALUE_KINDS:  # a list is only ever fixed
                    use.addItem(tr(f"maker_use_{key}", self._language), key)
            use.setAccessibleName(f"{entry.path}: {tr(HEADERS[USE], self._language)}")
            use.currentIndexChanged.connect(lambda _index, row=row: self._use_changed(row))
            self.setCellWidget(row, USE, use)
            for column in (VALUE, UNIT, MINIMUM, MAXIMUM):
                edit = QLineEdit(self)
                edit.setObjectName(f"{HEADERS[column]}_{entry.path}")
                edit.setAccessibleName(f"{entry.path}: {tr(HEADERS[column], self._language)}")
                edit.textChanged.connect(self.sig_changed)
                self.setCellWidget(row, column, edit)
            self.cellWidget(row, VALUE).setPlaceholderText(tr("maker_value_default", self._language,
                                                              value=_default_text(entry, self._language)))
            self._enable(row)
        self._number_places()
        self.sig_changed.emit()

    def set_use(self, path: str, use: str, value: str = "", unit: str = "", minimum: str = "", maximum: str = ""):
        """Make the field ``path`` an input (``value`` its default), a fixed ``value`` or a default (scripts, tests)."""
        row = [entry.path for entry in self._fields].index(path)
        self.blockSignals(True)
        try:
            combo = self.cellWidget(row, USE)
            combo.setCurrentIndex(combo.findData(use))
            for column, text in ((VALUE, value), (UNIT, unit), (MINIMUM, minimum), (MAXIMUM, maximum)):
                self.cellWidget(row, column).setText(str(text))
        finally:
            self.blockSignals(False)
        self.sig_changed.emit()

    def kind_of(self, path: str) -> str:
        """The kind of value of the field ``path`` (``number``, ``text``, ...), "" when it is not shown."""
        return next((entry.kind for entry in self._fields if entry.path == path), "")

    def _use_changed(self, row: int):
        self._enable(row)
        self._number_places()
        self.sig_changed.emit()

    def _enable(self, row: int):
        """Only what the row's use needs can be typed: a value unless left at its default, and a unit
        for an input, bounds for a number input."""
        use = self.cellWidget(row, USE).currentData()
        self.cellWidget(row, VALUE).setEnabled(use != "default")
        self.cellWidget(row, UNIT).setEnabled(use == "input")
        for column in (MINIMUM, MAXIMUM):
            self.cellWidget(row, column).setEnabled(use == "input" and self._fields[row].kind == "number")

    def _number_places(self):
        """Each input's place in the sentence (%1, %2, ...), in the table's order."""
        places = 0
        for row in range(self.rowCount()):
            is_input = self.cellWidget(row, USE).currentData() == "input"
            places += is_input
            self.item(row, PLACE).setText(f"%{places}" if is_input else "")

    def inputs(self) -> tuple:
        """The BlockInputs of the fields made inputs, in the table's order (%1, %2, ...)."""
        made = []
        for row, entry in enumerate(self._fields):
            if self.cellWidget(row, USE).currentData() != "input":
                continue
            text = self.cellWidget(row, VALUE).text
            made.append(BlockInput(input_name(entry.path), entry.kind, entry.path,
                                   self.cellWidget(row, UNIT).text().strip(),
                                   read_value(text(), entry.kind, self._language),
                                   read_value(self.cellWidget(row, MINIMUM).text(), "number", self._language),
                                   read_value(self.cellWidget(row, MAXIMUM).text(), "number", self._language)))
        return tuple(made)

    def fixed(self) -> dict:
        """{field path: the value always sent} of the fields given a fixed value; one left empty keeps its
        default (the placeholder shown), as a field left at its default does."""
        fixed = {entry.path: read_value(self.cellWidget(row, VALUE).text(), entry.kind, self._language)
                 for row, entry in enumerate(self._fields) if self.cellWidget(row, USE).currentData() == "fixed"}
        return {path: value for path, value in fixed.items() if value is not None}
