"""The made block's colour: one of the profile's categories' colours or a few more, each shown with its swatch,
and a swatch beside the box of the colour chosen (a new category gets this colour too)."""
from PySide6.QtCore import QSize, Signal
from PySide6.QtGui import QColor, QIcon, QPixmap
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QWidget

from rockly_desktop.ui.texts import tr

MORE_COLOURS = {"red": "#d64541", "orange": "#e67e22", "yellow": "#d4ac0d", "green": "#43a047",
                "teal": "#26a69a", "blue": "#4c97ff", "purple": "#8e44ad", "pink": "#d81b60",
                "brown": "#8d6e63", "grey": "#78909c"}
"""The colours offered beyond the profile's categories', by the catalogue key's last word (``maker_colour_red``)."""
SWATCH = QSize(16, 16)


def swatch_icon(colour: str) -> QIcon:
    """A square of ``colour`` for the list."""
    pixmap = QPixmap(SWATCH)
    pixmap.fill(QColor(colour))
    return QIcon(pixmap)


class ColourChoice(QWidget):
    """The colours of ``categories`` (``[(name shown, colour)]``) then MORE_COLOURS, each once, in ``language``;
    ``sig_changed`` when another is chosen."""

    sig_changed = Signal()

    def __init__(self, categories, language: str, parent=None):
        super().__init__(parent)
        self.box = QComboBox(self)
        self.box.setObjectName("maker_colour")
        self.box.setIconSize(SWATCH)
        for name, colour in [*categories, *((tr(f"maker_colour_{key}", language), colour)
                                            for key, colour in MORE_COLOURS.items())]:
            if colour and self.box.findData(colour.lower()) < 0:
                self.box.addItem(swatch_icon(colour), f"{name}  {colour.lower()}", colour.lower())
        self.swatch = QLabel(self)
        self.swatch.setObjectName("maker_colour_swatch")
        self.swatch.setFixedSize(48, self.box.sizeHint().height())
        self.box.currentIndexChanged.connect(self._chosen)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.box, 1)
        layout.addWidget(self.swatch)
        self._chosen()

    def colour(self) -> str:
        """The colour chosen, ``#rrggbb``."""
        return self.box.currentData() or ""

    def set_colour(self, colour: str):
        """Choose ``colour`` (added to the list when it is none of its colours, e.g. a pack's own)."""
        colour = (colour or "").lower()
        if not colour:
            return
        index = self.box.findData(colour)
        if index < 0:
            self.box.addItem(swatch_icon(colour), colour, colour)
            index = self.box.count() - 1
        self.box.setCurrentIndex(index)

    def _chosen(self, *_):
        self.swatch.setStyleSheet(f"background: {self.colour()}; border: 1px solid palette(mid); border-radius: 3px;")
        self.sig_changed.emit()
