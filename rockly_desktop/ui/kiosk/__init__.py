"""Kiosk mode for a fair stand: the locked window, noticing when nobody is there (its settings: ``settings.kiosk``)."""
