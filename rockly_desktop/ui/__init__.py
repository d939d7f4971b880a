"""Qt widgets: the main window, its docks and dialogs."""
