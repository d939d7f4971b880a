"""The block maker's "Try it": the previewed block run once on the window's robot (``RunSession.run`` on the
preview page), and what happened said in the maker: what was sent, the robot's answer or refusal, and how the
try ended. The maker is moved off the simulator view first, so the robot is seen doing it."""
import json

from PySide6.QtCore import QObject, QPoint, QTimer

from rockly_desktop.ui.texts import tr

DATA_LIMIT = 400  # characters of a message shown; a longer one ends in "…"
SENT = {"publish": "maker_try_published", "call": "maker_try_called", "goal": "maker_try_goal"}


def _data(data) -> str:
    text = json.dumps(data, ensure_ascii=False, default=str)
    return text if len(text) <= DATA_LIMIT else text[:DATA_LIMIT - 1] + "…"


def report_lines(notes: list, result, language: str) -> list:
    """The lines the maker shows after a try: each thing sent with the robot's answer or refusal (``notes``:
    ``RecordedBackend``'s entries), then how the run ended (``result``: a ``RunFinished``, None: it never
    ran, as a block that only gives a value is not run on its own)."""
    lines, refused = [], False
    last_failure = max((place for place, entry in enumerate(notes) if entry["kind"] == "failed"), default=-1)
    for place, entry in enumerate(notes):
        kind, name = entry["kind"], entry.get("name", "")
        if kind in SENT:
            lines.append(tr(SENT[kind], language, name=name, data=_data(entry.get("data"))))
        elif kind == "response":
            lines.append(tr("maker_try_answer", language, data=_data(entry.get("data"))))
        elif kind == "outcome":
            lines.append(tr("maker_try_outcome", language, status=entry.get("status"), text=entry.get("text") or ""))
        elif kind == "failed":
            refused = True
            if place == last_failure and result is not None and result.outcome == "error":
                lines.append(result.message)  # the refusal that ended the try, as the run says it in its language
            else:  # the error's class, then its text
                lines.append(tr("maker_try_refused", language, why=entry.get("text", "").partition(": ")[2]))
    if notes and notes[-1]["kind"] == "publish":
        lines.append(tr("maker_try_no_answer", language))
    if result is None:
        lines.append(tr("maker_try_not_run", language))
    elif result.outcome == "finished":
        lines.append(tr("maker_try_done", language))
    elif result.outcome == "stopped":
        lines.append(tr("maker_try_stopped", language))
    elif not refused:
        lines.append(tr("maker_try_failed", language, why=result.message))
    return lines


def keep_clear_of(dialog, widget):
    """Move ``dialog`` to the side of its screen away from ``widget`` when it covers it, narrowed to the room
    there (not below its minimum width)."""
    if widget is None or not widget.isVisible():
        return
    seen = widget.rect().translated(widget.mapToGlobal(QPoint(0, 0)))
    frame = dialog.frameGeometry()
    if not frame.intersects(seen):
        return
    area = dialog.screen().availableGeometry()
    extra = frame.width() - dialog.width()
    left_room, right_room = seen.left() - area.left(), area.right() - seen.right()
    room = max(left_room, right_room) - extra
    dialog.resize(max(dialog.minimumSizeHint().width(), min(dialog.width(), room)), dialog.height())
    x = area.left() if left_room >= right_room else area.right() + 1 - dialog.width() - extra
    dialog.move(x, frame.top())


class BlockTrial(QObject):
    """Runs ``maker``'s block on ``runs`` (a ``RunSession``) when its Try it is pressed, the maker kept off
    ``avoid()`` (the simulator view, or None), and shows the report in the maker."""

    def __init__(self, maker, runs, avoid=lambda: None):
        super().__init__(maker)
        self._maker, self._runs, self._avoid = maker, runs, avoid
        self._notes, self._result, self._trying, self._ending = [], None, False, False
        maker.sig_try_requested.connect(self.start)
        runs.sig_finished.connect(self._finished)
        runs.sig_state_changed.connect(self._state_changed)

    def start(self, page):
        """Try the block on ``page`` (the maker's preview) once."""
        language = self._maker.language
        keep_clear_of(self._maker, self._avoid())
        notes = []
        if not self._runs.run(page=page, notes=notes.append):
            self._maker.show_try_report([tr("maker_try_busy", language)])
            return
        self._notes, self._result, self._trying = notes, None, True
        self._maker.show_try_report([tr("maker_try_running", language)])

    def _finished(self, result):
        if self._trying or self._ending:
            self._result = result

    def _state_changed(self, state: str):
        # "idle" comes before the run's sig_finished (or alone, when there was nothing to run): report after both
        if self._trying and state == "idle":
            self._trying, self._ending = False, True
            QTimer.singleShot(0, self, self._report)

    def _report(self):
        self._ending = False
        self._maker.show_try_report(report_lines(list(self._notes), self._result, self._maker.language))
