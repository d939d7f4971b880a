"""Start-up time: process start until the editor is ready with a 300-block program loaded.

Rockly (main window, HOBBIT toolbox, a 300-block .rockly file opened) is measured against
a bare QWebEngineView showing plain Blockly with its default renderer loading 300 of
Blockly's own blocks, in the same run, alternating, each in a fresh process. Each child also
reports when its phases ended (QApplication made, window built, program sent to the page, ready);
their medians are printed too, to show where the time goes.

    python benchmarks/startup.py [--runs N]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
BLOCK_COUNT = 300


def _chain(blocks):
    for upper, lower in zip(blocks, blocks[1:], strict=False):
        upper["next"] = {"block": lower}
    return blocks[0]


def rockly_program() -> dict:
    """A 300-block HOBBIT program: 150 drive blocks, each with its number block."""
    drives = [{"type": "hobbit_move", "fields": {"direction": "+"},
               "inputs": {"speed": {"block": {"type": "math_number", "fields": {"NUM": i}}}}}
              for i in range(BLOCK_COUNT // 2)]
    return {"format": "rockly-program", "version": 1, "profile": "hobbit",
            "workspace": {"blocks": {"languageVersion": 0, "blocks": [dict(_chain(drives), x=20, y=20)]}}}


def plain_program() -> dict:
    """300 of Blockly's own blocks: 150 print blocks, each with its text block."""
    prints = [{"type": "text_print", "inputs": {"TEXT": {"block": {"type": "text", "fields": {"TEXT": str(i)}}}}}
              for i in range(BLOCK_COUNT // 2)]
    return {"blocks": {"languageVersion": 0, "blocks": [dict(_chain(prints), x=20, y=20)]}}


BARE_PAGE = """<!doctype html><html><head><meta charset="utf-8">
<script src="{vendor}/blockly_compressed.js"></script><script src="{vendor}/blocks_compressed.js"></script>
<script src="{vendor}/python_compressed.js"></script><script src="{vendor}/msg/en.js"></script>
<style>html,body,#ws{{margin:0;height:100%}}</style></head><body><div id="ws"></div><script>
const toolbox = {{kind: 'flyoutToolbox',
                  contents: [{{kind: 'block', type: 'text_print'}}, {{kind: 'block', type: 'text'}}]}};
const ws = Blockly.inject('ws', {{toolbox, media: '{vendor}/media/'}});
Blockly.serialization.workspaces.load({program}, ws);
python.pythonGenerator.workspaceToCode(ws);
document.title = 'ready';
</script></body></html>"""


def phase(name: str):
    """Tell the parent that phase ``name`` ended (seconds since the parent started this process)."""
    print(f"PHASE {name} {time.time() - float(os.environ['STARTUP_T0']):.4f}", flush=True)


def child_bare(page: str):
    from PySide6.QtCore import QUrl
    from PySide6.QtWebEngineWidgets import QWebEngineView
    from PySide6.QtWidgets import QApplication

    app = QApplication([])
    phase("application")
    view = QWebEngineView()
    view.titleChanged.connect(lambda title: title == "ready" and (print("READY", flush=True), app.quit()))
    view.resize(1280, 800)
    view.show()
    view.load(QUrl.fromLocalFile(page))
    phase("page loading")
    app.exec()
    del view


def child_rockly(program: str, settings: str):
    from rockly_desktop.app import build_main_window, create_application

    app = create_application()
    phase("application")
    window = build_main_window(settings)
    phase("window built")
    code = window.code_dock.view

    def check():
        if code.toPlainText().count("\n") == BLOCK_COUNT // 2:
            print("READY", flush=True)
            window.document.modified = False
            app.quit()

    code.textChanged.connect(check)
    window.start(program)  # in run_gui's order
    phase("program sent")
    window.show()
    app.exec()
    window.deleteLater()


def time_child(args, phases=None) -> float:
    """Seconds from starting the process until it prints READY; the phases it reported are
    appended to ``phases`` ({name: [seconds, ...]}) when given."""
    env = dict(os.environ, QT_QPA_PLATFORM=os.environ.get("QT_QPA_PLATFORM", "offscreen"),
               QTWEBENGINE_DISABLE_SANDBOX="1", STARTUP_T0=repr(time.time()))
    started = time.perf_counter()
    process = subprocess.Popen([sys.executable, __file__, *args], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, text=True, env=env)
    reported = {}
    for line in process.stdout:
        if line.startswith("PHASE "):
            name, seconds = line[len("PHASE "):].rsplit(" ", 1)
            reported[name] = float(seconds)
        elif line.startswith("READY"):
            elapsed = time.perf_counter() - started
            break
    else:
        raise RuntimeError(f"child {args[0]} never became ready")
    process.wait(timeout=30)
    if phases is not None:
        for name, seconds in reported.items():
            phases.setdefault(name, []).append(seconds)
    return elapsed


def phase_medians(phases: dict, ready: list) -> str:
    """"name 0.123 s, ..." in the order the phases ended, then ready."""
    medians = {name: statistics.median(values) for name, values in phases.items()}
    medians["ready"] = statistics.median(ready)
    return ", ".join(f"{name} {seconds:.3f}" for name, seconds in sorted(medians.items(), key=lambda item: item[1]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    options = parser.parse_args()
    from rockly_desktop.core import paths

    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        program = folder / "large.rockly"
        program.write_text(json.dumps(rockly_program()))
        page = folder / "bare.html"
        vendor = paths.blockly_vendor_dir().as_uri()
        page.write_text(BARE_PAGE.format(vendor=vendor, program=json.dumps(plain_program())))
        time_child(["bare", str(page)])  # warm the file cache for both
        load_before = os.getloadavg()[0]
        bare, rockly, bare_phases, rockly_phases = [], [], {}, {}
        for run in range(options.runs):
            bare.append(time_child(["bare", str(page)], bare_phases))
            rockly.append(time_child(["rockly", str(program), str(folder / f"settings{run}.ini")], rockly_phases))
        load_after = os.getloadavg()[0]
    bare_median, rockly_median = statistics.median(bare), statistics.median(rockly)
    print(f"startup  plain Blockly in QWebEngineView: median {bare_median:.3f} s  "
          f"(min {min(bare):.3f}, max {max(bare):.3f}, {options.runs} runs)")
    print(f"startup  Rockly, HOBBIT, 300-block program: median {rockly_median:.3f} s  "
          f"(min {min(rockly):.3f}, max {max(rockly):.3f}, {options.runs} runs)")
    print(f"startup  phases ended (median s from process start): plain Blockly: {phase_medians(bare_phases, bare)}")
    print(f"startup  phases ended (median s from process start): Rockly: {phase_medians(rockly_phases, rockly)}")
    print(f"startup  ratio Rockly / plain Blockly: {rockly_median / bare_median:.2f}  (aim <= 1.20)")
    # Each pair ran back to back, so a pair's ratio is less moved by other work coming and going.
    pair_ratio = statistics.median(r / b for b, r in zip(bare, rockly, strict=True))
    print(f"startup  median of the {options.runs} pairs' ratios: {pair_ratio:.2f}; machine load "
          f"(1-minute average) {load_before:.2f} before, {load_after:.2f} after, on {os.cpu_count()} cores")


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "bare":
        child_bare(sys.argv[2])
    elif len(sys.argv) > 1 and sys.argv[1] == "rockly":
        child_rockly(sys.argv[2], sys.argv[3])
    else:
        main()
