"""The window's docks in one table (``DOCKS``): what each is, where it goes, what the stage and the
kiosk do with it. Building, the View menu, retitling on a language change, the stage layout, the
bottom tabs' sizes and the kiosk all read this table; a new dock is one ``DockSpec`` here plus its
title in the catalogue."""
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from enum import Enum

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QMainWindow, QWidget

from rockly_desktop.ui.docks.code_dock import CodeDock
from rockly_desktop.ui.docks.console_dock import ConsoleDock
from rockly_desktop.ui.docks.lessons_dock import LessonsDock
from rockly_desktop.ui.docks.simulator_dock import SimulatorDock
from rockly_desktop.ui.docks.tab_room import give_tabs_room
from rockly_desktop.ui.docks.variables_dock import VariablesDock
from rockly_desktop.ui.texts import tr

RIGHT, BOTTOM = Qt.DockWidgetArea.RightDockWidgetArea, Qt.DockWidgetArea.BottomDockWidgetArea


class OnStage(Enum):
    """What the stage layout (View → Stage) does with a dock."""

    HIDDEN = "hidden"
    BIG_SIMULATED = "big_simulated"  # the large one while programs run on the built-in simulator
    BIG_REAL = "big_real"  # the large one while programs run on a real robot
    STRIP = "strip"  # a strip under the blocks, its tab on top


class InKiosk(Enum):
    """What kiosk mode does with a dock."""

    ALLOWED = "allowed"  # as the stage left it (and puts back for every new visitor); the View menu may show it
    CLOSED = "closed"  # closed for good (its exports would open file dialogs anywhere)


@dataclass(frozen=True)
class DockSpec:
    """One of the window's docks.

    ``key`` is its object name (the saved layout finds it by it) and the key the others ask for it
    by; ``title`` the catalogue key of its title; docks with the same ``group`` share tabs in
    ``area``, the first of a group in ``DOCKS`` on top. ``make(language, parent)`` builds the dock
    (its contents may come later). A ``roomy`` bottom tab gets a third of the window when first shown;
    ``first_width``/``first_height`` are its size (px) when no layout is remembered. ``retranslate(dock,
    language)`` renames what else it shows besides its title.
    """

    key: str
    title: str
    area: Qt.DockWidgetArea
    group: str
    make: Callable[[str, QWidget], QDockWidget]
    on_stage: OnStage = OnStage.HIDDEN
    in_kiosk: InKiosk = InKiosk.ALLOWED
    roomy: bool = False
    first_width: int | None = None
    first_height: int | None = None
    retranslate: Callable[[QDockWidget, str], None] | None = None


def _plain_dock(_language: str, parent: QWidget) -> QDockWidget:
    """A dock whose contents the window puts in once a robot is there (state panels, monitor, plot)."""
    return QDockWidget(parent)


def _titled_only(dock_class):
    """The factory of a dock class made from its title (and parent) alone: its title comes with the others'."""
    return lambda _language, parent: dock_class("", parent)


def _variable_headers(language: str) -> list:
    return [tr("variable", language), tr("value", language)]


# In the View menu's order.
DOCKS = (
    DockSpec("simulator_dock", "simulator_dock", RIGHT, "simulator", _titled_only(SimulatorDock),
             on_stage=OnStage.BIG_SIMULATED, first_height=420),
    DockSpec("code_dock", "code_dock", RIGHT, "program", _titled_only(CodeDock),
             first_width=460, first_height=300),
    DockSpec("variables_dock", "variables_dock", RIGHT, "program",
             lambda language, parent: VariablesDock("", _variable_headers(language), parent),
             retranslate=lambda dock, language: dock.table.setHorizontalHeaderLabels(_variable_headers(language))),
    DockSpec("state_dock", "state_dock", RIGHT, "program", _plain_dock, on_stage=OnStage.BIG_REAL),
    DockSpec("lessons_dock", "lessons_dock", RIGHT, "program", _titled_only(LessonsDock),
             retranslate=lambda dock, language: dock.retranslate(language)),
    DockSpec("console_dock", "console_dock", BOTTOM, "bottom", _titled_only(ConsoleDock),
             on_stage=OnStage.STRIP, first_height=130),
    DockSpec("monitor_dock", "monitor_dock", BOTTOM, "bottom", _plain_dock, in_kiosk=InKiosk.CLOSED, roomy=True),
    DockSpec("plot_dock", "plot_dock", BOTTOM, "bottom", _plain_dock, in_kiosk=InKiosk.CLOSED, roomy=True),
)


