"""What one paint draws from: the snapshot as given, the eased values, the language, fonts and the moment."""
from rockly_desktop.sdk_view import sized_font

from . import snapshot as read
from .texts import MIN_TEXT_PX, TEXTS


class Scene:
    """A read-only bundle for the painters, made by the view for each paint.

    ``phase`` is the view's clock in seconds, 0 when animation is off: whatever moves by itself
    (blinking, floating z, a waving flag, pulses) is a function of it.
    """

    def __init__(self, snapshot, shown, target, language, base_font, animate, phase, text_cache):
        self.snapshot, self.shown, self.target = snapshot, shown, target
        self.texts = TEXTS.get(language, TEXTS["en"])
        self.language = language
        self.animate, self.phase = animate, phase
        self.text_cache = text_cache        # the view's fitted tablet texts; it empties it on a language change
        self._base_font = base_font
        self.emotion = read.emotion(snapshot)
        self.notices = read.notices(snapshot)
        self.tablet = read.tablet(snapshot)
        self.sos = read.sos_active(snapshot)

    def font(self, px, bold=False):
        """The view's font at ``px`` pixels."""
        return sized_font(self._base_font, px, bold, MIN_TEXT_PX)
