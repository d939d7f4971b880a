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
    "opened_with_changes": ("The program was opened with changes", "Das Programm wurde mit Änderungen geöffnet"),
    "opened_with_changes_detail": (
        "The file itself is unchanged. Saving writes the program as it is shown now; close it without saving "
        "to keep the file as it was.",
        "Die Datei selbst ist unverändert. Beim Speichern wird das Programm so geschrieben, wie es jetzt "
        "angezeigt wird; schließe es ohne zu speichern, um die Datei so zu behalten."),
    "missing_profile": (
        "This program was made for the robot profile “{declared}”, which is not installed here (installed: "
        "{installed}). It is shown with the blocks of {name}; saving it makes it a program for {name}.",
        "Dieses Programm wurde für das Roboterprofil „{declared}“ gemacht, das hier nicht installiert ist "
        "(installiert: {installed}). Es wird mit den Blöcken von {name} gezeigt; beim Speichern wird es ein "
        "Programm für {name}."),
    "replaced_fields": ("Some values in this program do not fit their blocks and were replaced:",
                        "Einige Werte in diesem Programm passen nicht zu ihren Blöcken und wurden ersetzt:"),
    "replaced_field": ("Block {number} ({type}), {field}: “{requested}” → “{now}”",
                       "Block {number} ({type}), {field}: „{requested}“ → „{now}“"),
    "field_left_out": ("Block {number} ({type}) has no field {field}: “{requested}” was left out",
                       "Block {number} ({type}) hat kein Feld {field}: „{requested}“ wurde weggelassen"),
    "recovery_title": ("Restore unsaved work?", "Ungespeicherte Arbeit wiederherstellen?"),
    "recovery_found": ("Rockly did not close properly last time. Your program “{name}” had changes that were not "
                       "saved, and Rockly kept a copy of them.",
                       "Rockly wurde beim letzten Mal nicht richtig beendet. Dein Programm „{name}“ hatte "
                       "ungespeicherte Änderungen, und Rockly hat eine Kopie davon aufbewahrt."),
    "recovery_file": ("File: {path}", "Datei: {path}"),
    "recovery_no_file": ("File: none (the program was never saved)",
                         "Datei: keine (das Programm wurde nie gespeichert)"),
    "recovery_when": ("Copy from: {date}, {time}", "Kopie vom: {date}, {time}"),
    "recovery_choice": ("Restore opens the copy with its changes still unsaved. Discard deletes the copy.",
                        "Wiederherstellen öffnet die Kopie, ihre Änderungen sind noch nicht gespeichert. "
                        "Verwerfen löscht die Kopie."),
    "recovery_restore": ("Restore", "Wiederherstellen"),
    "recovery_discard": ("Discard", "Verwerfen"),
    "restored": ("Restored the unsaved program – save it to keep it",
                 "Das ungespeicherte Programm ist wiederhergestellt – speichere es, um es zu behalten"),
    "autosave_failed": ("Rockly could not keep a copy of your unsaved changes: {error}",
                        "Rockly konnte keine Kopie deiner ungespeicherten Änderungen anlegen: {error}"),
    "profile_errors_title": ("Some robot profiles could not be loaded",
                             "Einige Roboterprofile konnten nicht geladen werden"),
    "editor_error": ("The block editor reported a problem: {message}",
                     "Der Block-Editor meldet ein Problem: {message}"),
    "preferences_title": ("Preferences", "Einstellungen"),
    "language": ("Language", "Sprache"),
    "preferences_general": ("General", "Allgemein"),
    "teacher_tab": ("Teacher", "Lehrkraft"),
    "teacher_locked": ("Enter the teacher's PIN to change these settings.",
                       "Gib die PIN der Lehrkraft ein, um diese Einstellungen zu ändern."),
    "teacher_new_pin": ("Choose a PIN (at least {count} characters) that guards the teacher's settings.",
                        "Wähle eine PIN (mindestens {count} Zeichen), die die Einstellungen der Lehrkraft schützt."),
    "teacher_pin": ("PIN", "PIN"),
    "teacher_pin_again": ("PIN again", "PIN wiederholen"),
    "teacher_unlock": ("Unlock", "Entsperren"),
    "teacher_set_pin": ("Set PIN", "PIN festlegen"),
    "teacher_wrong_pin": ("Wrong PIN.", "Falsche PIN."),
    "teacher_pin_short": ("The PIN needs at least {count} characters.", "Die PIN braucht mindestens {count} Zeichen."),
    "teacher_pin_mismatch": ("The two PINs differ.", "Die beiden PINs sind verschieden."),
    "teacher_for": ("Settings for {name}", "Einstellungen für {name}"),
    "teacher_level": ("Toolbox level", "Stufe der Blöcke"),
    "teacher_all_blocks": ("All blocks", "Alle Blöcke"),
    "teacher_max_speed": ("Maximum driving speed", "Höchstes Fahrtempo"),
    "teacher_max_turn": ("Maximum turning speed", "Höchstes Drehtempo"),
    "teacher_no_limit": ("no limit", "keine Grenze"),
    "teacher_allowed": ("Allowed", "Erlaubt"),
    "switch_profile_title": ("Change the robot", "Roboter wechseln"),
    "switch_profile": ("Start a new program for {name}?", "Ein neues Programm für {name} beginnen?"),
    "run": ("Run", "Start"),
    "pause": ("Pause", "Pause"),
    "step": ("Step", "Schritt"),
    "continue": ("Continue", "Weiter"),
    "stop": ("STOP", "STOPP"),
    "run_tip": ("Run the program (F5)", "Programm starten (F5)"),
    "pause_tip": ("Pause before the next block (F6)", "Vor dem nächsten Block anhalten (F6)"),
    "step_tip": ("Run one block, then pause (F10)", "Einen Block ausführen, dann anhalten (F10)"),
    "continue_tip": ("Continue the paused program (F5)", "Das angehaltene Programm fortsetzen (F5)"),
    "stop_tip": ("Stop the program and the robot (Esc)", "Programm und Roboter anhalten (Esc)"),
    "reset_robot": ("Put back", "Zurücksetzen"),
    "reset_robot_tip": ("Put the simulated robot back where it started (Ctrl+R)",
                        "Den simulierten Roboter an den Start zurücksetzen (Strg+R)"),
    "robot_put_back": ("The robot is back where it started.", "Der Roboter ist wieder am Start."),
    "robot_not_put_back": ("This robot cannot be put back.", "Dieser Roboter kann nicht zurückgesetzt werden."),
    "reset_before_run": ("Put the robot back before each Run", "Roboter vor jedem Start zurücksetzen"),
    "speed": ("Speed", "Tempo"),
    "slow": ("slow", "langsam"),
    "fast": ("fast", "schnell"),
    "speed_tip": ("Slow motion: wait at every block", "Zeitlupe: bei jedem Block warten"),
    "backend_simulator": ("Simulator (built in)", "Simulator (eingebaut)"),
    "backend_ros1": ("Real robot (ROS 1)…", "Echter Roboter (ROS 1)…"),
    "connect_title": ("Connect to {robot} over ROS", "Über ROS mit {robot} verbinden"),
    "connect_explanation": ("Rockly talks to the robot through its ROS master. Ask the robot's owner for its address.",
                            "Rockly spricht über den ROS-Master mit dem Roboter. Frag nach seiner Adresse."),
    "connect_master": ("ROS master (ROS_MASTER_URI)", "ROS-Master (ROS_MASTER_URI)"),
    "connect_host": ("This computer (ROS_IP or ROS_HOSTNAME)", "Dieser Computer (ROS_IP oder ROS_HOSTNAME)"),
    "connect_host_hint": ("e.g. 192.168.1.20 (empty: automatic)", "z. B. 192.168.1.20 (leer: automatisch)"),
    "connect_failed": ("Cannot connect to the robot", "Keine Verbindung zum Roboter"),
    "ros_no_master": ("No ROS master answers at {master}.", "Unter {master} antwortet kein ROS-Master."),
    "ros_no_master_hint": ("Is roscore running on that computer? Is the address right?",
                           "Läuft dort roscore? Stimmt die Adresse?"),
    "ros_no_rospy": ("ROS 1 is not installed on this computer, so Rockly cannot reach a real robot.",
                     "ROS 1 ist auf diesem Computer nicht installiert, deshalb erreicht Rockly keinen echten Roboter."),
    "ros_no_rospy_hint": ("Use the built-in simulator, or ask an adult to set up ROS 1: "
                          "“make setup” in Rockly's folder installs it (rospy).",
                          "Nimm den eingebauten Simulator oder bitte einen Erwachsenen, ROS 1 einzurichten: "
                          "„make setup“ im Rockly-Ordner installiert es (rospy)."),
    "ros_no_ros_tools": ("The ROS 1 message tools (genpy, actionlib) are not installed on this computer.",
                         "Die ROS-1-Nachrichtenwerkzeuge (genpy, actionlib) sind auf diesem Computer "
                         "nicht installiert."),
    "ros_no_ros_tools_hint": ("Use the built-in simulator, or ask an adult to install them: "
                              "“make setup” in Rockly's folder does it.",
                              "Nimm den eingebauten Simulator oder bitte einen Erwachsenen, sie zu installieren: "
                              "„make setup“ im Rockly-Ordner erledigt das."),
    "ros_other_master": ("Rockly is already connected to the ROS master at {current}, so it cannot use {wanted}.",
                         "Rockly ist schon mit dem ROS-Master unter {current} verbunden und kann deshalb "
                         "{wanted} nicht nutzen."),
    "ros_other_master_hint": ("Restart Rockly to use another ROS master.",
                              "Starte Rockly neu, um einen anderen ROS-Master zu nutzen."),
    "ros_connected": ("● ROS connected", "● ROS verbunden"),
    "ros_connecting": ("● ROS connecting…", "● ROS verbindet…"),
    "ros_lost": ("● ROS connection lost", "● ROS-Verbindung verloren"),
    "real_robot_view": ("Connected to the real robot over ROS.\nThe simulator view shows the built-in simulator only.",
                        "Mit dem echten Roboter über ROS verbunden.\n"
                        "Die Simulator-Ansicht zeigt nur den eingebauten Simulator."),
    "console_dock": ("Console", "Konsole"),
    "variables_dock": ("Variables", "Variablen"),
    "simulator_dock": ("Simulator", "Simulator"),
    "variable": ("Variable", "Variable"),
    "value": ("Value", "Wert"),
    "add_breakpoint": ("Pause here (breakpoint)", "Hier anhalten (Haltepunkt)"),
    "remove_breakpoint": ("Remove breakpoint", "Haltepunkt entfernen"),
    "run_started": ("Program started", "Programm gestartet"),
    "ros_address_title": ("The robot may not reach this computer",
                          "Der Roboter erreicht diesen Computer vielleicht nicht"),
    "ros_address_ipv6": ("ROS_IP is {address}, an IPv6 address, but ROS_IPV6 is not “on”: the robot cannot connect "
                         "back to this computer, so the program's commands would never arrive. Give this computer's "
                         "IPv4 address (127.0.0.1 for a robot on this computer) and restart Rockly.",
                         "ROS_IP ist {address}, eine IPv6-Adresse, aber ROS_IPV6 ist nicht „on“: Der Roboter kann "
                         "diesen Computer nicht erreichen, die Befehle des Programms kämen nie an. Gib die "
                         "IPv4-Adresse dieses Computers an (127.0.0.1 für einen Roboter auf diesem Computer) und "
                         "starte Rockly neu."),
    "ros_address_not_local": ("ROS_IP is {address}, which is not an address of this computer: the robot cannot "
                              "connect back to it, so the program's commands would never arrive.",
                              "ROS_IP ist {address}, aber das ist keine Adresse dieses Computers: Der Roboter kann "
                              "ihn nicht erreichen, die Befehle des Programms kämen nie an."),
    "output_skipped": ("… {count} more lines were printed too fast to show",
                       "… {count} weitere Zeilen kamen zu schnell, um sie zu zeigen"),
    "run_empty": ("There is nothing to run yet: drag blocks from the list on the left into the workspace.",
                  "Noch gibt es nichts zu starten: Zieh Blöcke aus der Liste links auf die Arbeitsfläche."),
    "run_not_started": ("The program was not started: the block editor did not give its code ({error}).",
                        "Das Programm wurde nicht gestartet: Der Block-Editor hat seinen Code "
                        "nicht geliefert ({error})."),
    "run_finished": ("Program finished", "Programm beendet"),
    "run_stopped": ("Program stopped", "Programm gestoppt"),
    "run_failed": ("Program stopped because of an error", "Programm wegen eines Fehlers gestoppt"),
    "paused": ("Paused before the highlighted block", "Angehalten vor dem markierten Block"),
    "paused_breakpoint": ("Paused at a breakpoint", "An einem Haltepunkt angehalten"),
    "error_title": ("Something went wrong", "Etwas ist schiefgegangen"),
    "tablet_title": ("{robot}'s tablet", "Tablet von {robot}"),
    "yes": ("Yes", "Ja"),
    "no": ("No", "Nein"),
    "ok": ("OK", "OK"),
    "robot_says": ("Robot: {text}", "Roboter: {text}"),
    "sim_window_title": ("{robot} (simulated) on ROS — {master}", "{robot} (simuliert) auf ROS — {master}"),
    "sim_window_status": ("Tablet questions open here. Close this window to end the robot.",
                          "Tablet-Fragen erscheinen hier. Schließe das Fenster, um den Roboter zu beenden."),
    "sim_window_master": ("ROS master: {master}", "ROS-Master: {master}"),
    "sim_no_view": ("This robot profile has no simulator view; its tablet questions still open here.",
                    "Dieses Roboterprofil hat keine Simulatoransicht; Tablet-Fragen erscheinen trotzdem hier."),
    "state_dock": ("Robot state", "Roboterzustand"),
    "monitor_dock": ("Topic monitor", "Topic-Monitor"),
    "plot_dock": ("Plot", "Diagramm"),
    "health_title": ("Connection to the robot", "Verbindung zum Roboter"),
    "health_green": ("Connection: all good", "Verbindung: alles gut"),
    "health_amber": ("Connection: check the details", "Verbindung: Details prüfen"),
    "health_red": ("Connection: problem", "Verbindung: Problem"),
    "goal_pending": ("waiting", "wartet"),
    "goal_active": ("working", "läuft"),
    "goal_preempted": ("cancelled", "abgebrochen"),
    "goal_succeeded": ("done", "fertig"),
    "goal_aborted": ("failed", "fehlgeschlagen"),
    "goal_rejected": ("refused", "abgelehnt"),
    "goal_lost": ("unknown", "unbekannt"),
    "plot_window": ("Show the last", "Zeige die letzten"),
    "plot_window_tip": ("How much time the plot shows", "Wie viel Zeit der Plot zeigt"),
    "plot_pause": ("Pause", "Anhalten"),
    "plot_resume": ("Resume", "Weiter"),
    "plot_pause_tip": ("Freeze the plot (the data keeps being recorded)",
                       "Plot einfrieren (die Daten werden weiter aufgezeichnet)"),
    "plot_clear": ("Clear", "Leeren"),
    "plot_clear_tip": ("Remove all curves", "Alle Kurven entfernen"),
    "plot_add": ("Add…", "Hinzufügen…"),
    "plot_add_tip": ("Plot a numeric field of a topic", "Ein Zahlenfeld eines Topics plotten"),
    "plot_add_button": ("Add", "Hinzufügen"),
    "plot_topic": ("Topic", "Topic"),
    "plot_field": ("Field", "Feld"),
    "plot_field_hint": ("e.g. pose.pose.position.x", "z. B. pose.pose.position.x"),
    "plot_export": ("Export…", "Exportieren…"),
    "plot_export_csv": ("Save data as CSV…", "Daten als CSV speichern…"),
    "plot_export_png": ("Save image as PNG…", "Bild als PNG speichern…"),
    "plot_filter_csv": ("CSV files (*.csv)", "CSV-Dateien (*.csv)"),
    "plot_filter_png": ("PNG images (*.png)", "PNG-Bilder (*.png)"),
    "plot_export_failed": ("Cannot export the plot", "Der Plot kann nicht exportiert werden"),
    "plot_time_axis": ("Time", "Zeit"),
    "plot_value_axis": ("Value", "Wert"),
    "plot_hint": ("Drop a field here or use Add… to plot it",
                  "Zieh ein Feld hierher oder plotte es mit Hinzufügen…"),
    "monitor_topic": ("Topic", "Topic"),
    "monitor_type": ("Type", "Typ"),
    "monitor_publishers": ("Publishers", "Publisher"),
    "monitor_rate": ("Rate (Hz)", "Rate (Hz)"),
    "monitor_age": ("Age (s)", "Alter (s)"),
    "monitor_filter": ("Filter topics or types…", "Topics oder Typen filtern…"),
    "monitor_pause": ("Pause", "Anhalten"),
    "monitor_resume": ("Resume", "Weiter"),
    "monitor_pause_tip": ("Freeze the display (messages keep being recorded)",
                          "Anzeige einfrieren (Nachrichten werden weiter aufgezeichnet)"),
    "monitor_count": ("Topics: {count}", "Topics: {count}"),
    "monitor_count_filtered": ("Topics: {shown} of {total}", "Topics: {shown} von {total}"),
    "monitor_count_tip": ("{count} messages received", "{count} Nachrichten empfangen"),
    "monitor_field": ("Field", "Feld"),
    "monitor_value": ("Value", "Wert"),
    "monitor_message": ("Latest message", "Neueste Nachricht"),
    "monitor_choose": ("Select a topic to see its latest message",
                       "Wähle ein Topic, um seine neueste Nachricht zu sehen"),
    "monitor_no_messages": ("No messages on {topic} yet", "Noch keine Nachrichten auf {topic}"),
    "monitor_items": ("[{count} items]", "[{count} Einträge]"),
    "monitor_more": ("… {count} more", "… {count} weitere"),
    "monitor_plot_tip": ("{path}: double-click or drag to a plot", "{path}: doppelklicken oder in einen Plot ziehen"),
    "empty_hint": ("Drag blocks from the categories on the left and drop them here.\n"
                   "Snap them together, then click {run} and watch your robot.",
                   "Zieh Blöcke aus den Kategorien links hierher.\n"
                   "Steck sie zusammen, klick auf {run} und schau deinem Roboter zu."),
    "menu_examples": ("E&xamples", "&Beispiele"),
    "no_examples": ("No examples for this robot", "Keine Beispiele für diesen Roboter"),
    "example_opened": ("A copy of the example “{name}”: Save asks where to keep it.",
                       "Eine Kopie des Beispiels „{name}“: Speichern fragt, wo sie hin soll."),
    "first_steps": ("&First Steps", "&Erste Schritte"),
    "first_steps_title": ("First steps with Rockly", "Erste Schritte mit Rockly"),
    "first_steps_intro": ("Rockly programs a robot with blocks that snap together like puzzle pieces.",
                          "Mit Rockly programmierst du einen Roboter mit Blöcken, die wie Puzzleteile zusammenpassen."),
    "first_steps_robot": ("Choose your robot in the {robot_menu} menu.", "Wähle deinen Roboter im Menü {robot_menu}."),
    "first_steps_blocks": ("Drag blocks from the categories on the left onto the canvas and snap them together, "
                           "one under the other. They run from top to bottom.",
                           "Zieh Blöcke aus den Kategorien links auf die Arbeitsfläche und steck sie untereinander "
                           "zusammen. Sie laufen von oben nach unten."),
    "first_steps_run": ("Click {run} ({run_keys}) and watch the robot in the simulator. "
                        "{stop} ({stop_keys}) stops it at once.",
                        "Klick auf {run} ({run_keys}) und schau dem Roboter im Simulator zu. "
                        "{stop} ({stop_keys}) hält ihn sofort an."),
    "first_steps_glow": ("The block that is running glows yellow. When something goes wrong, its block is outlined "
                         "red and says why: change it and try again.",
                         "Der Block, der gerade läuft, leuchtet gelb. Geht etwas schief, wird sein Block rot umrandet "
                         "und sagt, warum: ändere ihn und probier es noch einmal."),
    "first_steps_loose": ("A value block lying on its own (like 1 + 2) does nothing and looks faded: "
                          "snap it into another block.",
                          "Ein Wert-Block, der allein herumliegt (wie 1 + 2), tut nichts und sieht blass aus: "
                          "steck ihn in einen anderen Block."),
    "first_steps_put_back": ("{put_back} ({put_back_keys}) puts the simulated robot back where it started.",
                             "{put_back} ({put_back_keys}) setzt den simulierten Roboter an den Start zurück."),
    "first_steps_examples": ("{file_menu} → {examples} opens a ready-made program to try and change; "
                             "{save} keeps your own programs.",
                             "{file_menu} → {examples} öffnet ein fertiges Programm zum Ausprobieren und "
                             "Ändern; {save} bewahrt deine eigenen Programme auf."),
    "keyboard_shortcuts": ("&Keyboard Shortcuts", "&Tastenkürzel"),
    "shortcuts_title": ("Keyboard shortcuts", "Tastenkürzel"),
    "shortcut_command": ("Command", "Befehl"),
    "shortcut_keys": ("Keys", "Tasten"),
    "no_shortcut": ("none", "keins"),
    "run_on": ("Run on:", "Ausführen auf:"),
    "run_on_tip": ("Where the program runs: on the simulator built into Rockly or on the real robot",
                   "Wo das Programm läuft: im eingebauten Simulator oder auf dem echten Roboter"),
}


def tr(key: str, language: str, **values) -> str:
    """The text ``key`` in ``language`` (English or German), with ``values`` filled in."""
    english, german = _TEXTS[key]
    text = german if language == "de" else english
    return text.format(**values) if values else text


def editor_page_texts(language: str) -> dict:
    """The editor page's own menu texts in ``language`` (``EditorView.start``'s ``texts``)."""
    return {"addBreakpoint": tr("add_breakpoint", language), "removeBreakpoint": tr("remove_breakpoint", language),
            "emptyHint": tr("empty_hint", language, run=tr("run", language))}


def robot_problem(error, language: str) -> tuple:
    """(what went wrong, what to try next) for an error reaching the robot, in ``language``.

    An error that names its ``reason`` (like RosUnavailable's 'no_master') is said with
    the texts ``ros_REASON`` and ``ros_REASON_hint``; any other is shown as it is, with no hint.
    """
    key = f"ros_{getattr(error, 'reason', None)}"
    if key not in _TEXTS:
        return str(error), ""
    values = getattr(error, "values", {})
    hint = f"{key}_hint"
    return tr(key, language, **values), tr(hint, language, **values) if hint in _TEXTS else ""
