"""Look at the block maker as a new user would, under a real X display (Xvfb, not offscreen), in English and
German: Tools → Make a block…, the /MMUI service of the simulated HOBBIT with its two text fields made
inputs, the sentence in both languages, the preview, saving, and the block in the toolbox afterwards.

    python tools/look_block_maker.py OUT_DIR [--language en de] [--display :97]

Each language starts Rockly afresh (a new home folder: no packs, no settings of the person running it),
drives it with xdotool as a person would (clicks and typed words, counted), and saves a screenshot
(ImageMagick's ``import -window root``) after each step into ``OUT_DIR/LANGUAGE-NN-step.png``. It prints
how many person actions the flow took and how long each step took to be on screen (including the waits
this script leaves for the screen to settle; the maker's own response is ``benchmarks/blockmaker.py``).

Needs Xvfb, xdotool and ImageMagick (``apt-get install xvfb xdotool imagemagick``), for looking only. The
clicks are placed relative to the maker's window as Rockly lays it out on a 1380x860 screen: after a
change to the maker's layout, look at the screenshots and adjust ``SPOTS``.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SCREEN = "1380x860x24"
MENU_KEYS = {"en": ("alt+t", "m"), "de": ("alt+w", "b")}  # Tools → Make a block…, Werkzeuge → Block bauen…
TITLES = {"en": ("Rockly", "Make a block"), "de": ("Rockly", "Einen Block bauen")}
SENTENCES = {"en": "ask %1 to say %2", "de": "frag %1 und sag %2"}
SPOTS = {  # (x, y) in the maker's window
    "first offer": (124, 47),
    "sessionID use": (738, 414),
    "requestText use": (738, 444),
    "sentence en": (824, 133),
    "sentence de": (824, 161),
}
AN_INPUT = 19  # "an input", the second entry of a use box's list, below the box's middle
FIRST_CATEGORY = (46, 85)  # the toolbox's first category (Drive / Fahren) in the main window


class Look:
    """Rockly under Xvfb on ``display`` in ``language``; screenshots into ``folder``."""

    def __init__(self, display: str, language: str, folder: Path):
        self.display, self.language, self.folder = display, language, folder
        self.home = Path(tempfile.mkdtemp(prefix="rockly-look-"))
        self.env = {**os.environ, "DISPLAY": display, "HOME": str(self.home),
                    "XDG_CONFIG_HOME": str(self.home / "config"), "XDG_DATA_HOME": str(self.home / "data"),
                    "QTWEBENGINE_DISABLE_SANDBOX": "1", "QT_QPA_PLATFORM": "xcb"}
        self.actions, self.shots, self.steps = 0, 0, []
        self.processes = []

    def start(self):
        """Xvfb, the window's language remembered as a person's last choice, then Rockly."""
        self.processes.append(subprocess.Popen(["Xvfb", self.display, "-screen", "0", SCREEN, "-nolisten", "tcp"],
                                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        self._wait(lambda: subprocess.run(["xdpyinfo"], env=self.env, capture_output=True).returncode == 0, 10)
        subprocess.run([sys.executable, "-c", "from rockly_desktop.settings.app_settings import AppSettings\n"
                        f"settings = AppSettings(); settings.language = {self.language!r}; settings.sync()"],
                       env=self.env, cwd=REPO, check=True)
        rockly = Path(sys.executable).parent / "rockly"
        self.processes.append(subprocess.Popen([str(rockly)], env=self.env, cwd=self.home,
                                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        self.main = self._wait(lambda: self.window(TITLES[self.language][0]), 60)
        time.sleep(4)  # the editor page and the simulator draw their first frames

    def stop(self):
        """End Rockly and Xvfb (only the processes this look started)."""
        for process in reversed(self.processes):
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        shutil.rmtree(self.home, ignore_errors=True)

    def xdo(self, *args) -> str:
        return subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True).stdout.strip()

    def window(self, title: str):
        """(id, x, y) of the visible window whose name has ``title``, or None."""
        for window in self.xdo("search", "--onlyvisible", "--name", title).split():
            geometry = dict(line.split("=") for line in self.xdo("getwindowgeometry", "--shell", window).split())
            return window, int(geometry["X"]), int(geometry["Y"])
        return None

    def click(self, place, x: int, y: int):
        """A person's click at (x, y) in the window ``place`` ((id, x, y))."""
        self.actions += 1
        self.xdo("mousemove", str(place[1] + x), str(place[2] + y), "click", "1")
        time.sleep(0.4)

    def key(self, *keys):
        """A person's key press (one action each)."""
        for key in keys:
            self.actions += 1
            self.xdo("key", key)
            time.sleep(0.4)

    def type(self, text: str):
        """A person typing ``text`` (one action per word)."""
        self.actions += len(text.split())
        self.xdo("type", "--delay", "40", text)
        time.sleep(0.6)

    def shot(self, name: str, started: float):
        """Save the screen as the next screenshot ``name``; note how long the step took."""
        self.shots += 1
        path = self.folder / f"{self.language}-{self.shots:02d}-{name}.png"
        subprocess.run(["import", "-window", "root", str(path)], env=self.env, check=True)
        self.steps.append((name, time.perf_counter() - started))
        print(f"  {path.name}: {self.steps[-1][1]:.1f} s")

    @staticmethod
    def _wait(condition, seconds: float):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            found = condition()
            if found:
                return found
            time.sleep(0.2)
        raise RuntimeError(f"gave up after {seconds} s")


