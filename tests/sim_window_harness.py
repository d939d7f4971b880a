"""`rockly sim PROFILE --ros` with its window, in its own process, worked by a test as a person would.

    python tests/sim_window_harness.py sim hobbit --ros --master URI [--answer A ...]

runs the real command (``rockly_desktop.cli.main``) here, with Qt offscreen. A timer in
the GUI thread prints ``dialog QUESTION TEXT`` (TEXT as JSON) whenever a tablet dialog opens,
and each line on stdin is done in the GUI thread:

    click LABEL   press the open tablet dialog's button labelled LABEL
    type TEXT     type TEXT into the open dialog's text field
    describe      print ``described {json}``: the title, the view's class, what it shows
    shot PATH     save the window, with the open dialog drawn over it, as a PNG
    close         close the window (as its × does)

``SimWindowProcess`` starts it and talks to it; ``RosCaller`` is another process on the
same master asking HOBBIT's tablet (a program's side).
"""
import json
import os
import queue
import subprocess
import sys
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


class _Lines:
    """A process's stdout, line by line, read in a thread so nothing blocks."""

    def __init__(self, process):
        self.lines = queue.Queue()
        self.seen = []
        threading.Thread(target=self._read, args=(process.stdout,), daemon=True).start()

    def _read(self, stream):
        for line in stream:
            self.lines.put(line.rstrip("\n"))
        self.lines.put(None)

    def expect(self, prefix: str, timeout: float = 30.0) -> str:
        """The next line starting with ``prefix`` (earlier lines are kept in ``seen``)."""
        deadline = time.monotonic() + timeout
        while True:
            try:
                line = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                raise AssertionError(f"no line starting with {prefix!r} in {timeout} s; seen: {self.seen}") from None
            if line is None:
                raise AssertionError(f"the process ended before a line starting with {prefix!r}; seen: {self.seen}")
            self.seen.append(line)
            if line.startswith(prefix):
                return line


