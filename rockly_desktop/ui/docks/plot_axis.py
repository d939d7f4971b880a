"""The Plot panel's axes, their tick numbers written the window's way (a decimal comma in German)."""
import os

os.environ.setdefault("PYQTGRAPH_QT_LIB", "PySide6")
import pyqtgraph as pg

from rockly_desktop.core.numbers import number_marks


class LocalAxis(pg.AxisItem):
    """A pyqtgraph axis whose tick labels use ``language``'s decimal mark and digit group mark."""

    def __init__(self, language: str, **options):
        super().__init__(**options)
        point, group = number_marks(language)
        self._marks = str.maketrans({".": point, ",": group})

    def tickStrings(self, values, scale, spacing):
        """pyqtgraph override: the labels pyqtgraph would write, with this language's marks."""
        return [text.translate(self._marks) for text in super().tickStrings(values, scale, spacing)]
