"""Kiosk mode for a fair stand: the locked window, its settings, noticing when nobody is there."""
