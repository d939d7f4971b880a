"""The composition root: builds the Qt application, the profiles and the main window."""
import gc
import logging
import os
import sys

from rockly_desktop.core import paths

START_SWITCH_INTERVAL = 0.0005  # seconds; the GUI thread waits at most this long for the worker's GIL
WARM_UP_MS = 1000  # after the window shows, the first run's program process starts (Run -> first block is quick)


def prepare_qt_environment():
    """Settings QtWebEngine needs before the QApplication exists.

    Chromium's sandbox cannot start as root (fairs often run kiosk laptops as root),
    so it is disabled there; everywhere else the sandbox stays on.
    """
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")
    flags = os.environ.get("QTWEBENGINE_CHROMIUM_FLAGS", "")
    if "--log-level" not in flags:
        # Chromium's own log (D-Bus, GPU probing) means nothing to Rockly's users.
        flags = f"{flags} --log-level=3"
    if "--disable-renderer-backgrounding" not in flags:
        # The editor page loads its start-up program before the window shows (``run_gui``): Chromium would run
        # a page not yet on screen at a lower priority, and load it a third slower.
        flags = f"{flags} --disable-renderer-backgrounding"
    os.environ["QTWEBENGINE_CHROMIUM_FLAGS"] = flags.strip()


def route_qt_messages_to_logging():
    """Send Qt's messages to the ``qt`` logger: rendering fallbacks and the like are not
    shown unless logging is turned up (``ROCKLY_LOG=debug``); real errors still are."""
    from PySide6.QtCore import QtMsgType, qInstallMessageHandler

    logger = logging.getLogger("qt")
    levels = {QtMsgType.QtDebugMsg: logging.DEBUG, QtMsgType.QtInfoMsg: logging.DEBUG,
              QtMsgType.QtWarningMsg: logging.INFO, QtMsgType.QtCriticalMsg: logging.ERROR,
              QtMsgType.QtFatalMsg: logging.CRITICAL}

    def handler(kind, _context, message):
        logger.log(levels.get(kind, logging.INFO), "%s", message)

    qInstallMessageHandler(handler)


def create_application(argv=None):
    """The QApplication (created once), with Rockly's names and icon."""
    prepare_qt_environment()
    from PySide6.QtCore import QCoreApplication, Qt
    from PySide6.QtGui import QIcon
    from PySide6.QtWidgets import QApplication

    app = QApplication.instance()
    if app is None:
        route_qt_messages_to_logging()
        QCoreApplication.setAttribute(Qt.ApplicationAttribute.AA_ShareOpenGLContexts)
        app = QApplication(list(argv or sys.argv[:1]))
        app.setOrganizationName("Rockly")
        app.setApplicationName("Rockly")
        app.setDesktopFileName("rockly")
        app.setWindowIcon(QIcon(str(paths.data_root() / "resources" / "icons" / "rockly.svg")))
    return app


def build_main_window(settings_path=None, extra_profile_dirs=(), kiosk: bool = False):
    """The main window with every installed profile; ``settings_path`` picks a settings file;
    ``kiosk``: the settings of a kiosk session (see ``start_kiosk``).

    Python's garbage collector waits meanwhile: the start makes some 100,000 objects, most for good
    (modules, classes), and collecting among them as they came took 17–70 ms of it. What the start made
    is kept out of collections (``gc.freeze``) until the editor is ready, so the first ones stay short.
    """
    from PySide6.QtCore import Qt

    gc.disable()
    try:
        window = _build_main_window(settings_path, extra_profile_dirs, kiosk)
    except BaseException:
        gc.enable()
        raise
    gc.freeze()
    gc.enable()
    window.editor.sig_ready.connect(gc.unfreeze, Qt.ConnectionType.SingleShotConnection)
    return window


def _build_main_window(settings_path, extra_profile_dirs, kiosk):
    from rockly_desktop.bridge.editor_view import EditorView

    editor = EditorView()  # Chromium loads the page while Python reads profiles and builds the window
    registry, first_setup, look = while_events_run(lambda: _read_profiles(settings_path, extra_profile_dirs))
    editor.set_look(look)  # before the setup, which then injects Blockly in it
    if first_setup is not None:  # the page builds that profile's workspace while the window is made
        editor.prepare(*first_setup)
    main_window_class = while_events_run(_main_window_class)
    from rockly_desktop.settings.app_settings import AppSettings
    from rockly_desktop.ui.qt_language import use_language

    settings = AppSettings(settings_path)
    settings.kiosk_mode = kiosk
    use_language(settings.language)  # Qt's own buttons and dialogs, now and whenever the language changes
    settings.current_language.watch(use_language)
    return main_window_class(registry, settings, editor)


def _read_profiles(settings_path, extra_profile_dirs):
    """The installed profiles, ``EditorView.prepare``'s arguments for the one the window starts
    with, as the settings name it (None if no profile is installed), and the blocks' look."""
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.settings.app_settings import AppSettings
    from rockly_desktop.ui.texts import editor_page_texts

    remembered = AppSettings(settings_path)  # this thread's own reader; the window makes its own
    language, profile_id = remembered.language, remembered.profile_id
    registry = ProfileRegistry.discover(extra_profile_dirs)
    if not registry.profiles:
        return registry, None, remembered.block_look
    first = registry.profiles.get(profile_id) or registry.default()  # as MainWindow picks it
    return registry, (first.editor_config(language), language, editor_page_texts(language)), remembered.block_look


