"""A spin box for a decimal number that reads what is typed as the window's language writes numbers
(``core.numbers.read_number``): in German "0,25" is 0.25; in English a comma that is no group of three
("0,25") is not taken as a number, so Enter keeps the box's last number instead of reading 25 or 2."""
import re

from PySide6.QtGui import QValidator
from PySide6.QtWidgets import QDoubleSpinBox

from rockly_desktop.core.numbers import number_format, number_marks, read_number


class NumberBox(QDoubleSpinBox):
    """``QDoubleSpinBox`` in ``language``: shows "0,25 m/s" in German and reads what a person types there."""

    def __init__(self, language: str, parent=None, **properties):
        self._language = language  # (before Qt's constructor: setting the properties asks textFromValue)
        point, group = number_marks(language)
        self._typeable = re.compile(rf"[\d\s+\-\u2212eE{re.escape(point)}{re.escape(group)}]*")
        # Tracking each key would take "2" of "2,5" as the number, and keep it when the whole is refused.
        super().__init__(parent, **{"keyboardTracking": False, **properties})

    def _typed(self, text: str) -> str:
        """``text`` without the box's prefix and suffix (and without the special value's text)."""
        text = text.removeprefix(self.prefix()).removesuffix(self.suffix())
        return text.strip()

    def validate(self, text: str, position: int):
        """Qt override: a number in range is acceptable, a text on its way to one (or not one) intermediate, so
        the box keeps its last number when editing ends there; characters no number has are refused."""
        if self.specialValueText() and text == self.specialValueText():
            return QValidator.State.Acceptable, text, position
        typed = self._typed(text)
        if not self._typeable.fullmatch(typed):
            return QValidator.State.Invalid, text, position
        try:
            value = read_number(typed, self._language)
        except ValueError:
            return QValidator.State.Intermediate, text, position
        in_range = self.minimum() <= round(value, self.decimals()) <= self.maximum()
        return (QValidator.State.Acceptable if in_range else QValidator.State.Intermediate), text, position

    def valueFromText(self, text: str) -> float:
        """Qt override: the number typed, read in the box's language."""
        if self.specialValueText() and text == self.specialValueText():
            return self.minimum()
        return float(read_number(self._typed(text), self._language))

    def textFromValue(self, value: float) -> str:
        """Qt override: ``value`` with the language's decimal mark, ungrouped ("0,25")."""
        return number_format(self._language).format("{:.{}f}", value, self.decimals())
