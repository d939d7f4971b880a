"""The made block as Blockly draws it: an editor page of its own (the editor's page and assets) that
shows one block, defined anew on each change.

At most one drawing is on its way to the page: changes made meanwhile are drawn together once it
is answered, so typing never queues up work the page has not done yet.
"""
from PySide6.QtCore import Signal

from rockly_desktop.bridge.editor_view import EditorView
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.packs.choices import preview_block
from rockly_desktop.profiles.packs.generate import toolbox_entry


class BlockPreview(EditorView):
    """Draws a MadeBlock for ``profile`` in ``language``; ``sig_drawn`` once the page has drawn the newest."""

    sig_drawn = Signal()
    sig_typed = Signal()  # the person changed a value in the drawn block (``typed_values``)

    def __init__(self, profile, language: str, parent=None):
        super().__init__(parent)
        self.setObjectName("maker_preview")
        self._profile = profile
        self._language = language
        self._waiting = False   # a drawing was sent and not answered yet
        self._next = None       # the newest block entry not sent yet
        self.drawn = None       # what the page shows: {"block": editor_config entry, "state": its toolbox entry}
        self.sig_changed.connect(lambda _workspace, _python, origin: origin == "user" and self.sig_typed.emit())
        self.start({"profile": profile.id, "blocks": [], "toolbox": None, "types": profile.ros_types.editor_catalog},
                   language)

    @property
    def is_drawing(self) -> bool:
        """True while a drawing is on its way to the page or waiting to be sent."""
        return self._waiting or self._next is not None

    def show_block(self, block):
        """Draw ``block`` with its inputs' defaults; a block whose definition does not read back leaves
        the last drawing (the maker lists its problems)."""
        try:
            entry = {"block": preview_block(block, self._profile, self._language), "state": toolbox_entry(block)}
        except ManifestError:
            return
        self._next = entry
        if not self._waiting:
            self._send()

    def typed_values(self) -> dict:
        """{input name: value} of the drawn block's inputs as the page has them now (a yes/no as a bool)."""
        tops = ((self.workspace or {}).get("blocks") or {}).get("blocks") or []
        values = {}
        for name, slot in (tops[0].get("inputs", {}) if tops else {}).items():
            fields = (slot.get("shadow") or slot.get("block") or {}).get("fields") or {}
            if len(fields) == 1:
                (field, value), = fields.items()
                values[name] = value == "TRUE" if field == "BOOL" else value
        return values

    def _send(self):
        entry, self._next = self._next, None
        self._waiting = True
        self.call("preview", entry, lambda _result, error: self._answered(entry, error))

    def _answered(self, entry, error):
        self._waiting = False
        if not error:  # a drawing the page refused leaves the last one (the maker lists the block's problems)
            self.drawn = entry
        if self._next is not None:
            self._send()
        else:
            self.sig_drawn.emit()
