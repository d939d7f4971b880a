"""The window's texts in English and German (block texts come from the profiles)."""

LANGUAGE_NAMES = {"en": "English", "de": "Deutsch"}

_TEXTS = {
    "app_name": ("Rockly", "Rockly"),
    "untitled": ("Untitled", "Unbenannt"),
    "menu_file": ("&File", "&Datei"),
    "new": ("&New", "&Neu"),
    "open": ("&Open…", "Ö&ffnen…"),
    "open_recent": ("Open &Recent", "&Zuletzt geöffnet"),
    "clear_recent": ("Clear List", "Liste leeren"),
    "save": ("&Save", "&Speichern"),
    "save_as": ("Save &As…", "Speichern &unter…"),
    "import_xml": ("&Import First-Rockly Program (XML)…", "Programm aus dem ersten Rockly &importieren (XML)…"),
    "export_python": ("&Export Python…", "Python &exportieren…"),
    "quit": ("&Quit", "&Beenden"),
    "menu_edit": ("&Edit", "&Bearbeiten"),
    "undo": ("&Undo", "&Rückgängig"),
    "redo": ("&Redo", "&Wiederholen"),
    "menu_robot": ("&Robot", "&Roboter"),
    "menu_view": ("&View", "&Ansicht"),
    "menu_settings": ("&Settings", "&Einstellungen"),
    "preferences": ("&Preferences…", "&Einstellungen…"),
    "menu_help": ("&Help", "&Hilfe"),
    "about": ("&About Rockly", "Über &Rockly"),
    "about_text": ("Rockly {version}: program robots by snapping blocks together.",
                   "Rockly {version}: Roboter programmieren, indem man Blöcke zusammensteckt."),
    "code_dock": ("Python code", "Python-Code"),
    "robot_status": ("Robot: {name}", "Roboter: {name}"),
    "loading_editor": ("Starting the block editor…", "Der Block-Editor startet…"),
    "filter_program": ("Rockly programs (*.rockly)", "Rockly-Programme (*.rockly)"),
    "filter_open": ("Programs (*.rockly *.xml)", "Programme (*.rockly *.xml)"),
    "filter_xml": ("First-Rockly programs (*.xml)", "Programme aus dem ersten Rockly (*.xml)"),
    "filter_python": ("Python files (*.py)", "Python-Dateien (*.py)"),
    "save_changes_title": ("Unsaved changes", "Ungespeicherte Änderungen"),
    "save_changes": ("Save the changes to “{name}”?", "Änderungen an „{name}“ speichern?"),
    "save_changes_detail": ("Your changes will be lost if you don't save them.",
                            "Deine Änderungen gehen verloren, wenn du sie nicht speicherst."),
    "cannot_open": ("Cannot open the program", "Das Programm kann nicht geöffnet werden"),
    "cannot_save": ("Cannot save the program", "Das Programm kann nicht gespeichert werden"),
    "cannot_export": ("Cannot export the Python code", "Der Python-Code kann nicht exportiert werden"),
    "nothing_changed": ("Your current program has not been changed.", "Dein aktuelles Programm wurde nicht verändert."),
    "saved": ("Saved {path}", "Gespeichert: {path}"),
    "opened": ("Opened {path}", "Geöffnet: {path}"),
    "imported": ("Imported {path} – save it as a Rockly program to keep it",
                 "Importiert: {path} – speichere es als Rockly-Programm, um es zu behalten"),
    "exported": ("Exported the Python code to {path}", "Python-Code exportiert nach {path}"),
    "profile_errors_title": ("Some robot profiles could not be loaded", "Einige Roboterprofile konnten nicht geladen werden"),
    "editor_error": ("The block editor reported a problem: {message}", "Der Block-Editor meldet ein Problem: {message}"),
    "preferences_title": ("Preferences", "Einstellungen"),
    "language": ("Language", "Sprache"),
    "switch_profile_title": ("Change the robot", "Roboter wechseln"),
    "switch_profile": ("Start a new program for {name}?", "Ein neues Programm für {name} beginnen?"),
}


def tr(key: str, language: str, **values) -> str:
    """The text ``key`` in ``language`` (English or German), with ``values`` filled in."""
    english, german = _TEXTS[key]
    text = german if language == "de" else english
    return text.format(**values) if values else text
