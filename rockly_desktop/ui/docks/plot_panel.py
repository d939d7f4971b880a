"""The Plot panel: live curves of numeric message fields, for people who measure their robot.

Each curve is one numeric field of one topic (``/odom`` ``pose.pose.position.x``). The panel
reads the :class:`~rockly_desktop.core.state_store.StateStore` on a timer, copies only the
samples it has not seen yet into its own bounded buffer per curve (the store keeps a short
history; the panel keeps up to 5 minutes), and draws the last 10 s / 30 s / 60 s / 5 min with
pyqtgraph, time on the x axis in seconds relative to now (0 = now, -30 = 30 s ago).

During a replay (``show_recorded``) the curves show their recorded series instead, over the whole
run (time since it began) with a vertical cursor at the replay's moment; ``show_live`` goes back.

Fields arrive by drag and drop (text ``"topic|field.path"``, see
:func:`~rockly_desktop.core.field_paths.field_mime_text`) or through the "Add…" menu. Clicking a
curve's legend entry hides or shows it.
"""
import os
import time

import numpy as np
from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (
    QComboBox,
    QCompleter,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QMenu,
    QMessageBox,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
    QWidgetAction,
)

from rockly_desktop.core.field_paths import numeric_paths, parse_mime_text
from rockly_desktop.plotting.csv_export import write_tidy_csv
from rockly_desktop.plotting.samples import SampleBuffer, read_new_samples
from rockly_desktop.ui.docks.plot_axis import LocalAxis
from rockly_desktop.ui.texts import tr

os.environ.setdefault("PYQTGRAPH_QT_LIB", "PySide6")
import pyqtgraph as pg

WINDOWS = ((10, "10 s"), (30, "30 s"), (60, "60 s"), (300, "5 min"))
"""The time windows on offer: (seconds, label)."""

DEFAULT_WINDOW = 30
MAX_SAMPLES = 300_000
"""Samples kept per curve: 5 minutes of a 1 kHz topic."""

MIN_Y_SPAN = 0.01
"""The value axis never shows less than this: a value that stops changing is a flat line with readable
ticks, not its last bits of floating-point noise blown up (×1e-15)."""

REFRESH_INTERVAL_MS = 33
"""At most ~30 redraws a second."""
MAX_REFRESH_INTERVAL_MS = 250
_BUSY_SHARE = 4  # reading and drawing may take at most a quarter of the time between refreshes

# Okabe & Ito's colour-blind-safe palette (without its yellow, which vanishes on white).
_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")
_FOREGROUND = "#333333"


class _Curve:
    def __init__(self, topic, path, item, bound):
        self.topic = topic
        self.path = path
        self.item = item
        self.buffer = SampleBuffer(bound)

    @property
    def name(self):
        return f"{self.topic} {self.path}"


class _TopicCombo(QComboBox):
    """An editable topic box that re-reads the store's topics whenever it opens."""

    def __init__(self, reload, parent=None):
        super().__init__(parent)
        self._reload = reload
        self.setEditable(True)
        self.setInsertPolicy(QComboBox.InsertPolicy.NoInsert)
        self.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        self.setMinimumContentsLength(16)

    def showPopup(self):
        self._reload()
        super().showPopup()


