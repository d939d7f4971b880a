"""The Variables dock: the program's Blockly variables and their current values."""
from PySide6.QtWidgets import QDockWidget, QHeaderView, QTableWidget, QTableWidgetItem


class VariablesDock(QDockWidget):
    """A two-column table (name, value); ``show_values`` replaces the contents."""

    def __init__(self, title: str, headers, parent=None):
        super().__init__(title, parent)
        self.table = QTableWidget(0, 2, self)
        self.table.setHorizontalHeaderLabels(list(headers))
        self.table.horizontalHeader().setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        self.table.verticalHeader().hide()
        self.table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        self.setWidget(self.table)
        self._shown = None

    def show_values(self, values: dict):
        """Show ``values`` (name -> value text), sorted by name; unchanged values cost nothing."""
        if values == self._shown:
            return
        self._shown = dict(values)
        self.table.setRowCount(len(values))
        for row, name in enumerate(sorted(values, key=str.lower)):
            self.table.setItem(row, 0, QTableWidgetItem(name))
            self.table.setItem(row, 1, QTableWidgetItem(values[name]))

    def clear(self):
        """Show no variables (another program is on screen: the last run's values are not its own)."""
        self.show_values({})

    def values(self) -> dict:
        """What the table shows now."""
        return dict(self._shown or {})
