"""The Topic monitor's Qt models: the topic table, changing only the cells that changed, and
the tree of one message, updated in place (so it keeps its expanded branches)."""
from PySide6.QtCore import QAbstractTableModel, QMimeData, QModelIndex, Qt
from PySide6.QtGui import QFont, QPalette, QStandardItem, QStandardItemModel

from rockly_desktop.core.field_paths import child_fields, field_mime_text
from rockly_desktop.core.message_text import summary, value_kind, value_text
from rockly_desktop.core.topic_rows import row_cells
from rockly_desktop.ui.plain_text import tooltip_text
from rockly_desktop.ui.texts import tr

LIST_LIMIT = 50           # list items shown before "… N more"
MIME_TYPE = "text/plain"

TOPIC, TYPE, PUBLISHERS, RATE, AGE = range(5)
HEADERS = ("monitor_topic", "monitor_type", "monitor_publishers", "monitor_rate", "monitor_age")  # texts keys
SORT_ROLE = Qt.ItemDataRole.UserRole
FILTER_ROLE = Qt.ItemDataRole.UserRole + 1
KIND_ROLE = Qt.ItemDataRole.UserRole + 2
PATH_ROLE = Qt.ItemDataRole.UserRole + 3


# ----------------------------------------------------------------------------- the table

class _Row:
    __slots__ = ("topic", "texts", "keys", "count")

    def __init__(self, topic):
        self.topic = topic
        self.texts = ("",) * 5
        self.keys = ("",) * 5
        self.count = 0


class TopicTableModel(QAbstractTableModel):
    """One row per topic, in arrival order (the view sorts); ``update`` changes only what changed."""

    def __init__(self, language: str, parent=None):
        super().__init__(parent)
        self._language = language
        self._rows = []
        self._index = {}
        self._silent = QPalette().color(QPalette.ColorRole.PlaceholderText)  # topics without messages yet

    def rowCount(self, parent=None):
        return 0 if parent is not None and parent.isValid() else len(self._rows)

    def columnCount(self, parent=None):
        return 0 if parent is not None and parent.isValid() else len(HEADERS)

    def headerData(self, section, orientation, role=Qt.ItemDataRole.DisplayRole):
        if orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.DisplayRole:
            return tr(HEADERS[section], self._language)
        if orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.TextAlignmentRole:
            return _alignment(section)
        return None

    def data(self, index, role=Qt.ItemDataRole.DisplayRole):
        if not index.isValid():
            return None
        row = self._rows[index.row()]
        column = index.column()
        if role == Qt.ItemDataRole.DisplayRole:
            return row.texts[column]
        if role == SORT_ROLE:
            return row.keys[column]
        if role == FILTER_ROLE:
            return f"{row.topic} {row.texts[TYPE]}"
        if role == Qt.ItemDataRole.TextAlignmentRole:
            return _alignment(column)
        if role == Qt.ItemDataRole.ForegroundRole and row.count == 0:
            return self._silent
        if role == Qt.ItemDataRole.ToolTipRole:
            return f"{row.topic}\n{row.texts[TYPE]}\n{tr('monitor_count_tip', self._language, count=row.count)}"
        return None

    def topic_at(self, row: int) -> str:
        return self._rows[row].topic

    def row_of(self, topic: str) -> int:
        """The row of ``topic``, -1 when it is not listed."""
        return self._index.get(topic, -1)

    def topics(self) -> list:
        return [row.topic for row in self._rows]

    def update(self, entries: list):
        """Show ``entries`` [(topic, type, publishers or None, count, rate, age, Rockly's publishers)]
        (``core.topic_rows.topic_entries``); signal changed cells only."""
        wanted = {entry[0] for entry in entries}
        removed = False
        for position in reversed(range(len(self._rows))):
            if self._rows[position].topic not in wanted:
                self.beginRemoveRows(QModelIndex(), position, position)
                del self._rows[position]
                self.endRemoveRows()
                removed = True
        if removed:
            self._index = {row.topic: position for position, row in enumerate(self._rows)}
        new = [entry for entry in entries if entry[0] not in self._index]
        if new:
            self.beginInsertRows(QModelIndex(), len(self._rows), len(self._rows) + len(new) - 1)
            for entry in new:
                self._index[entry[0]] = len(self._rows)
                self._rows.append(_Row(entry[0]))
            self.endInsertRows()
        for entry in entries:
            position = self._index[entry[0]]
            row = self._rows[position]
            texts, row.keys = row_cells(entry, self._language)
            if entry[6]:  # Rockly publishes here too: "1 (Rockly)", "2 (with Rockly)"
                key = "monitor_publishers_rockly" if entry[6] == entry[2] else "monitor_publishers_with_rockly"
                texts = texts[:PUBLISHERS] + (tr(key, self._language, count=entry[2]),) + texts[PUBLISHERS + 1:]
            changed = [column for column in range(len(texts)) if texts[column] != row.texts[column]]
            was_seen, seen = row.count > 0, entry[3] > 0
            row.count = entry[3]
            row.texts = texts
            if was_seen != seen:
                changed = range(len(texts))  # the whole row changes colour
            if changed:
                self.dataChanged.emit(self.index(position, changed[0]), self.index(position, changed[-1]))


