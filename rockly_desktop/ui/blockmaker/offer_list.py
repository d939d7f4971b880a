"""The maker's list of what the robot offers: each row its kind and name, its type, and whether the robot has it
now. A row wider than the list gives up the middle of its type first, then of its name, never the robot's state;
its tooltip says it whole."""
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QListWidget, QListWidgetItem, QStyle, QStyledItemDelegate

from rockly_desktop.ui.texts import tr

PARTS = Qt.ItemDataRole.UserRole + 1  # (kind and name, type, state) of a row, as ``offer_parts`` gives them


def offer_parts(offer, language: str) -> tuple:
    """(kind and name, type, state) as the list shows ``offer`` (an ``offers.Offer``); "" for a part it has not."""
    kind = tr(offer.text_key, language)
    label = offer.label()
    head, middle = (f"{kind}: {offer.name}", f"  ({offer.type})") if offer.name and offer.type else (
        f"{kind}: {label}" if label else kind, "")
    return head, middle, f"  · {tr('maker_offer_live', language)}" if offer.live else ""


def fitted_text(parts: tuple, metrics, width: int) -> str:
    """``parts`` as one text within ``width`` pixels of ``metrics`` (a QFontMetrics): the type's middle goes
    first, then the name's; the state stays whole."""
    head, middle, tail = parts
    whole = head + middle + tail
    if metrics.horizontalAdvance(whole) <= width:
        return whole
    room = width - metrics.horizontalAdvance(head + tail)
    if middle and room >= metrics.horizontalAdvance("  (…)"):
        return head + metrics.elidedText(middle, Qt.TextElideMode.ElideMiddle, room) + tail
    room = max(0, width - metrics.horizontalAdvance(tail))
    return metrics.elidedText(head, Qt.TextElideMode.ElideMiddle, room) + tail


class _FittingDelegate(QStyledItemDelegate):
    """Draws each row's parts fitted to the list's visible width."""

    def initStyleOption(self, option, index):
        super().initStyleOption(option, index)
        parts = index.data(PARTS)
        view = self.parent()
        if parts:
            margin = 2 * (view.style().pixelMetric(QStyle.PixelMetric.PM_FocusFrameHMargin, None, view) + 1) + 2
            right = min(option.rect.right(), view.viewport().width())
            option.text = fitted_text(parts, option.fontMetrics, right - option.rect.left() - margin)


class OfferList(QListWidget):
    """The offers, one row each (``add``), fitted to the list's width: no sideways scrolling."""

    def __init__(self, language: str, parent=None):
        super().__init__(parent)
        self._language = language
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setItemDelegate(_FittingDelegate(self))

    def add(self, offer) -> QListWidgetItem:
        """A row for ``offer``: its text whole (what the filter reads) and its tooltip (the live ones' also
        says what being on the robot now means)."""
        parts = offer_parts(offer, self._language)
        item = QListWidgetItem("".join(parts), self)
        item.setData(Qt.ItemDataRole.UserRole, offer)
        item.setData(PARTS, parts)
        item.setToolTip(item.text() + (f"\n{tr('maker_offer_live_tip', self._language)}" if offer.live else ""))
        return item
