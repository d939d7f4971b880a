"""The Preferences dialog and what a teacher sets behind its PIN."""