def flow(look: Look):
    """The issue's flow: open the maker, pick /MMUI, two inputs, the sentences, save, see the toolbox."""
    language = look.language
    began = started = time.perf_counter()
    look.shot("window", started)
    look.xdo("windowfocus", "--sync", look.main[0])  # no window manager gives it the focus
    started = time.perf_counter()
    look.key(*MENU_KEYS[language])
    maker = look._wait(lambda: look.window(TITLES[language][1]), 30)
    time.sleep(1.5)  # the preview page's first frame
    look.shot("maker-open", started)
    started = time.perf_counter()
    look.type("MMUI")
    look.shot("filtered", started)
    started = time.perf_counter()
    look.click(maker, *SPOTS["first offer"])
    look.shot("service-chosen", started)
    started = time.perf_counter()
    for field in ("sessionID", "requestText"):
        x, y = SPOTS[f"{field} use"]
        look.click(maker, x, y)
        look.click(maker, x, y + AN_INPUT)
    look.shot("two-inputs", started)
    started = time.perf_counter()
    for code in ("en", "de"):
        look.click(maker, *SPOTS[f"sentence {code}"])
        look.type(SENTENCES[code])
    look.shot("sentences-and-preview", started)
    started = time.perf_counter()
    look.key("alt+s")  # &Save the block / Block &speichern
    look._wait(lambda: look.window(TITLES[language][1]) is None, 30)
    time.sleep(3)  # the editor page restarts with the new toolbox
    look.shot("saved", started)
    started = time.perf_counter()
    look.click(look.main, *FIRST_CATEGORY)
    time.sleep(1)
    look.shot("toolbox", started)
    steps = sum(seconds for _name, seconds in look.steps)
    print(f"{language}: {look.actions} person actions (clicks, keys, typed words), {look.shots} screenshots; "
          f"the flow took {time.perf_counter() - began:.1f} s scripted ({steps:.1f} s in its steps)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="where the screenshots go")
    parser.add_argument("--language", nargs="+", default=["en", "de"], choices=sorted(MENU_KEYS))
    parser.add_argument("--display", default=":97", help="the X display Xvfb makes (must be free)")
    options = parser.parse_args()
    options.folder.mkdir(parents=True, exist_ok=True)
    for language in options.language:
        look = Look(options.display, language, options.folder)
        try:
            look.start()
            flow(look)
        finally:
            look.stop()


if __name__ == "__main__":
    main()
