"""Qt's own texts and number formats in the window's language.

Standard buttons (Save, Discard, Cancel), "Show Details…" and the file dialog come from
Qt, not from ``texts.py``; their German lives in ``qtbase_de.qm``, which PySide6 ships in
its translations folder. ``use_language`` installs it (and makes the language's locale
the default, so the file dialog's sizes and dates match); English needs no file.
"""
from PySide6.QtCore import QCoreApplication, QLibraryInfo, QLocale, QTranslator

CATALOGUE = "qtbase"
_installed = {}  # the application's one translator of Qt's texts, while one is installed


def translations_folder() -> str:
    """Where PySide6 keeps Qt's translation files."""
    return QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)


def use_language(language: str) -> bool:
    """Show Qt's texts in ``language`` from now on; False if Qt has no translation for it (English then)."""
    app = QCoreApplication.instance()
    previous = _installed.pop("translator", None)
    if previous is not None and app is not None:
        app.removeTranslator(previous)
    locale = QLocale(language)
    QLocale.setDefault(locale)
    if app is None or language == "en":
        return language == "en"
    translator = QTranslator(app)
    if not translator.load(locale, CATALOGUE, "_", translations_folder()):
        translator.deleteLater()
        return False
    app.installTranslator(translator)
    _installed["translator"] = translator
    return True
