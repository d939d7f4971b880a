"""Programs on disk: opening, saving, recent files, autosave and recovery, the file dialogs."""
