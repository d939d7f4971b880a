"""The view's words in each language (fonts and numbers: ``rockly_desktop.sdk_view``)."""
TEXTS = {
    "en": {"language": "en", "laser": "Laser", "ahead": "ahead", "nothing": "nothing in sight", "speed": "Speed",
           "driving": "driving", "turning": "turning", "battery": "Battery", "bumped": "Bump!",
           "bumps": "bumps", "standing": "standing still"},
    "de": {"language": "de", "laser": "Laser", "ahead": "vorne", "nothing": "nichts in Sicht", "speed": "Tempo",
           "driving": "fahren", "turning": "drehen", "battery": "Akku", "bumped": "Rums!",
           "bumps": "Stöße", "standing": "steht still"},
}