class PlotPanel(QWidget):
    """Live plots of numeric fields from a :class:`StateStore`.

    ``add_curve(topic, path)`` / ``remove_curve(topic, path)`` / ``clear()`` choose the curves
    (each gets its own colour and a legend entry "topic path"); ``set_window(seconds)`` picks
    one of :data:`WINDOWS`; ``pause()`` freezes the view while the store keeps recording and
    ``resume()`` catches up with what the store still holds; ``refresh()`` reads the new samples
    and redraws (the panel's timer calls it ~30 times a second while the panel is visible, not
    paused and has curves; while paused ``refresh()`` does nothing).

    ``export_csv(path)`` writes what the plot shows, one row per sample in long ("tidy") format
    (:mod:`rockly_desktop.plotting.csv_export`), ``time`` counted from the first sample shown.

    ``export_png(path)`` saves the plot as it is on screen.

    ``clock`` must be the store's clock (the default reads it from the store); ``max_samples``
    bounds each curve's buffer.
    """

    def __init__(self, store, language: str = "en", parent=None, *, clock=None, max_samples: int = MAX_SAMPLES):
        super().__init__(parent)
        self.setObjectName("plot_panel")
        self._store = store
        self._language = language
        # StateStore stamps samples with its clock and has no public accessor for it.
        self._clock = clock or store.now
        self._max_samples = max_samples
        self._curves = []
        self._window = DEFAULT_WINDOW
        self._paused = False
        self._now = None  # the moment the plot shows as 0 s
        self._recorded = None  # a replay's RecordedTopics while one is shown
        self._recorded_series = {}
        self._duration = 0.0
        self.cursor = None

        self.timer = QTimer(self)
        self.timer.setInterval(REFRESH_INTERVAL_MS)
        self.timer.timeout.connect(self._tick)

        self._build_toolbar()
        self._build_plot()
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.setSpacing(4)
        layout.addLayout(self._toolbar)
        layout.addWidget(self.plot_widget, 1)
        self.setAcceptDrops(True)
        self._show_hint()

    # --- building ---

    def _t(self, key):
        return tr(key, self._language)

    def _build_toolbar(self):
        self.window_label = QLabel(self._t("plot_window"))
        self.window_box = QComboBox()
        self.window_box.setToolTip(self._t("plot_window_tip"))
        for seconds, label in WINDOWS:
            self.window_box.addItem(label, seconds)
        self.window_box.setCurrentIndex(self.window_box.findData(self._window))
        self.window_box.currentIndexChanged.connect(lambda index: self.set_window(self.window_box.itemData(index)))
        self.window_label.setBuddy(self.window_box)

        self.pause_button = QPushButton(self._t("plot_pause"))
        self.pause_button.setCheckable(True)
        self.pause_button.setToolTip(self._t("plot_pause_tip"))
        self.pause_button.toggled.connect(self.set_paused)

        self.clear_button = QPushButton(self._t("plot_clear"))
        self.clear_button.setToolTip(self._t("plot_clear_tip"))
        self.clear_button.clicked.connect(self.clear)

        self.add_button = QToolButton()
        self.add_button.setText(self._t("plot_add"))
        self.add_button.setToolTip(self._t("plot_add_tip"))
        self.add_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        self.add_menu = QMenu(self.add_button)
        form = QWidget()
        form_layout = QFormLayout(form)
        self.topic_box = _TopicCombo(self.reload_topics)
        self.topic_box.currentTextChanged.connect(self._offer_fields)
        self.field_edit = QLineEdit()
        self.field_edit.setPlaceholderText(self._t("plot_field_hint"))
        self.field_edit.setMinimumWidth(220)
        self.field_completer = QCompleter([], self.field_edit)
        self.field_completer.setCaseSensitivity(Qt.CaseSensitivity.CaseInsensitive)
        self.field_completer.setFilterMode(Qt.MatchFlag.MatchContains)
        self.field_edit.setCompleter(self.field_completer)
        self.field_edit.returnPressed.connect(self._add_from_form)
        self.add_form_button = QPushButton(self._t("plot_add_button"))
        self.add_form_button.clicked.connect(self._add_from_form)
        form_layout.addRow(self._t("plot_topic"), self.topic_box)
        form_layout.addRow(self._t("plot_field"), self.field_edit)
        form_layout.addRow("", self.add_form_button)
        form_action = QWidgetAction(self.add_menu)
        form_action.setDefaultWidget(form)
        self.add_menu.addAction(form_action)
        self.add_menu.aboutToShow.connect(self.reload_topics)
        self.add_button.setMenu(self.add_menu)

        self.export_button = QToolButton()
        self.export_button.setText(self._t("plot_export"))
        self.export_button.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        export_menu = QMenu(self.export_button)
        self.export_csv_action = export_menu.addAction(self._t("plot_export_csv"), self._ask_export_csv)
        self.export_png_action = export_menu.addAction(self._t("plot_export_png"), self._ask_export_png)
        self.export_button.setMenu(export_menu)
        for button in (self.add_button, self.export_button):  # the "…" says that a menu opens
            button.setStyleSheet("QToolButton::menu-indicator { image: none; width: 0px; }")

        self._toolbar = QHBoxLayout()
        for widget in (self.add_button, self.window_label, self.window_box, self.pause_button, self.clear_button):
            self._toolbar.addWidget(widget)
        self._toolbar.addStretch(1)
        self._toolbar.addWidget(self.export_button)

    def _build_plot(self):
        self.plot_widget = pg.PlotWidget(background="w", axisItems={
            side: LocalAxis(self._language, orientation=side) for side in ("left", "bottom")})
        # Drags go to the panel, not to the graphics view (which would swallow them).
        self.plot_widget.setAcceptDrops(False)
        self.plot_widget.viewport().setAcceptDrops(False)
        self.plot_item = self.plot_widget.getPlotItem()
        self.plot_item.setMenuEnabled(False)
        self.plot_item.hideButtons()
        # Draw only the visible samples, a few per pixel (min and max of each bin): a 1 kHz minute is 60,000 samples.
        self.plot_item.setClipToView(True)
        self.plot_item.setDownsampling(auto=True, mode="peak")
        self.plot_item.showGrid(x=True, y=True, alpha=0.15)
        for name in ("left", "bottom"):
            axis = self.plot_item.getAxis(name)
            axis.setPen(_FOREGROUND)
            axis.setTextPen(_FOREGROUND)
            axis.setStyle(maxTickLevel=1)  # major and minor ticks: a calmer grid, drawn in half the time
            axis.enableAutoSIPrefix(False)  # values as they are: no "(x1000)" or "(x1e-15)" beside the axis
        self.plot_item.setLabel("bottom", self._t("plot_time_axis"), units="s", color=_FOREGROUND)
        self.plot_item.setLabel("left", self._t("plot_value_axis"), color=_FOREGROUND)
        view = self.plot_item.getViewBox()
        view.setMouseEnabled(x=False, y=True)
        view.enableAutoRange(x=False, y=True)
        view.setAutoVisible(y=True)
        view.setLimits(minYRange=MIN_Y_SPAN)
        self._show_window()
        self.legend = self.plot_item.addLegend(offset=(10, 10), labelTextColor=_FOREGROUND,
                                               brush=pg.mkBrush(255, 255, 255, 210), pen=pg.mkPen("#bbbbbb"))

    # --- curves ---

    def curves(self) -> list:
        """The plotted (topic, path) pairs, in the order they were added."""
        return [(curve.topic, curve.path) for curve in self._curves]

    def _find(self, topic, path):
        for curve in self._curves:
            if curve.topic == topic and curve.path == path:
                return curve
        return None

    def curve_item(self, topic: str, path: str):
        """The pyqtgraph PlotDataItem drawing a field (``getData()`` gives what is drawn), or None."""
        curve = self._find(topic, path)
        return curve.item if curve else None

    def buffer(self, topic: str, path: str):
        """The :class:`SampleBuffer` of a field, or None."""
        curve = self._find(topic, path)
        return curve.buffer if curve else None

    def _next_colour(self):
        used = {curve.item.opts["pen"].color().name().upper() for curve in self._curves}
        for colour in _COLOURS:
            if colour.upper() not in used:
                return QColor(colour)
        return pg.intColor(len(self._curves))

    def add_curve(self, topic: str, path: str) -> bool:
        """Plot the numeric field ``path`` of ``topic``; False if it is already plotted."""
        topic, path = topic.strip(), path.strip()
        if not topic or not path or self._find(topic, path):
            return False
        item = pg.PlotDataItem(pen=pg.mkPen(self._next_colour(), width=2), name=f"{topic} {path}")
        item.opts["autoDownsampleFactor"] = 2.0  # min and max per pixel look the same as pyqtgraph's 5 per pixel
        self.plot_item.addItem(item)  # gives the item the plot's clip-to-view and downsampling modes
        curve = _Curve(topic, path, item, self._max_samples)
        self._curves.append(curve)
        self._show_hint()
        if self._paused:
            if self._now is None:
                self._now = self._clock()
            self._read(curve)
            self._draw()
        else:
            self.refresh()
        self._update_timer()
        return True

    def remove_curve(self, topic: str, path: str) -> bool:
        """Stop plotting a field; False if it was not plotted."""
        curve = self._find(topic, path)
        if curve is None:
            return False
        self._curves.remove(curve)
        self.plot_item.removeItem(curve.item)  # also takes it out of the legend
        self._show_hint()
        self._update_timer()
        return True

    def clear(self):
        """Remove every curve."""
        for topic, path in self.curves():
            self.remove_curve(topic, path)

    def add_from_mime_text(self, text: str) -> list:
        """Add the fields in a drag text (``topic|field.path`` a line); returns those newly added."""
        return [field for field in parse_mime_text(text) if self.add_curve(*field)]

    def _show_hint(self):
        self.legend.setVisible(bool(self._curves))  # no empty legend frame
        if self._curves:
            self.plot_item.setTitle(None)
        else:
            self.plot_item.setTitle(self._t("plot_hint"), color="#777777", size="10pt")

    # --- time window and pausing ---

    @property
    def window_seconds(self) -> int:
        """The seconds shown (not ``window``: that is QWidget's own, the top-level widget)."""
        return self._window

    def set_window(self, seconds: int):
        """Show the last ``seconds`` (one of :data:`WINDOWS`)."""
        index = self.window_box.findData(seconds)
        if index < 0:
            raise ValueError(f"no {seconds} s window; choose one of {[s for s, _ in WINDOWS]}")
        self._window = seconds
        if self.window_box.currentIndex() != index:
            self.window_box.setCurrentIndex(index)  # calls back here, changing nothing
        self._draw()

    @property
    def paused(self) -> bool:
        return self._paused

    def set_paused(self, paused: bool):
        """Freeze (True) or follow the data again (False)."""
        paused = bool(paused)
        if self.pause_button.isChecked() != paused:
            self.pause_button.setChecked(paused)  # calls back here
            return
        if paused == self._paused:
            return
        self._paused = paused
        self.pause_button.setText(self._t("plot_resume" if paused else "plot_pause"))
        if not paused:
            self.refresh()
        self._update_timer()

    def pause(self):
        self.set_paused(True)

    def resume(self):
        self.set_paused(False)

    # --- reading and drawing ---

    def refresh(self):
        """Read the samples that arrived since the last refresh and redraw (nothing while paused)."""
        if self._recorded is not None:
            self._draw()
            return
        if self._paused:
            return
        self._now = self._clock()
        oldest_kept = self._now - WINDOWS[-1][0]
        for curve in self._curves:
            self._read(curve)
            curve.buffer.trim_before(oldest_kept)
        self._draw()

    def _tick(self):
        started = time.perf_counter()
        self.refresh()
        # Refresh less often when a refresh is expensive (a huge store history, many curves):
        # the window stays responsive.
        cost_ms = (time.perf_counter() - started) * 1000
        self.timer.setInterval(int(min(MAX_REFRESH_INTERVAL_MS, max(REFRESH_INTERVAL_MS, _BUSY_SHARE * cost_ms))))

    def _read(self, curve):
        read_new_samples(self._store, curve.topic, curve.path, curve.buffer)

    def _shown(self, curve):
        """(times, values) of a curve's samples inside the window ending at the shown moment (in a replay:
        its recorded series)."""
        if self._recorded is not None:
            key = (curve.topic, curve.path)
            if key not in self._recorded_series:
                self._recorded_series[key] = tuple(np.array(part) for part in self._recorded.series(*key))
            return self._recorded_series[key]
        if self._now is None:
            return np.empty(0), np.empty(0)
        return curve.buffer.between(self._now - self._window, self._now)

    def _draw(self):
        if self._recorded is not None:
            for curve in self._curves:
                curve.item.setData(*self._shown(curve))
            self.plot_item.setXRange(0, max(self._duration, 0.001), padding=0.015)
            return
        for curve in self._curves:
            times, values = self._shown(curve)
            # Copies: the buffer reuses its memory, pyqtgraph keeps what it gets.
            curve.item.setData(times - self._now if len(times) else times, np.array(values))
        self._show_window()

    def _show_window(self):
        # A little room on both sides so that the "0" and "-window" tick labels show.
        self.plot_item.setXRange(-self._window, 0, padding=0.015)

    def _update_timer(self):
        if self.isVisible() and not self._paused and self._curves and self._recorded is None:
            if not self.timer.isActive():
                self.timer.start()
        else:
            self.timer.stop()

    def showEvent(self, event):
        super().showEvent(event)
        self.refresh()
        self._update_timer()

    def hideEvent(self, event):
        super().hideEvent(event)
        self.timer.stop()

    # --- replay ---

    @property
    def replaying(self) -> bool:
        """Whether a replay's recorded series are shown."""
        return self._recorded is not None

    def show_recorded(self, topics, seconds: float, duration: float):
        """Show the curves' series recorded in ``topics`` (a ``RecordedTopics``), the x axis in seconds since
        the run began (0 to ``duration``), with the cursor at ``seconds``; the live plot waits meanwhile."""
        if self.cursor is None:
            self.cursor = pg.InfiniteLine(angle=90, movable=False, pen=pg.mkPen("#c62828", width=2))
            self.plot_item.addItem(self.cursor, ignoreBounds=True)
        self.cursor.setValue(seconds)
        if topics is not self._recorded:  # the series are drawn once; a moment only moves the cursor
            self._recorded, self._recorded_series, self._duration = topics, {}, duration
            self.timer.stop()
            self.plot_item.setLabel("bottom", self._t("plot_replay_axis"), units="s", color=_FOREGROUND)
            self._draw()

    def show_live(self):
        """Follow the robot again (the replay closed)."""
        if self._recorded is None:
            return
        self._recorded, self._recorded_series = None, {}
        self.plot_item.removeItem(self.cursor)
        self.cursor = None
        self.plot_item.setLabel("bottom", self._t("plot_time_axis"), units="s", color=_FOREGROUND)
        self._now = self._now if self._paused else self._clock()
        self._draw()
        self.refresh()
        self._update_timer()

    # --- the Add… form ---

    def reload_topics(self):
        """Offer the store's topics in the Add… form (keeping what is typed)."""
        typed = self.topic_box.currentText()
        names = self._recorded.names if self._recorded is not None else [info.topic for info in self._store.topics()]
        if names != [self.topic_box.itemText(i) for i in range(self.topic_box.count())]:
            self.topic_box.blockSignals(True)
            self.topic_box.clear()
            self.topic_box.addItems(names)
            self.topic_box.setCurrentText(typed or (names[0] if names else ""))
            self.topic_box.blockSignals(False)
        self._offer_fields(self.topic_box.currentText())

    def _offer_fields(self, topic):
        latest = self._store.latest if self._recorded is None else self._recorded.at(self._duration).latest
        message = latest(topic.strip()) if topic.strip() else None
        self.field_completer.model().setStringList(numeric_paths(message) if message is not None else [])

    def _add_from_form(self):
        if self.add_curve(self.topic_box.currentText(), self.field_edit.text()):
            self.field_edit.clear()
            self.add_menu.close()

    # --- drag and drop ---

    def dragEnterEvent(self, event):
        if event.mimeData().hasText() and parse_mime_text(event.mimeData().text()):
            event.acceptProposedAction()
        else:
            event.ignore()

    def dragMoveEvent(self, event):
        self.dragEnterEvent(event)

    def dropEvent(self, event):
        if event.mimeData().hasText() and parse_mime_text(event.mimeData().text()):
            self.add_from_mime_text(event.mimeData().text())
            event.acceptProposedAction()
        else:
            event.ignore()

    # --- export ---

    def export_csv(self, path) -> int:
        """Write the samples shown to ``path`` (format in the class docstring); returns the number of rows."""
        if not self._paused:
            self.refresh()
        return write_tidy_csv(path, [(curve.topic, curve.path, *self._shown(curve)) for curve in self._curves])

    def export_png(self, path):
        """Save the plot (axes, curves, legend) as it is on screen to ``path`` as PNG; OSError if that fails."""
        if not self.plot_widget.grab().save(str(path), "PNG"):
            raise OSError(f"cannot write {path}")

    def _ask_export_csv(self):
        self._ask_export("plot_export_csv", "plot_filter_csv", ".csv", self.export_csv)

    def _ask_export_png(self):
        self._ask_export("plot_export_png", "plot_filter_png", ".png", self.export_png)

    def _ask_export(self, title_key, filter_key, suffix, export):
        path, _ = QFileDialog.getSaveFileName(self, self._t(title_key).rstrip("…"), "", self._t(filter_key))
        if not path:
            return
        if not path.lower().endswith(suffix):
            path += suffix
        try:
            export(path)
        except OSError as error:
            QMessageBox.warning(self, self._t("plot_export_failed"), str(error))
