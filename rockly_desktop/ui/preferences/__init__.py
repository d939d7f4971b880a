"""The Preferences dialog and the teacher's PIN-guarded tab (what they set: ``settings``)."""
