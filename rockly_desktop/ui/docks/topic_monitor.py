"""The Topic monitor: every topic of the robot with its type, publishers, rate and age,
and the newest message of the selected topic as a tree (what researchers used rqt for).

The panel reads the StateStore on a timer in the GUI thread (at most 10 times a second,
only while it is visible) and stays cheap whatever the message rate: the table redraws
only the cells whose text changed, and the tree is updated in place (so it keeps its
expanded branches) and not at all while the topic's newest message is the same object.
A numeric field can be dragged to a plot ("topic|field.path") or double-clicked to
ask for one (``sig_plot_requested``). When the store's byte budget cut the selected topic's
history (a camera's images), a line under its message says so. Under the table, the robot's services and
action servers (``interface_list``) when the window gives them; each row's menu offers "Make a block from this…".
"""
import math
import time

from PySide6.QtCore import QEvent, QItemSelectionModel, QSortFilterProxyModel, Qt, QTimer, Signal
from PySide6.QtGui import QPalette
from PySide6.QtWidgets import (
    QAbstractItemView,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QMenu,
    QSplitter,
    QStackedWidget,
    QStyle,
    QTableView,
    QTabWidget,
    QToolButton,
    QTreeView,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.core.topic_rows import topic_entries
from rockly_desktop.ui.docks.interface_list import InterfaceList
from rockly_desktop.ui.docks.topic_models import (
    AGE,
    FILTER_ROLE,
    HEADERS,
    PUBLISHERS,
    RATE,
    SORT_ROLE,
    TOPIC,
    TYPE,
    MessageModel,
    TopicTableModel,
)
from rockly_desktop.ui.texts import tr

REFRESH_MS = 100          # at most 10 updates a second
GRAPH_INTERVAL = 1.0      # seconds between two questions to the ROS graph on the timer
_NOTHING_SHOWN = object()  # "nothing shown yet": never the same object as a message


class TopicMonitor(QWidget):
    """The Topic monitor panel over ``store``; ``graph()`` -> [(topic, type, publishers)] lists silent topics too,
    ``own()`` -> {topic: Rockly's own publishers} counts those in, ``offers()`` -> [("service" or "action", name,
    type)] lists the robot's services and actions under the table."""

    sig_plot_requested = Signal(str, str)  # topic, field path of a numeric field
    sig_make_block_requested = Signal(str, str)  # name, "topic"/"service"/"action": "Make a block from this…"

    def __init__(self, store, graph=None, language: str = "en", parent=None, own=None, offers=None):
        super().__init__(parent)
        self.setObjectName("topic_monitor")
        self._store = store
        self._graph = graph
        self._own = own
        self._offers = offers
        self._graph_topics = []
        self._own_publishers = {}
        self._graph_time = -math.inf
        self._language = language
        self._topic = None
        self._shown = _NOTHING_SHOWN
        self._paused = False
        self._expanded = {}  # topic -> label paths of its expanded branches, for when it is shown again

        bar = self._build_bar()
        self._build_table()
        message_pane = self._build_message_pane()
        self.interfaces = InterfaceList(language, self)
        self.interfaces.sig_make_block_requested.connect(self.sig_make_block_requested)
        # the topics and the services and actions each get the dock's whole height (one under the other,
        # a bottom dock left the services one and a half rows)
        self.lists = QTabWidget(self)
        self.lists.setObjectName("monitor_lists")
        self.lists.setDocumentMode(True)
        self.lists.addTab(self.table, tr("monitor_tab_topics", language))
        self.lists.addTab(self.interfaces, tr("monitor_tab_interfaces", language))
        self.lists.tabBar().setVisible(offers is not None)
        self.lists.setTabVisible(1, offers is not None)
        lists = self.lists
        self.splitter = QSplitter(Qt.Orientation.Horizontal, self)
        self.splitter.setChildrenCollapsible(False)
        self.splitter.addWidget(lists)
        self.splitter.addWidget(message_pane)
        self.splitter.setStretchFactor(0, 3)
        self.splitter.setStretchFactor(1, 2)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.addLayout(bar)
        layout.addWidget(self.splitter, 1)

        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self._tick)
        self._show_pause_state()
        self._show_title()
        self.refresh()

    # -- building

    def _build_bar(self) -> QHBoxLayout:
        """The filter, the topic count and the pause button."""
        self.filter_edit = QLineEdit(self)
        self.filter_edit.setPlaceholderText(tr("monitor_filter", self._language))
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.textChanged.connect(self._filter_changed)
        self.pause_button = QToolButton(self)
        self.pause_button.setCheckable(True)
        self.pause_button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)
        self.pause_button.setToolTip(tr("monitor_pause_tip", self._language))
        self.pause_button.toggled.connect(self.set_paused)
        self.count_label = QLabel(self)
        self.count_label.setForegroundRole(QPalette.ColorRole.PlaceholderText)
        bar = QHBoxLayout()
        bar.addWidget(self.filter_edit, 1)
        bar.addWidget(self.count_label)
        bar.addWidget(self.pause_button)
        return bar

    def _build_table(self):
        """The topic table, sorted and filtered through ``proxy``."""
        self.table_model = TopicTableModel(self._language, self)
        self.proxy = QSortFilterProxyModel(self)
        self.proxy.setSourceModel(self.table_model)
        self.proxy.setSortRole(SORT_ROLE)
        self.proxy.setFilterRole(FILTER_ROLE)
        self.proxy.setFilterKeyColumn(TOPIC)
        self.proxy.setFilterCaseSensitivity(Qt.CaseSensitivity.CaseInsensitive)
        self.proxy.setDynamicSortFilter(True)
        self.table = QTableView(self)
        self.table.setModel(self.proxy)
        self.table.setSortingEnabled(True)
        self.table.sortByColumn(TOPIC, Qt.SortOrder.AscendingOrder)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setAlternatingRowColors(True)
        self.table.setShowGrid(False)
        self.table.setWordWrap(False)
        self.table.setTextElideMode(Qt.TextElideMode.ElideRight)  # a name's start says what it is
        self.table.verticalHeader().hide()
        self.table.verticalHeader().setDefaultSectionSize(self.fontMetrics().height() + 8)
        header = self.table.horizontalHeader()
        header.setHighlightSections(False)
        header.setSectionResizeMode(TYPE, QHeaderView.ResizeMode.Stretch)  # the topic's column is fitted to its names
        width = self.fontMetrics().horizontalAdvance
        for column in (PUBLISHERS, RATE, AGE):
            header.resizeSection(column, max(width(tr(HEADERS[column], self._language)), width("1000.0")) + 22)
        self.table.selectionModel().selectionChanged.connect(self._selection_changed)
        self.table.viewport().installEventFilter(self)  # its width changes the room for the topics' names
        self.table.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        self.table.customContextMenuRequested.connect(self._topic_menu)

    def _build_message_pane(self) -> QWidget:
        """The selected topic's name and type over its message tree (or a placeholder)."""
        self.message_title = QLabel(self)
        self.message_title.setTextFormat(Qt.TextFormat.PlainText)
        title_font = self.message_title.font()
        title_font.setBold(True)
        self.message_title.setFont(title_font)
        self.message_type = QLabel(self)
        self.message_type.setTextFormat(Qt.TextFormat.PlainText)
        self.message_type.setForegroundRole(QPalette.ColorRole.PlaceholderText)
        self.history_note = QLabel(self)
        self.history_note.setTextFormat(Qt.TextFormat.PlainText)
        self.history_note.setWordWrap(True)
        self.history_note.setForegroundRole(QPalette.ColorRole.PlaceholderText)
        self.history_note.hide()
        self._build_tree()
        self.placeholder = QLabel(tr("monitor_choose", self._language), self)
        self.placeholder.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.placeholder.setWordWrap(True)
        self.placeholder.setForegroundRole(QPalette.ColorRole.PlaceholderText)
        self._message_stack = QStackedWidget(self)
        self._message_stack.addWidget(self.placeholder)
        self._message_stack.addWidget(self.tree)

        message_pane = QWidget(self)
        message_layout = QVBoxLayout(message_pane)
        message_layout.setContentsMargins(0, 0, 0, 0)
        message_layout.setSpacing(4)
        title = QHBoxLayout()
        title.setContentsMargins(2, 0, 0, 0)
        title.setSpacing(10)
        title.addWidget(self.message_title)
        title.addWidget(self.message_type, 1)
        message_layout.addLayout(title)
        message_layout.addWidget(self._message_stack, 1)
        message_layout.addWidget(self.history_note)
        return message_pane

    def _build_tree(self):
        """The message tree: numeric fields drag out, a double-click asks for a plot."""
        self.message_model = MessageModel(self._language, self)
        self.tree = QTreeView(self)
        self.tree.setModel(self.message_model)
        self.tree.setUniformRowHeights(True)
        self.tree.setAlternatingRowColors(True)
        self.tree.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.tree.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.tree.setDragEnabled(True)
        self.tree.setDragDropMode(QAbstractItemView.DragDropMode.DragOnly)
        self.tree.setExpandsOnDoubleClick(True)
        self.tree.header().setStretchLastSection(True)
        self.tree.header().resizeSection(0, self.fontMetrics().horizontalAdvance("child_frame_id") + 80)
        self.tree.doubleClicked.connect(self._double_clicked)

    # -- public API

    def refresh(self):
        """One update of the table and the message tree (also asks the ROS graph); nothing while paused."""
        self._update(query_graph=True)

    def selected_topic(self):
        """The topic whose message is shown, or None."""
        return self._topic

    def select_topic(self, name: str) -> bool:
        """Select ``name`` in the table (clearing a filter that hides it); False when it is not listed."""
        if self.table_model.row_of(name) < 0:
            self._update_table(query_graph=True)
        row = self.table_model.row_of(name)
        if row < 0:
            return False
        if not self.proxy.mapFromSource(self.table_model.index(row, 0)).isValid():
            self.filter_edit.clear()
        self._set_topic(name)
        self._select_row(name)
        return True

    def field_index(self, path: str):
        """The tree's index of field ``path`` (e.g. ``pose.pose.position.x``) of the shown message."""
        return self.message_model.index_of(path)

    def is_paused(self) -> bool:
        return self._paused

    def set_paused(self, paused: bool):
        """Freeze (True) or unfreeze the display; the store keeps recording either way."""
        paused = bool(paused)
        if self.pause_button.isChecked() != paused:
            self.pause_button.setChecked(paused)  # comes back here through toggled
            return
        if paused == self._paused:
            return
        self._paused = paused
        self._show_pause_state()
        if not paused:
            self.refresh()

    # -- Qt events

    def eventFilter(self, watched, event):
        """Qt override: the topics' column is fitted again when the table's width changes."""
        if watched is self.table.viewport() and event.type() == QEvent.Type.Resize:
            self._fit_topic_column()
        return super().eventFilter(watched, event)

    def showEvent(self, event):
        super().showEvent(event)
        self.refresh()
        self._timer.start()

    def hideEvent(self, event):
        self._timer.stop()
        super().hideEvent(event)

    def resizeEvent(self, event):
        super().resizeEvent(event)
        narrow = event.size().width() < 620 and event.size().height() > event.size().width() * 0.8
        wanted = Qt.Orientation.Vertical if narrow else Qt.Orientation.Horizontal
        if self.splitter.orientation() != wanted:
            self.splitter.setOrientation(wanted)

    # -- updating

    def _tick(self):
        self._update(query_graph=time.monotonic() - self._graph_time >= GRAPH_INTERVAL)

    def _update(self, query_graph: bool):
        if self._paused:
            return
        self._update_table(query_graph)
        if self._topic is not None and not self.message_type.text():
            self._show_title()  # the type became known
        self._show_message()

    def _update_table(self, query_graph: bool):
        infos = {info.topic: info for info in self._store.topics()}
        if self._graph is not None and query_graph:
            self._graph_time = time.monotonic()
            try:
                self._graph_topics = list(self._graph())
                self._own_publishers = dict(self._own()) if self._own is not None else {}
                if self._offers is not None:
                    self.interfaces.show_offers(self._offers())
                    self.interfaces.filter(self.filter_edit.text())
            except Exception:
                pass
        entries = topic_entries(infos, None if self._graph is None else self._graph_topics, self._own_publishers)
        listed = self.table_model.rowCount()
        self.table_model.update(entries)
        if self.table_model.rowCount() != listed:
            self._fit_topic_column()
        self._show_count()
        self._show_history_note(infos.get(self._topic))

    def _fit_topic_column(self):
        """Make the topics' column as wide as their longest name, leaving the type at least a third of the
        table (a longer name is cut at its end)."""
        width = self.table.fontMetrics().horizontalAdvance
        longest = max((width(topic) for topic in self.table_model.topics()), default=0)
        header = self.table.horizontalHeader()
        fixed = sum(header.sectionSize(column) for column in (PUBLISHERS, RATE, AGE))
        room = (self.table.viewport().width() - fixed) * 2 // 3
        header.resizeSection(TOPIC, max(width(tr(HEADERS[TOPIC], self._language)) + 30,
                                        min(longest + 2 * self.style().pixelMetric(
                                            QStyle.PixelMetric.PM_FocusFrameHMargin) + 12, room)))

    def _show_history_note(self, info):
        """Say under the message when the store's byte budget cut the selected topic's history."""
        if info is None or not info.cut:
            self.history_note.hide()
            return
        megabytes = f"{self._store.topic_budget() / 2 ** 20:.3g}"
        self.history_note.setText(tr("monitor_history_cut", self._language, topic=info.topic, kept=info.kept,
                                     megabytes=megabytes))
        self.history_note.show()

    def _show_message(self):
        topic = self._topic
        if topic is None:
            return
        message = self._store.latest(topic)
        if message is self._shown:
            return
        self._shown = message
        if message is None:
            self.placeholder.setText(tr("monitor_no_messages", self._language, topic=topic))
            self._message_stack.setCurrentWidget(self.placeholder)
            return
        first = self.message_model.topic != topic
        self.message_model.show_message(topic, message)
        if first:
            self._restore_expanded(topic)
        self._message_stack.setCurrentWidget(self.tree)

    def _set_topic(self, topic):
        if topic == self._topic:
            return
        if self._topic is not None and self.message_model.topic == self._topic:
            self._expanded[self._topic] = self._expanded_paths()
        self.message_model.clear_message()
        self._topic = topic
        self._shown = _NOTHING_SHOWN
        self._show_title()
        self._show_history_note(next((info for info in self._store.topics() if info.topic == topic), None))
        self._show_message()  # also while paused: the user asked to see this topic

    def _show_title(self):
        if self._topic is None:
            self.message_title.setText(tr("monitor_message", self._language))
            self.message_type.clear()
            return
        row = self.table_model.row_of(self._topic)
        self.message_title.setText(self._topic)
        self.message_type.setText(self.table_model.index(row, TYPE).data() if row >= 0 else "")

    def _show_count(self):
        total = self.table_model.rowCount()
        shown = self.proxy.rowCount()
        if shown == total:
            self.count_label.setText(tr("monitor_count", self._language, count=total))
        else:
            self.count_label.setText(tr("monitor_count_filtered", self._language, shown=shown, total=total))

    def _show_pause_state(self):
        style = self.style()
        if self._paused:
            self.pause_button.setText(tr("monitor_resume", self._language))
            self.pause_button.setIcon(style.standardIcon(QStyle.StandardPixmap.SP_MediaPlay))
        else:
            self.pause_button.setText(tr("monitor_pause", self._language))
            self.pause_button.setIcon(style.standardIcon(QStyle.StandardPixmap.SP_MediaPause))

    # -- selection, filter, expansion

    def _selection_changed(self, *_):
        rows = self.table.selectionModel().selectedRows()
        if rows:
            self._set_topic(self.table_model.topic_at(self.proxy.mapToSource(rows[0]).row()))
            self._show_title()

    def _select_row(self, topic):
        index = self.proxy.mapFromSource(self.table_model.index(self.table_model.row_of(topic), 0))
        if index.isValid():
            flags = QItemSelectionModel.SelectionFlag.ClearAndSelect | QItemSelectionModel.SelectionFlag.Rows
            self.table.selectionModel().setCurrentIndex(index, flags)
            self.table.scrollTo(index)

    def _filter_changed(self, text):
        self.proxy.setFilterFixedString(text.strip())
        self.interfaces.filter(text)
        self._show_count()
        if self._topic is not None and not self.table.selectionModel().hasSelection():
            self._select_row(self._topic)

    def topic_menu(self, topic: str) -> QMenu:
        """The context menu of ``topic``'s row: make a block from it."""
        menu = QMenu(self)
        menu.setObjectName("topic_menu")
        menu.addAction(tr("make_block_from_this", self._language),
                       lambda: self.sig_make_block_requested.emit(topic, "topic"))
        return menu

    def _topic_menu(self, position):
        index = self.table.indexAt(position)
        if index.isValid():
            topic = self.table_model.topic_at(self.proxy.mapToSource(index).row())
            self.topic_menu(topic).popup(self.table.viewport().mapToGlobal(position))

    def _double_clicked(self, index):
        path = self.message_model.plot_path(index)
        if path:
            self.sig_plot_requested.emit(self.message_model.topic, path)

    def _expanded_paths(self) -> set:
        paths = set()

        def walk(parent, labels):
            for position in range(parent.rowCount()):
                item = parent.child(position, 0)
                if item.hasChildren() and self.tree.isExpanded(item.index()):
                    own = labels + (item.text(),)
                    paths.add(own)
                    walk(item, own)
        walk(self.message_model.invisibleRootItem(), ())
        return paths

    def _restore_expanded(self, topic):
        paths = self._expanded.get(topic)
        if not paths:
            return

        def walk(parent, labels):
            for position in range(parent.rowCount()):
                item = parent.child(position, 0)
                own = labels + (item.text(),)
                if own in paths:
                    self.tree.expand(item.index())
                    walk(item, own)
        walk(self.message_model.invisibleRootItem(), ())
