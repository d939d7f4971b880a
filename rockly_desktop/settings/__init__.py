"""What Rockly remembers between starts (QSettings, so QtCore only): the app's settings, the language
Rockly speaks now, the teacher's and the kiosk's settings. The window and the command line read them alike."""