class _Process:
    def __init__(self, args, env):
        self.process = subprocess.Popen([sys.executable, *map(str, args)], cwd=REPO, env=env, text=True,
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.out = _Lines(self.process)

    def send(self, line: str):
        self.process.stdin.write(line + "\n")
        self.process.stdin.flush()

    def wait(self, timeout: float = 20.0) -> int:
        return self.process.wait(timeout)

    def stderr(self) -> str:
        return self.process.stderr.read() if self.process.poll() is not None else ""

    def stop(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait(10)


class SimWindowProcess(_Process):
    """`rockly sim hobbit --ros` with its window, waiting for its ready line."""

    def __init__(self, master, env, *extra):
        super().__init__([__file__, "sim", "hobbit", "--ros", "--master", master.uri, "--speed", "20", *extra], env)
        self.out.expect("simulated HOBBIT is up on ROS")

    def dialog(self, timeout=30.0):
        """(kind, text) of the next tablet dialog that opens."""
        _, kind, text = self.out.expect("dialog ", timeout).split(" ", 2)
        return kind, json.loads(text)

    def describe(self) -> dict:
        self.send("describe")
        return json.loads(self.out.expect("described ").split(" ", 1)[1])


class RosCaller(_Process):
    """A program's side on ROS: each line sent is one HOBBIT command; prints ``result {json}``."""

    SCRIPT = """
import json, sys
from rockly_desktop.robot.ros1.link import RosRobot
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.interrupt import Interrupt

hobbit = ProfileRegistry.discover().get("hobbit")
api = hobbit.load_object("api")(RosRobot(hobbit, sys.argv[1]).backend(Interrupt()))
print("caller ready", flush=True)
for line in sys.stdin:
    command, _, argument = line.rstrip("\\n").partition(" ")
    try:
        result = getattr(api, command)(*json.loads(argument))
        print("result " + json.dumps({"value": result}), flush=True)
    except Exception as error:
        print("result " + json.dumps({"error": type(error).__name__, "message": str(error)}), flush=True)
"""

    def __init__(self, master, env):
        super().__init__(["-c", self.SCRIPT, master.uri], env)
        self.out.expect("caller ready")

    def start(self, command: str, *arguments):
        self.send(f"{command} {json.dumps(arguments)}")

    def result(self, timeout=30.0) -> dict:
        return json.loads(self.out.expect("result ", timeout).split(" ", 1)[1])

    def call(self, command: str, *arguments, timeout=30.0) -> dict:
        self.start(command, *arguments)
        return self.result(timeout)


def _run_window(argv) -> int:
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtCore import QObject, QPoint, QRect, Qt, QTimer, Signal
    from PySide6.QtGui import QColor, QImage, QPainter
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QPushButton

    from rockly_desktop import cli
    from rockly_desktop.app import create_application
    from rockly_desktop.ui.docks.tablet import TabletDialog

    app = create_application()

    def window():
        return next(w for w in app.topLevelWidgets() if w.objectName() == "sim_window")

    def dialogs():
        return [d for d in window().findChildren(TabletDialog) if d.isVisible()]

    reported = []  # the requests themselves: an id() could be reused by the next one

    def report_dialogs():
        for dialog in dialogs():
            if not any(request is dialog.request for request in reported):
                reported.append(dialog.request)
                print(f"dialog {dialog.request.question.value} {json.dumps(dialog.label.text())}", flush=True)

    def shot(path):
        """The window under a strip with its title (offscreen windows have no frame), the open
        dialog drawn where a window manager would put it, near the bottom, over the window."""
        main = window()
        content = main.grab()
        title_height = 28
        image = QImage(content.width(), content.height() + title_height, QImage.Format.Format_RGB32)
        image.fill(QColor("#37474f"))
        painter = QPainter(image)
        painter.setPen(QColor("white"))
        painter.drawText(QRect(0, 0, image.width(), title_height), Qt.AlignmentFlag.AlignCenter, main.windowTitle())
        painter.drawPixmap(0, title_height, content)
        open_now = dialogs()
        if open_now:
            picture = open_now[0].grab()
            corner = QPoint(max(0, (image.width() - picture.width()) // 3), image.height() - picture.height() - 60)
            painter.fillRect(corner.x() - 2, corner.y() - 2, picture.width() + 4, picture.height() + 4,
                             QColor("#37474f"))
            painter.drawPixmap(corner, picture)
        painter.end()
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        image.save(str(path))
        print(f"shot {path}", flush=True)

    def obey(line):
        command, _, argument = line.partition(" ")
        if command == "click":
            dialog = dialogs()[0]
            QTest.mouseClick(next(b for b in dialog.findChildren(QPushButton) if b.text() == argument),
                             Qt.MouseButton.LeftButton)
        elif command == "type":
            QTest.keyClicks(dialogs()[0].entry, argument)
        elif command == "describe":
            main = window()
            view = main.centralWidget()
            shown = view.snapshot() if hasattr(view, "snapshot") else {}
            print("described " + json.dumps({"title": main.windowTitle(), "view": type(view).__name__,
                                             "x": shown.get("x"), "tablet": shown.get("tablet"),
                                             "status": main.statusBar().currentMessage()}), flush=True)
        elif command == "shot":
            shot(argument)
        elif command in ("close", ""):  # "" : stdin ended
            window().close()

    class Remote(QObject):
        line = Signal(str)

    remote = Remote()
    remote.line.connect(obey, Qt.ConnectionType.QueuedConnection)

    def read_stdin():
        for line in sys.stdin:
            remote.line.emit(line.rstrip("\n"))
        remote.line.emit("")

    threading.Thread(target=read_stdin, daemon=True).start()
    poll = QTimer()
    poll.timeout.connect(report_dialogs)
    poll.start(30)
    return cli.main(argv)


if __name__ == "__main__":
    sys.path.insert(0, str(REPO))  # this checkout's Rockly, not whichever the environment has installed
    sys.exit(_run_window(sys.argv[1:]))