class Docks(Mapping):
    """The docks ``specs`` (by default ``DOCKS``) describe, made for ``frame`` (the QMainWindow they dock
    in) in ``language``; ``docks[key]`` is one of them, iteration goes in the table's order."""

    def __init__(self, frame: QMainWindow, language: str, specs=None):
        self._frame = frame
        self.specs = tuple(DOCKS if specs is None else specs)
        self._docks = {}
        self._past = set()  # the keys of the docks that show a recorded moment (a replay's)
        for spec in self.specs:
            dock = spec.make(language, frame)
            dock.setObjectName(spec.key)
            self._docks[spec.key] = dock
        self.retitle(language)

    def __getitem__(self, key: str) -> QDockWidget:
        return self._docks[key]

    def __iter__(self):
        return iter(self._docks)

    def __len__(self) -> int:
        return len(self._docks)

    def place(self):
        """Dock each in its area, group by group: the first of a group alone, the others as tabs behind
        it, the first on top."""
        groups = {}
        for spec in self.specs:
            groups.setdefault(spec.group, []).append(spec)
        for first, *others in groups.values():
            leader = self[first.key]
            self._frame.addDockWidget(first.area, leader)
            for spec in others:
                self._frame.tabifyDockWidget(leader, self[spec.key])
            if others:
                leader.raise_()

    def give_first_sizes(self):
        """The sizes for a window with no remembered layout: widths, then each area's heights."""
        widths = [spec for spec in self.specs if spec.first_width is not None]
        if widths:
            self._frame.resizeDocks([self[spec.key] for spec in widths], [spec.first_width for spec in widths],
                                    Qt.Orientation.Horizontal)
        for area in dict.fromkeys(spec.area for spec in self.specs):
            heights = [spec for spec in self.specs if spec.area == area and spec.first_height is not None]
            if heights:
                self._frame.resizeDocks([self[spec.key] for spec in heights], [spec.first_height for spec in heights],
                                        Qt.Orientation.Vertical)

    def retitle(self, language: str):
        """Name every dock (and what it shows) in ``language``; docks sharing tabs at a side get the room for their
        titles."""
        for spec in self.specs:
            title = tr(spec.title, language)
            if spec.key in self._past:
                title = tr("dock_replayed", language, title=title)
            self[spec.key].setWindowTitle(title)
            if spec.retranslate is not None:
                spec.retranslate(self[spec.key], language)
        side_groups = {}
        for spec in self.specs:
            if spec.area in (RIGHT, Qt.DockWidgetArea.LeftDockWidgetArea):
                side_groups.setdefault(spec.group, []).append(self[spec.key])
        screen_width = self._frame.screen().availableGeometry().width()
        for docks in side_groups.values():
            if len(docks) > 1:  # its tabs' titles whole, as far as the screen allows
                give_tabs_room(docks, screen_width)

    def mark_past(self, keys, language: str):
        """Mark the docks ``keys`` name as showing the past (a replay drives them), and only those; say it in
        ``language``."""
        self._past = set(keys)
        self.retitle(language)

    def where(self, keep: Callable[[DockSpec], bool]) -> list:
        """The docks whose spec ``keep`` accepts, in the table's order."""
        return [self[spec.key] for spec in self.specs if keep(spec)]