def _alignment(column: int):
    horizontal = Qt.AlignmentFlag.AlignRight if column >= PUBLISHERS else Qt.AlignmentFlag.AlignLeft
    return int(horizontal | Qt.AlignmentFlag.AlignVCenter)


# ----------------------------------------------------------------------------- the message tree

class MessageModel(QStandardItemModel):
    """Field | Value rows of one message, updated in place; numeric fields drag as "topic|path"."""

    def __init__(self, language: str, parent=None):
        super().__init__(0, 2, parent)
        self._language = language
        self.topic = ""
        self.setHorizontalHeaderLabels([tr("monitor_field", language), tr("monitor_value", language)])
        self._value_font = QFont()
        self._value_font.setStyleHint(QFont.StyleHint.Monospace)
        self._value_font.setFamilies(["DejaVu Sans Mono", "Menlo", "Consolas", "monospace"])

    def show_message(self, topic: str, message):
        """Show ``message`` of ``topic``: rows whose field is unchanged stay (and stay expanded)."""
        if topic != self.topic:
            self.clear_message()
            self.topic = topic
        self._sync(self.invisibleRootItem(), message, "")

    def clear_message(self):
        root = self.invisibleRootItem()
        if root.rowCount():
            root.removeRows(0, root.rowCount())
        self.topic = ""

    def plot_path(self, index) -> str:
        """The field path of a numeric field at ``index`` (any column), or None."""
        if not index.isValid():
            return None
        item = self.itemFromIndex(index.siblingAtColumn(0))
        if item is None or item.data(KIND_ROLE) != "number":
            return None
        return item.data(PATH_ROLE)

    def index_of(self, path: str):
        """The index (Field column) of the row showing field ``path``, invalid when not shown."""
        def find(parent):
            for position in range(parent.rowCount()):
                item = parent.child(position, 0)
                own = item.data(PATH_ROLE)
                if own == path:
                    return item.index()
                if own and path.startswith(own) and path[len(own)] in ".[":
                    return find(item)
            return QModelIndex()
        return find(self.invisibleRootItem())

    def mimeTypes(self):
        return [MIME_TYPE]

    def mimeData(self, indexes):
        for index in indexes:
            path = self.plot_path(index)
            if path:
                mime = QMimeData()
                mime.setText(field_mime_text(self.topic, path))
                return mime
        return None

    # -- building and updating rows

    def _sync(self, parent: QStandardItem, value, path):
        entries = list(child_fields(value, path, LIST_LIMIT))
        labels = [entry[0] for entry in entries]
        if value_kind(value) == "list" and len(value) > LIST_LIMIT:
            labels.append(tr("monitor_more", self._language, count=len(value) - LIST_LIMIT))
        rows = parent.rowCount()
        keep = 0
        while keep < rows and keep < len(labels) and parent.child(keep, 0).text() == labels[keep]:
            keep += 1
        if keep < rows:
            parent.removeRows(keep, rows - keep)
        for position, (label, child, child_path) in enumerate(entries):
            if position < keep:
                self._update_row(parent, position, label, child, child_path)
            else:
                parent.appendRow(self._make_row(label, child, child_path))
        if len(labels) > len(entries) and keep < len(labels):
            more = QStandardItem(labels[-1])
            more.setFlags(Qt.ItemFlag.ItemIsEnabled)
            more.setData("more", KIND_ROLE)
            more.setForeground(QPalette().color(QPalette.ColorRole.PlaceholderText))
            filler = QStandardItem("")
            filler.setFlags(Qt.ItemFlag.ItemIsEnabled)
            parent.appendRow([more, filler])

    def _make_row(self, label, value, path):
        kind = value_kind(value)
        field = QStandardItem(label)
        field.setData(kind, KIND_ROLE)
        field.setData(path, PATH_ROLE)
        cell = QStandardItem()
        self._set_kind(field, cell, kind, path)
        if kind in ("dict", "list"):
            cell.setText(self._summary(value))
            self._sync(field, value, path)
        else:
            cell.setText(value_text(value))
        return [field, cell]

    def _update_row(self, parent, position, label, value, path):
        field, cell = parent.child(position, 0), parent.child(position, 1)
        kind, old = value_kind(value), field.data(KIND_ROLE)
        if kind != old:
            if "dict" in (kind, old) or "list" in (kind, old):
                parent.removeRow(position)
                parent.insertRow(position, self._make_row(label, value, path))
                return
            field.setData(kind, KIND_ROLE)
            self._set_kind(field, cell, kind, path)
        if kind in ("dict", "list"):
            text = self._summary(value)
            if cell.text() != text:
                cell.setText(text)
            self._sync(field, value, path)
        else:
            text = value_text(value)
            if cell.text() != text:
                cell.setText(text)

    def _summary(self, value):
        return summary(value, lambda count: tr("monitor_items", self._language, count=count))

    def _set_kind(self, field, cell, kind, path):
        flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
        tip = ""
        if kind == "number" and path:
            flags |= Qt.ItemFlag.ItemIsDragEnabled
            tip = tooltip_text(tr("monitor_plot_tip", self._language, path=path))  # a robot's field names
        for item in (field, cell):
            item.setFlags(flags)
            item.setToolTip(tip)
        if kind not in ("dict", "list"):
            cell.setFont(self._value_font)
