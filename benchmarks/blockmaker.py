"""The block maker (issue 22): how fast it answers an edit, and the scripted time from opening it to a
working block in the toolbox, for HOBBIT's /MMUI service with two fields made inputs.

- response: one change until the preview page has drawn the block anew (median and max over 50 of
  each kind: the sentence typed, a field's use switched between input and default, the colour,
  and another offer chosen), against a baseline measured in the same window: one round trip of a
  page call to the editor (``getState``), the least any drawing can take;
- open to toolbox: Tools → Make a block… until the saved block is a block type of the editor page,
  against the editor page's own restart with the same profile (what showing the new toolbox costs).

    python benchmarks/blockmaker.py [--edits N] [--language en|de] [--shots DIR]

``--shots DIR`` also saves screenshots of the maker and of the toolbox afterwards into DIR.
"""
import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
for _name in ("XDG_DATA_HOME", "XDG_CONFIG_HOME"):  # a fresh user: no packs of the person running it
    os.environ[_name] = tempfile.mkdtemp(prefix="rockly-bench-maker-")

PARAMS = '[{name: type, value: D_PLAIN}, {name: text, value: "made by hand"}]'


def wait_until(predicate, timeout=60.0):
    """Process Qt events until ``predicate()`` is true; RuntimeError after ``timeout`` seconds."""
    from PySide6.QtWidgets import QApplication

    end = time.perf_counter() + timeout
    while not predicate():
        if time.perf_counter() > end:
            raise RuntimeError(f"timed out waiting for {predicate}")
        QApplication.processEvents()
        time.sleep(0.001)


def pause(seconds):
    """Let Qt run for ``seconds`` (screenshots only: a page's frame reaches its widget later)."""
    deadline = time.perf_counter() + seconds
    wait_until(lambda: time.perf_counter() > deadline)


def page_answer(view, name, args=None):
    """Call ``name`` on an editor page and wait for its answer."""
    answers = []
    view.call(name, args, lambda result, error: answers.append(result))
    wait_until(lambda: answers)
    return answers[0]


def open_window(settings_path, language):
    from rockly_desktop.app import build_main_window, create_application, prepare_qt_environment
    from rockly_desktop.settings.app_settings import AppSettings

    prepare_qt_environment()
    create_application([])
    settings = AppSettings(settings_path)
    settings.language = language
    settings.sync()
    window = build_main_window(settings_path)
    window.resize(1400, 900)
    window.show()
    ready = []
    window.editor.sig_ready.connect(lambda: ready.append(True))
    window.start()
    wait_until(lambda: ready)
    return window


def make_block(window, language):
    """Open the maker, make /MMUI's block and save it; returns (maker, seconds until it is in the toolbox)."""
    from PySide6.QtGui import QAction

    from rockly_desktop.ui.blockmaker.maker_dialog import BlockMakerDialog

    start = time.perf_counter()
    next(action for action in window.findChildren(QAction) if action.objectName() == "action_make_block").trigger()
    maker = window.findChild(BlockMakerDialog)
    wait_until(lambda: maker.preview.is_ready)
    maker.ready_after = time.perf_counter() - start
    maker.choose_named("/MMUI")
    maker.fields.set_use("sessionID", "input", "7")
    maker.fields.set_use("requestText", "input", "hello")
    maker.fields.set_use("params", "fixed", PARAMS)
    maker.sentence["en"].setText("ask %1 to say %2")
    maker.sentence["de"].setText("frag %1 und sag %2")
    maker.category.setEditText("My blocks" if language == "en" else "Meine Blöcke")
    maker.block_id.setText("made_say")
    wait_until(lambda: maker.preview.drawn is not None and not maker.preview.is_drawing)
    return maker, start


CHANGES = {
    "sentence typed": lambda maker, index: maker.sentence["en"].setText(f"ask %1 to say %2 ({index})"),
    "a field's use": lambda maker, index: maker.fields.set_use("sessionID", ("default", "input")[index % 2], "7"),
    "colour": lambda maker, index: maker.colour.box.setCurrentIndex((index + 1) % maker.colour.box.count()),
    "offer chosen": lambda maker, index: maker.choose_named(("/head/emo", "/MMUI")[index % 2]),
}
"""Each kind of change a person makes in the maker, as ``change(maker, index)``."""


def response_times(maker, edits, change=CHANGES["sentence typed"]):
    """Seconds from each ``change`` until the preview page drew it, and until the maker had checked
    the block and shown its problems and Python (its own part, before the page draws)."""
    drawn, checked, times, own = [], [], [], []
    maker.preview.sig_drawn.connect(lambda: drawn.append(time.perf_counter()))
    maker.sig_changed.connect(lambda: checked.append(time.perf_counter()))
    for index in range(edits):
        drawn.clear()
        checked.clear()
        start = time.perf_counter()
        change(maker, index)
        wait_until(lambda: drawn)
        times.append(drawn[0] - start)
        own.append(checked[0] - start)
    maker.preview.sig_drawn.disconnect()
    maker.sig_changed.disconnect()
    return times, own


