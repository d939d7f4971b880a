"""The view's words in each language, and the smallest text it writes (fonts, wrapping: ``rockly_desktop.sdk_view``)."""
MIN_TEXT_PX = 11

TEXTS = {
    "en": {
        "emotions": {"HAPPY": "happy", "VHAPPY": "very happy", "LTIRED": "a bit tired", "VTIRED": "very tired",
                     "CONCERNED": "worried", "SAD": "sad", "WONDERING": "wondering", "NEUTRAL": "calm",
                     "SLEEPING": "asleep"},
        "motion": {"idle": "standing", "moving": "driving", "turning": "turning", "navigating": "driving to the flag"},
        "waiting": "Waiting for your answer", "yes": "Yes", "no": "No", "ok": "OK", "type": "Type here…",
        "tablet_off": "tablet is off",
        "arm": "Arm", "gripper": "Gripper", "head": "Head", "turntable": "Turntable",
        "open": "open", "closed": "closed", "out": "out", "stored": "stored",
    },
    "de": {
        "emotions": {"HAPPY": "fröhlich", "VHAPPY": "sehr fröhlich", "LTIRED": "etwas müde", "VTIRED": "sehr müde",
                     "CONCERNED": "besorgt", "SAD": "traurig", "WONDERING": "verwundert", "NEUTRAL": "ruhig",
                     "SLEEPING": "schläft"},
        "motion": {"idle": "steht", "moving": "fährt", "turning": "dreht sich", "navigating": "fährt zur Fahne"},
        "waiting": "Wartet auf deine Antwort", "yes": "Ja", "no": "Nein", "ok": "OK", "type": "Hier tippen…",
        "tablet_off": "Tablet ist aus",
        "arm": "Arm", "gripper": "Greifer", "head": "Kopf", "turntable": "Drehteller",
        "open": "offen", "closed": "zu", "out": "draußen", "stored": "eingefahren",
    },
}
