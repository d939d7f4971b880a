"""The robot's services and action servers under the Topic monitor's table: kind, name and type, each with
the context menu "Make a block from this…" (as a topic's row). Redrawn only when the graph changed."""
from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import QAbstractItemView, QLabel, QMenu, QTreeWidget, QTreeWidgetItem, QVBoxLayout, QWidget

from rockly_desktop.ui.texts import tr

KINDS = ("service", "action")


class InterfaceList(QWidget):
    """Services and actions in ``language``, as ``show_offers`` gives them;
    ``sig_make_block_requested(name, kind)`` from an entry's context menu."""

    sig_make_block_requested = Signal(str, str)

    def __init__(self, language: str, parent=None):
        super().__init__(parent)
        self.setObjectName("interface_list")
        self._language = language
        self._shown = None
        self.title = QLabel(self)
        self.title.setTextFormat(Qt.TextFormat.PlainText)
        self.tree = QTreeWidget(self)
        self.tree.setObjectName("monitor_interfaces")
        self.tree.setAccessibleName(tr("monitor_interfaces", language))
        self.tree.setRootIsDecorated(False)
        self.tree.setUniformRowHeights(True)
        self.tree.setAlternatingRowColors(True)
        self.tree.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.tree.setHeaderLabels([tr(key, language) for key in ("monitor_interface_kind", "monitor_interface_name",
                                                                 "monitor_type")])
        self.tree.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        self.tree.customContextMenuRequested.connect(self._menu_at)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        layout.addWidget(self.title)
        layout.addWidget(self.tree, 1)
        self.show_offers([])

    def show_offers(self, offers):
        """Show ``offers``: (kind in KINDS, name, type) each, sorted by kind and name."""
        offers = sorted(offers, key=lambda offer: (KINDS.index(offer[0]), offer[1]))
        if offers == self._shown:
            return
        self._shown = offers
        self.tree.clear()
        for kind, name, type_name in offers:
            item = QTreeWidgetItem(self.tree, [tr(f"maker_offer_{kind}", self._language), name, type_name])
            item.setData(0, Qt.ItemDataRole.UserRole, (name, kind))
        self.tree.resizeColumnToContents(0)
        self.tree.resizeColumnToContents(1)
        self.title.setText(tr("monitor_interfaces_count", self._language, count=len(offers)))

    def filter(self, text: str):
        """Show only the entries whose name or type has ``text`` (the monitor's filter)."""
        text = text.strip().lower()
        for row in range(self.tree.topLevelItemCount()):
            item = self.tree.topLevelItem(row)
            item.setHidden(bool(text) and text not in f"{item.text(1)} {item.text(2)}".lower())

    def names(self) -> list:
        """(name, kind) of the entries, as listed."""
        return [self.tree.topLevelItem(row).data(0, Qt.ItemDataRole.UserRole)
                for row in range(self.tree.topLevelItemCount())]

    def menu(self, name: str, kind: str) -> QMenu:
        """The context menu of the entry ``name`` of ``kind``: make a block from it."""
        menu = QMenu(self)
        menu.setObjectName("interface_menu")
        menu.addAction(tr("make_block_from_this", self._language),
                       lambda: self.sig_make_block_requested.emit(name, kind))
        return menu

    def _menu_at(self, position):
        item = self.tree.itemAt(position)
        if item is not None:
            self.menu(*item.data(0, Qt.ItemDataRole.UserRole)).popup(self.tree.viewport().mapToGlobal(position))