def _main_window_class():
    from rockly_desktop.ui.main_window import MainWindow

    return MainWindow


def while_events_run(work):
    """Return ``work()``, run in a worker thread while this thread runs Qt's event loop.

    Chromium's browser side lives on the GUI thread: the editor page only loads while the
    event loop runs. Importing modules and reading files need no GUI thread, so the page
    loads meanwhile. ``work`` must not touch widgets; its exception is raised here.
    """
    from concurrent.futures import ThreadPoolExecutor

    from PySide6.QtCore import QEventLoop, QMetaObject, Qt

    loop = QEventLoop()
    switch_interval = sys.getswitchinterval()
    sys.setswitchinterval(START_SWITCH_INTERVAL)  # Chromium calls Python for each request the page makes
    try:
        with ThreadPoolExecutor(1, thread_name_prefix="rockly-start") as pool:
            future = pool.submit(work)
            future.add_done_callback(
                lambda _: QMetaObject.invokeMethod(loop, "quit", Qt.ConnectionType.QueuedConnection))
            loop.exec()
    finally:
        sys.setswitchinterval(switch_interval)
    return future.result()


def run_gui(open_path=None, kiosk: bool = False) -> int:
    """Start Rockly's window (in kiosk mode: full screen, with ``open_path`` as the start program)
    and run until it closes."""
    from rockly_desktop.core.errors import RocklyError

    app = create_application()
    try:
        window = build_main_window(kiosk=kiosk)
    except RocklyError as error:  # e.g. every installed profile is broken
        from PySide6.QtWidgets import QMessageBox

        QMessageBox.critical(None, "Rockly", f"Rockly cannot start: {error}")
        return 1
    if kiosk and start_kiosk(window, open_path) is None:
        return 2
    window.start(open_path)
    if not kiosk:  # after start(): the page loads the program before Chromium draws an empty editor (decision 017)
        window.show()
    from PySide6.QtCore import QTimer

    QTimer.singleShot(WARM_UP_MS, window.runs.warm_up)  # the program's process of the first run (decision 041)
    return app.exec()


def start_kiosk(window, start_program=None):
    """Make ``window`` (built with ``kiosk=True``) a kiosk with ``start_program`` and show it full
    screen; the caller then starts it with the same program. Returns the Kiosk, or None (after
    saying why) when no teacher PIN or key chord is set: nobody could leave it."""
    from rockly_desktop.ui.kiosk.kiosk import can_be_left

    if not can_be_left(window.settings):
        from PySide6.QtWidgets import QMessageBox

        from rockly_desktop.ui.texts import tr

        QMessageBox.critical(None, tr("kiosk_no_way_out_title", window.language),
                             tr("kiosk_no_way_out", window.language))
        window.deleteLater()
        return None
    kiosk = window.become_kiosk(start_program)
    window.showFullScreen()
    return kiosk


def generate_headless(program_path, language: str = "en", python_profile: str = None):
    """Read a program file and let a windowless editor generate its Python (a ``.py`` program is first turned
    into blocks in memory, ``python_blocks.program_file``, for ``python_profile``: by default the robot its header
    names).

    Returns (ProgramToOpen, plain Python, instrumented run code, workspace JSON). Raises
    RocklyError with a message for people: a bad file, no profile, unknown blocks, or a
    program Blockly refuses.
    """
    for _path, generated in generate_many([program_path], language, python_profile):
        if isinstance(generated, Exception):
            raise generated
        return generated


def generate_many(program_paths, language: str = "en", python_profile: str = None):
    """Yield ``(path, generated)`` for each program file, generated by one windowless editor in turn
    (``rockly lessons check`` of a class's programs): ``generated`` is what ``generate_headless``
    returns, or the RocklyError that says why that program could not be generated (``python_profile``: as
    ``generate_headless`` takes it, for every ``.py`` among them).
    """
    if not os.environ.get("QT_QPA_PLATFORM"):
        os.environ["QT_QPA_PLATFORM"] = "offscreen"  # no window: works over ssh and in CI
    from rockly_desktop.bridge.headless import HeadlessEditor, UnknownBlocks
    from rockly_desktop.core.app_texts import app_text
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.profiles.opening import read_program_to_open, unknown_blocks_error
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.python_blocks.program_file import is_python_program, read_python_program_to_open

    create_application()
    registry = ProfileRegistry.discover()
    if not registry.profiles:
        raise RocklyError(app_text("cli_no_profile", language))
    editor = HeadlessEditor(language)
    try:
        for program_path in program_paths:
            try:
                if is_python_program(program_path):
                    program = read_python_program_to_open(program_path, registry, python_profile)
                else:
                    program = read_program_to_open(program_path, registry, registry.default())
                python = editor.python_for(program)
                run_code = editor.call_and_wait("getRunCode")
                workspace = editor.call_and_wait("getState")["workspace"]
            except UnknownBlocks as refused:
                yield program_path, unknown_blocks_error(program, refused.block_types, registry)
            except RuntimeError as error:
                yield program_path, RocklyError(app_text("cli_editor_refused", language, path=program_path,
                                                         error=error))
            except RocklyError as error:
                yield program_path, error
            else:
                yield program_path, (program, python, run_code, workspace)
    finally:
        editor.close()