def round_trips(view, count):
    times = []
    for _ in range(count):
        start = time.perf_counter()
        page_answer(view, "getState")
        times.append(time.perf_counter() - start)
    return times


def editor_restart(window):
    ready = []

    def on_ready():
        ready.append(time.perf_counter())
    window.editor.sig_ready.connect(on_ready)
    start = time.perf_counter()
    window._restart_editor()
    wait_until(lambda: ready)
    window.editor.sig_ready.disconnect(on_ready)  # only its own: the window's keyboard access follows it too
    return ready[0] - start


def show_toolbox_category(window, name):
    """Open the toolbox category ``name`` (its flyout shows its blocks)."""
    script = f"""(() => {{ const box = Blockly.getMainWorkspace().getToolbox();
        const item = box.getToolboxItems().find((i) => i.getName && i.getName() === {name!r});
        box.setSelectedItem(item); return true; }})()"""
    done = []
    window.editor.page().runJavaScript(script, 0, done.append)
    wait_until(lambda: done)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--edits", type=int, default=50)
    parser.add_argument("--language", default="en")
    parser.add_argument("--shots", type=Path)
    options = parser.parse_args()
    window = open_window(Path(tempfile.mkdtemp(prefix="rockly-bench-maker-")) / "settings.ini", options.language)
    maker, start = make_block(window, options.language)
    if options.shots:
        options.shots.mkdir(parents=True, exist_ok=True)
        pause(0.5)  # the page's drawing reaches the widget on its next frames
        maker.grab().save(str(options.shots / f"maker-{options.language}.png"))
        maker.preview.grab().save(str(options.shots / f"preview-{options.language}.png"))
    maker.save_button.click()
    wait_until(lambda: "made_say" in window.editor.known_block_types)
    to_toolbox = time.perf_counter() - start
    if options.shots:
        wait_until(lambda: window.editor.is_ready)
        show_toolbox_category(window, "My blocks" if options.language == "en" else "Meine Blöcke")
        pause(1.0)  # the flyout opens on the next frames
        window.grab().save(str(options.shots / f"toolbox-{options.language}.png"))

    from PySide6.QtCore import QCoreApplication, QEvent

    from rockly_desktop.ui.blockmaker.maker_dialog import open_block_maker
    from rockly_desktop.ui.blockmaker.offers import LiveGraph

    again = open_block_maker(window.profile, options.language, LiveGraph, window)
    wait_until(lambda: again.preview.is_ready)
    again.choose_named("/MMUI")
    again.fields.set_use("sessionID", "input", "7")
    again.fields.set_use("requestText", "input", "hello")
    again.sentence["en"].setText("ask %1 to say %2")
    wait_until(lambda: again.preview.drawn is not None and not again.preview.is_drawing)
    edits, own = response_times(again, options.edits)
    others = {name: response_times(again, options.edits, change) for name, change in CHANGES.items()
              if name != "sentence typed"}
    baseline = round_trips(again.preview, options.edits)
    restart = editor_restart(window)
    median, base = statistics.median(edits), statistics.median(baseline)
    print(f"maker response to an edit (preview drawn), {options.edits} edits: median {median * 1000:.1f} ms, "
          f"max {max(edits) * 1000:.1f} ms; of which the maker's own check, Python and drawing request: median "
          f"{statistics.median(own) * 1000:.1f} ms, max {max(own) * 1000:.1f} ms")
    for name, (times, checks) in others.items():
        print(f"maker response to {name} (preview drawn), {options.edits} changes: median "
              f"{statistics.median(times) * 1000:.1f} ms, max {max(times) * 1000:.1f} ms; the maker's own part: "
              f"median {statistics.median(checks) * 1000:.1f} ms, max {max(checks) * 1000:.1f} ms")
    print(f"baseline: one page-call round trip: median {base * 1000:.1f} ms, max {max(baseline) * 1000:.1f} ms"
          f" -> ratio {median / base:.2f}")
    print(f"scripted: opening the maker to the block in the toolbox (/MMUI, two inputs): {to_toolbox:.2f} s "
          f"(of which the preview page getting ready: {maker.ready_after:.2f} s)")
    print(f"baseline: the editor page's restart with the profile: {restart:.2f} s -> ratio {to_toolbox / restart:.2f}")
    again.close()
    window.document.modified = False
    window.close()
    window.deleteLater()  # now, as the tests' windows are: a page left for the interpreter's exit crashes QtWebEngine
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


if __name__ == "__main__":
    main()
