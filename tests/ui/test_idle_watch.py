"""The kiosk's idle watch lets the windows it watched go at any time: while it watches, or after the
kiosk was left (``stop()``), without an error or a crash."""
from PySide6.QtCore import SIGNAL, QCoreApplication, QEvent
from PySide6.QtWidgets import QDialog, QWidget

from rockly_desktop.ui.kiosk.idle_watch import IdleWatch


def delete_now(widget):
    widget.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def test_a_watched_window_that_went_is_no_trouble_when_the_watch_stops(qtbot):
    window = QWidget()
    qtbot.addWidget(window)
    window.show()
    watch = IdleWatch(60, window)
    dialog = QDialog(window)                  # a PIN dialog the kiosk makes anew each time it asks
    dialog.show()
    watch._watch(dialog.windowHandle())      # what focusing it does
    delete_now(dialog)
    watch.stop()                              # the kiosk is left (this raised: the dialog's window had gone)
    assert watch._watched == []


def test_no_python_slot_waits_for_a_watched_window_to_go(qtbot):
    """A slot on a QWindow's ``destroyed`` runs while the window is half destroyed: PySide then makes a
    wrapper for it and crashes (once the watch has let go of its own wrapper, when the kiosk was left)."""
    window = QWidget()
    qtbot.addWidget(window)
    window.show()
    handle = window.windowHandle()
    destroyed = SIGNAL("destroyed(QObject*)")
    watch = IdleWatch(60, window)
    assert handle.receivers(destroyed) == 0
    watch.stop()
    assert handle.receivers(destroyed) == 0
