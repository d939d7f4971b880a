"""The block maker's dialog: pick what the robot offers, say what the block does and how it reads,
see it drawn and its Python, and save it into a block pack (``profiles.packs.making.save_block``).

A live offer of a type Rockly has no definition for gets its fields from the robot
(``learning.FieldLearning``, off the window's thread), or a plain note why there are none.

Every change rebuilds the MadeBlock, lists its problems (``validation.block_problems``, in the
window's language) and redraws the preview; saving writes nothing while there is a problem.
"""
import re
from dataclasses import replace

from PySide6.QtCore import QSize, Qt, QTimer, Signal
from PySide6.QtGui import QFontDatabase
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QSplitter,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.profiles.packs.choices import category_choices
from rockly_desktop.profiles.packs.generate import python_preview
from rockly_desktop.profiles.packs.interfaces import fields_of_block_kind, interface_fields, knows_type
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.spec import COMPARISONS, INTERFACE_KINDS, OUTCOME, BlockInput, MadeBlock
from rockly_desktop.profiles.packs.validation import BlockMakerError, block_problems, sentence_places
from rockly_desktop.ui.blockmaker.colour_choice import ColourChoice
from rockly_desktop.ui.blockmaker.editing import OFFER_KIND, PackBeingEdited, value_text
from rockly_desktop.ui.blockmaker.field_table import FieldTable
from rockly_desktop.ui.blockmaker.learning import FieldLearning
from rockly_desktop.ui.blockmaker.offer_list import OfferList
from rockly_desktop.ui.blockmaker.offers import KINDS_OF, Offer, global_name, known_offers, robot_offers
from rockly_desktop.ui.blockmaker.preview import BlockPreview
from rockly_desktop.ui.plain_text import plain_label
from rockly_desktop.ui.texts import said_in, tr
from rockly_desktop.ui.window_fit import fit_first_window

PREVIEW_TYPE = "rockly_maker_preview"  # the preview's block type: never one of the toolbox's
FILLS_FIELDS = ("publish", "call_service", "send_goal")
READS_FIELD = ("sensor_value", "wait_until")
FALLBACK_COLOUR = "#4c97ff"
GRAPH_REFRESH_MS = 1000  # the live graph is read again this often while the maker is open (as the feeds poll)
WANTED_SIZE = QSize(1200, 800)  # or less: the dialog with its frame fits the screen (its buttons stay on it)


def pack_id_for(profile) -> str:
    """The block pack the maker saves into for ``profile``: one per robot profile."""
    return f"made_for_{profile.id}"


def suggested_id(name: str) -> str:
    """A block id from a ROS name: ``/head/emo`` → ``made_head_emo``."""
    words = re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")
    return f"made_{words}"[:40].rstrip("_")


def drawable_sentence(block) -> dict:
    """The sentences of ``block`` Blockly can draw (each input's place once); until there is one, the
    interface's name followed by the places, so the inputs show while the sentence is written."""
    wanted = list(range(1, len(block.inputs) + 1))
    sentences = {language: text for language, text in block.sentence.items() if sorted(sentence_places(text)) == wanted}
    return sentences or {"en": " ".join([block.interface or "?"] + [f"%{number}" for number in wanted])}


def _same_offer(offer: Offer, other: Offer) -> bool:
    """The same thing to make a block from, whether or not the live graph has it now."""
    return (offer.kind, offer.name, offer.type) == (other.kind, other.name, other.type)


class BlockMakerDialog(QDialog):
    """The maker for ``profile`` in ``language``, offering ``offers`` (``offers.Offer``s); ``packs_folder``
    is where packs are saved (None: the user's); ``asker()`` gives the robot link's ``interface_definition``
    that asks the robot for a live offer's definition (None: no robot; see ``learning``).
    ``sig_saved(block id)`` once a block was written."""

    sig_saved = Signal(str)
    sig_try_requested = Signal(object)  # the preview page, whose one block the window runs once ("Try it")
    sig_changed = Signal()  # the block, its problems and its Python were updated (the drawing follows)

    def __init__(self, profile, language: str, offers, parent=None, packs_folder=None, asker=None):
        super().__init__(parent)
        self.setObjectName("block_maker")
        self.setWindowTitle(tr("maker_title", language))
        self.profile = profile
        self.language = language
        self.packs_folder = packs_folder
        self.problems = []
        self.editing = ""  # the pack of the made block shown again to change ("": a new block)
        self._edited_pack = None
        self._used_inputs = set()  # the fields (or values) whose inputs the open program fills, as the table names them
        self._suggested_id = ""  # the block id the last offer chosen suggested
        self._updating = False
        self._offer = None
        self._not_learnt = {}  # offer -> why the robot did not say its fields (until it is chosen again)
        self.learning = FieldLearning(profile, asker, self)
        self.learning.sig_learnt.connect(lambda offer: offer == self._offer and self._kind_changed())
        self.learning.sig_failed.connect(self._not_learnt_from)
        self.finished.connect(lambda _result: self.learning.forget())
        self.offers = OfferList(language, self)
        self.offers.setObjectName("maker_offers")
        self.offers.setAccessibleName(tr("maker_offers", language))
        self.offer_filter = QLineEdit(self)
        self.offer_filter.setObjectName("maker_offer_filter")
        self.offer_filter.setPlaceholderText(tr("maker_offer_filter", language))
        self.offer_filter.setAccessibleName(tr("maker_offer_filter", language))
        self.offer_filter.setClearButtonEnabled(True)
        self.offer_filter.textChanged.connect(self._filter_offers)
        self._list_offers(offers)
        self.offers.currentItemChanged.connect(lambda item, _old: item is not None and self.choose(
            item.data(Qt.ItemDataRole.UserRole)))
        self._build_form()
        self.preview = BlockPreview(profile, language, self)
        self.preview.sig_typed.connect(lambda: self._show_python(self.preview.typed_values()))
        self.python = QPlainTextEdit(self)
        self.python.setObjectName("maker_python")
        self.python.setReadOnly(True)
        self.python.setAccessibleName(tr("maker_python", language))
        self.python.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.problem_label = plain_label(parent=self, objectName="maker_problems")
        self.problem_label.setWordWrap(True)
        self.problem_label.setStyleSheet("color: #b00020;")
        self.warning_label = plain_label(parent=self, objectName="maker_warning")
        self.warning_label.setWordWrap(True)
        self.warning_label.setStyleSheet("color: #8a4b00;")
        self.warning_label.hide()
        self.try_report = QPlainTextEdit(self)
        self.try_report.setObjectName("maker_try_report")
        self.try_report.setReadOnly(True)
        self.try_report.setAccessibleName(tr("maker_try_report", language))
        self.try_report.setMaximumHeight(self.fontMetrics().lineSpacing() * 6 + 12)
        self.try_report.hide()
        self.buttons = QDialogButtonBox(self)
        self.save_button = QPushButton(tr("maker_save", language), self)
        self.save_button.setObjectName("maker_save")
        self.buttons.addButton(self.save_button, QDialogButtonBox.ButtonRole.AcceptRole)
        self.buttons.addButton(QDialogButtonBox.StandardButton.Close)
        self.buttons.button(QDialogButtonBox.StandardButton.Close).setText(tr("maker_close", language))
        self.save_button.clicked.connect(self.save)
        self.try_button = QPushButton(tr("maker_try", language), self)
        self.try_button.setObjectName("maker_try")
        self.try_button.setToolTip(tr("maker_try_tip", language))
        self.buttons.addButton(self.try_button, QDialogButtonBox.ButtonRole.ActionRole)
        self.try_button.clicked.connect(lambda: self.sig_try_requested.emit(self.preview))
        self.buttons.rejected.connect(self.reject)
        self._lay_out()
        self.offer_filter.setFocus()  # typing finds an offer; a focused list would choose its first by itself
        self._kind_changed()  # nothing chosen yet: only what every block has is shown

    # -- building

    def _build_form(self):
        language = self.language
        self.interface = self._edit("maker_interface")
        self.interface_type = self._edit("maker_interface_type")
        self.kind = QComboBox(self)
        self.kind.setObjectName("maker_kind")
        self.kind.currentIndexChanged.connect(self._kind_changed)
        self.fields = FieldTable(language, self)
        self.fields.sig_changed.connect(self.update_block)
        self.fields_note = plain_label(parent=self, objectName="maker_fields_note")
        self.fields_note.setWordWrap(True)
        self.fields_note.hide()
        self.read_field = QComboBox(self)
        self.read_field.setObjectName("maker_read_field")
        self.read_field.currentIndexChanged.connect(self.update_block)
        self.comparison = QComboBox(self)
        self.comparison.setObjectName("maker_comparison")
        for key, sign in COMPARISONS.items():
            self.comparison.addItem(sign, key)
        self.comparison.currentIndexChanged.connect(self.update_block)
        self.result = QComboBox(self)
        self.result.setObjectName("maker_result")
        self.result.currentIndexChanged.connect(self.update_block)
        self.while_waiting = QCheckBox(tr("maker_while_waiting_on", language), self)
        self.while_waiting.setObjectName("maker_while_waiting")
        self.while_waiting.toggled.connect(self.update_block)
        self.sentence = {code: self._edit(f"maker_sentence_{code}") for code in ("en", "de")}
        self.tooltip = {code: self._edit(f"maker_tooltip_{code}") for code in ("en", "de")}
        self.category = QComboBox(self)
        self.category.setObjectName("maker_category")
        self.category.setEditable(True)
        categories = category_choices(self.profile, language)
        for name, english, colour in categories:
            self.category.addItem(name, (english, colour or FALLBACK_COLOUR))
        self.category.currentTextChanged.connect(self._category_changed)
        self.colour = ColourChoice([(name, colour) for name, _english, colour in categories], language, self)
        self.colour.set_colour(self.category.currentData()[1] if categories else FALLBACK_COLOUR)
        self.colour.sig_changed.connect(self.update_block)
        self.block_id = self._edit("maker_block_id")
        form = QFormLayout()
        for key, widget in (("maker_interface", self.interface), ("maker_interface_type", self.interface_type),
                            ("maker_kind", self.kind), ("maker_read_field", self.read_field),
                            ("maker_comparison", self.comparison), ("maker_result", self.result),
                            ("maker_while_waiting", self.while_waiting), ("maker_sentence_en", self.sentence["en"]),
                            ("maker_sentence_de", self.sentence["de"]), ("maker_tooltip_en", self.tooltip["en"]),
                            ("maker_tooltip_de", self.tooltip["de"]), ("maker_category", self.category),
                            ("maker_colour", self.colour), ("maker_block_id", self.block_id)):
            form.addRow(tr(key, language), widget)
            named = self.colour.box if widget is self.colour else widget
            named.setAccessibleName(tr(key, language).rstrip(": "))  # a screen reader names it as the form does
        self.sentence["en"].setPlaceholderText(tr("maker_sentence_hint", language))
        self.form = form

    def _edit(self, name: str) -> QLineEdit:
        edit = QLineEdit(self)
        edit.setObjectName(name)
        edit.textChanged.connect(self.update_block)
        return edit

    def _category_changed(self, shown: str):
        """A category of the profile's brings its colour (the person may choose another); a new one keeps it."""
        index = self.category.findText(shown.strip())
        if index >= 0:
            self.colour.set_colour(self.category.itemData(index)[1])  # updates the block through sig_changed
        self.update_block()

    def _lay_out(self):
        right = QWidget(self)
        column = QVBoxLayout(right)
        column.setContentsMargins(0, 0, 0, 0)
        column.addLayout(self.form)
        column.addWidget(self.fields_note)
        column.addWidget(self.fields, 1)
        column.addWidget(self.problem_label)
        column.addWidget(self.warning_label)
        shown = QHBoxLayout()
        shown.addWidget(self.preview, 1)
        shown.addWidget(self.python, 1)
        column.addLayout(shown, 1)
        column.addWidget(self.try_report)
        left = QWidget(self)
        offers = QVBoxLayout(left)
        offers.setContentsMargins(0, 0, 0, 0)
        offers.addWidget(self.offer_filter)
        offers.addWidget(self.offers, 1)
        splitter = QSplitter(Qt.Orientation.Horizontal, self)
        splitter.addWidget(left)
        splitter.addWidget(right)
        splitter.setStretchFactor(1, 3)
        splitter.setSizes([400, 800])
        layout = QVBoxLayout(self)
        layout.addWidget(splitter, 1)
        layout.addWidget(self.buttons)
        fit_first_window(self, WANTED_SIZE)

    def _list_offers(self, offers):
        """Show ``offers`` in the list (the live ones marked), keeping the one chosen and the filter."""
        chosen = self.offers.currentItem().data(Qt.ItemDataRole.UserRole) if self.offers.currentItem() else None
        self.offers.blockSignals(True)  # the same offer chosen again must not reset the form
        try:
            self.offers.clear()
            for offer in offers:
                item = self.offers.add(offer)
                if chosen is not None and _same_offer(offer, chosen):
                    self.offers.setCurrentItem(item)
        finally:
            self.offers.blockSignals(False)
        self._listed = list(offers)
        self._filter_offers(self.offer_filter.text())

    def follow_graph(self, graph, known):
        """Keep the list up to date with the robot's live graph while the maker is open: ``graph()`` gives
        its ``LiveGraph`` (read without waiting), ``known`` the offers without a robot listed after it."""
        def refresh():
            offers = robot_offers(self.profile, graph()) + known
            if offers != self._listed:
                self._list_offers(offers)
        self._graph_timer = QTimer(self)
        self._graph_timer.timeout.connect(refresh)
        self._graph_timer.start(GRAPH_REFRESH_MS)

    # -- choosing

    def choose(self, offer: Offer):
        """Make the block from ``offer``: its name, type and the kinds of block it can make."""
        self._offer = offer
        self._not_learnt.pop(offer, None)  # chosen again: the robot is asked again
        self._updating = True
        try:
            self.interface.setText(offer.name)
            self.interface_type.setText(offer.type)
            self.kind.clear()
            for kind in KINDS_OF[offer.kind]:
                self.kind.addItem(tr(f"maker_kind_{kind}", self.language), kind)
            if offer.name and self.block_id.text() in ("", self._suggested_id):  # an id the person typed stays
                self._suggested_id = suggested_id(offer.name)
                self.block_id.setText(self._suggested_id)
        finally:
            self._updating = False
        self._kind_changed()

    def _filter_offers(self, text: str):
        words = text.lower().split()
        for row in range(self.offers.count()):
            item = self.offers.item(row)
            item.setHidden(not all(word in item.text().lower() for word in words))

    def choose_named(self, name: str, kind: str = "") -> bool:
        """Choose the offer called ``name`` (of ``kind``, "" for any) in the list (the Topic monitor's "Make a
        block from this…"); ``/move_base`` as the graph names it is the ``move_base`` a profile declares."""
        for exact in (True, False):
            for row in range(self.offers.count()):
                offer = self.offers.item(row).data(Qt.ItemDataRole.UserRole)
                same = offer.name == name if exact else (bool(offer.name)
                                                         and global_name(offer.name) == global_name(name))
                if same and kind in ("", offer.kind):
                    self.offers.setCurrentRow(row)
                    return True
        return False

    def _kind_changed(self, *_):
        if self._updating:  # the kinds are being listed anew (``choose`` shows the new first kind once after)
            return
        kind = self.kind.currentData() or ""
        fields = fields_of_block_kind(self.profile, kind, self.interface_type.text().strip()) if kind else []
        self._updating = True
        try:
            self.fields.set_fields(fields if kind in FILLS_FIELDS else [])
            self.read_field.clear()
            for entry in fields if kind in READS_FIELD else []:
                if entry.kind in ("number", "text", "yes_no"):
                    self.read_field.addItem(entry.path, entry.kind)
            self.result.clear()
            self.result.addItem(tr("maker_result_none", self.language), "")
            for path in self._results(kind):
                self.result.addItem(tr("maker_result_outcome", self.language) if path == OUTCOME else path, path)
            self.while_waiting.setChecked(False)
        finally:
            self._updating = False
        self.fields.setVisible(kind in FILLS_FIELDS)
        self._say_why_no_fields(kind)
        for widget, shown in ((self.read_field, kind in READS_FIELD), (self.comparison, kind == "wait_until"),
                              (self.result, kind in ("call_service", "send_goal")),
                              (self.while_waiting, kind == "send_goal")):
            widget.setVisible(shown)
            self.form.labelForField(widget).setVisible(shown)
        self.update_block()

    def _say_why_no_fields(self, kind: str):
        """Show why a block of ``kind`` has no fields yet, when Rockly does not know its type: the robot is
        being asked (asked now if it is not), what it answered, or that the type is unknown; else nothing."""
        definition, type_name, offer = INTERFACE_KINDS.get(kind), self.interface_type.text().strip(), self._offer
        note = ""
        if definition and type_name and not knows_type(self.profile, type_name, definition):
            live = offer is not None and offer.type == type_name and self.learning.needed(offer)
            if live and offer in self._not_learnt:
                note = self._not_learnt[offer].in_language(self.language)
            elif live and self.learning.can_ask():
                self.learning.ask(offer)
                note = tr("maker_fields_asking", self.language, type=type_name)
            else:
                note = tr("maker_fields_unknown", self.language, type=type_name)
        self.fields_note.setText(note)
        self.fields_note.setVisible(bool(note))

    def _not_learnt_from(self, offer, why):
        """The robot did not say ``offer``'s fields: say ``why`` (and what to do) while it is chosen."""
        self._not_learnt[offer] = why
        if offer == self._offer:
            self._say_why_no_fields(self.kind.currentData() or "")

    def _results(self, kind: str) -> list:
        """What a block of ``kind`` can give: a response field of the service, or the goal's outcome."""
        if kind == "send_goal":
            return [OUTCOME]
        if kind != "call_service":
            return []
        response = interface_fields(self.profile, self.interface_type.text().strip(), "srv", "out")
        return [entry.path for entry in response if entry.kind in ("number", "text", "yes_no")]

    def edit(self, made, pack_id: str, used_inputs=()):
        """Show the saved block ``made`` of the pack ``pack_id`` to change it: saving replaces it in that pack
        under the same id (programs name it by its id); ``used_inputs`` are the inputs the open program
        fills, and taking one of them away is said before it is saved."""
        self.editing = pack_id
        self._edited_pack = PackBeingEdited.of(self.profile, pack_id, made.id)
        self._used_inputs = {entry.field or entry.name for entry in made.inputs if entry.name in set(used_inputs)}
        self.setWindowTitle(tr("maker_edit_title", self.language, block=made.id))
        self.save_button.setText(tr("maker_save_changes", self.language))
        self.block_id.setText(made.id)
        self.block_id.setReadOnly(True)
        self.block_id.setToolTip(tr("maker_block_id_kept", self.language))
        offer = Offer(OFFER_KIND.get(made.kind, "topic"), made.interface, made.interface_type)
        self.offers.blockSignals(True)  # the list shows it chosen (else the list's focus would choose its first)
        try:
            if not self.choose_named(made.interface, offer.kind):
                self._list_offers([offer, *self._listed])
                self.offers.setCurrentRow(0)
        finally:
            self.offers.blockSignals(False)
        self.choose(offer)
        self.kind.setCurrentIndex(max(0, self.kind.findData(made.kind)))
        self._updating = True
        try:
            for entry in made.inputs:
                if entry.field:
                    self.fields.set_use(entry.field, "input", value_text(entry.default, entry.kind, self.language),
                                        entry.unit, value_text(entry.minimum, "number", self.language),
                                        value_text(entry.maximum, "number", self.language))
            for path, value in made.fixed.items():
                self.fields.set_use(path, "fixed", value_text(value, self.fields.kind_of(path), self.language))
            for box, data in ((self.comparison, made.comparison), (self.result, made.result)):
                box.setCurrentIndex(max(0, box.findData(data)))
            self.read_field.setCurrentIndex(max(0, self.read_field.findText(made.read_field)))
            self.while_waiting.setChecked(made.while_waiting)
            for code in ("en", "de"):
                self.sentence[code].setText(made.sentence.get(code, ""))
                self.tooltip[code].setText(made.tooltip.get(code, ""))
            self.category.setCurrentText(made.category.get(self.language) or made.category.get("en", ""))
            self.colour.set_colour(made.colour)
        finally:
            self._updating = False
        self.update_block()

    # -- the block

    def block(self) -> MadeBlock:
        """The MadeBlock as the dialog shows it now."""
        kind = self.kind.currentData() or ""
        read_kind = self.read_field.currentData() or "number"
        inputs = self.fields.inputs() if kind in FILLS_FIELDS else ()
        if kind == "wait_until":
            inputs = (BlockInput("value", read_kind),)
        elif kind == "set_param":
            inputs = (BlockInput("value", "number"),)
        shown = self.category.currentText().strip()
        index = self.category.findText(shown)
        english = self.category.itemData(index)[0] if index >= 0 else shown
        category = {"en": english, self.language: shown} if shown else {}
        return MadeBlock(
            id=self.block_id.text().strip(), kind=kind, interface=self.interface.text().strip(),
            interface_type=self.interface_type.text().strip() if kind not in ("get_param", "set_param") else "",
            inputs=inputs, fixed=self.fields.fixed() if kind in FILLS_FIELDS else {},
            sentence={code: edit.text() for code, edit in self.sentence.items() if edit.text().strip()},
            category=category, colour=self.colour.colour(),
            tooltip={code: edit.text() for code, edit in self.tooltip.items() if edit.text().strip()},
            read_field=self.read_field.currentText() if kind in READS_FIELD else "",
            value_kind=read_kind if kind == "sensor_value" else "number",
            comparison=self.comparison.currentData() if kind == "wait_until" else "equal",
            result=self.result.currentData() or "" if kind in ("call_service", "send_goal") else "",
            while_waiting=kind == "send_goal" and self.while_waiting.isChecked())

    def update_block(self, *_):
        """Check the block as it is now, show its problems and Python, and draw it."""
        if self._updating:
            return
        block = self.block()
        self.problems = [said_in(problem, self.language)
                         for problem in block_problems(block, self.profile, self._edited_pack)] if block.kind else [
            tr("maker_choose_first", self.language)]  # nothing chosen yet: no block to find fault with
        self.problem_label.setText("\n".join(self.problems))
        self.problem_label.setVisible(bool(self.problems))
        dropped = sorted(self._used_inputs - {entry.field or entry.name for entry in block.inputs})
        self.warning_label.setText(tr("maker_inputs_in_use", self.language, inputs=", ".join(dropped))
                                   if dropped else "")
        self.warning_label.setVisible(bool(dropped))
        self.save_button.setEnabled(not self.problems)
        self.try_button.setEnabled(not self.problems)
        self._show_python({})  # the preview is drawn anew with the defaults
        if block.kind:
            self.preview.show_block(replace(block, id=PREVIEW_TYPE, sentence=drawable_sentence(block)))
        self.sig_changed.emit()

    def _show_python(self, typed: dict):
        """Show the Python of the block with the ``typed`` values ({input name: value}) in place of the defaults."""
        block = self.block()
        inputs = tuple(replace(entry, default=typed[entry.name]) if entry.name in typed else entry
                       for entry in block.inputs)
        self.python.setPlainText(python_preview(replace(block, inputs=inputs)) if block.kind else "")

    def show_try_report(self, lines: list):
        """Show what the last "Try it" did (``trial.report_lines``) under the preview."""
        self.try_report.setPlainText("\n".join(lines))
        self.try_report.show()

    def keyPressEvent(self, event):
        """Qt override: Enter ends what is being typed (a form's field, the preview block's field) and presses
        only a button that has the focus; never Save and close on its own."""
        if event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter) and not isinstance(self.focusWidget(), QPushButton):
            event.accept()
            return
        super().keyPressEvent(event)

    def save(self):
        """Write the block into the profile's block pack; on a problem say it and write nothing."""
        try:
            save_block(self.block(), self.profile, self.editing or pack_id_for(self.profile), folder=self.packs_folder,
                       replace_block=bool(self.editing))
        except BlockMakerError as error:
            self.problems = [error.in_language(self.language)]
            self.problem_label.setText(self.problems[0])
            self.problem_label.setVisible(True)
            return
        self.sig_saved.emit(self.block().id)
        self.accept()



def open_block_maker(profile, language: str, graph, parent, chosen: str = "", kind: str = "",
                     asker=None) -> BlockMakerDialog:
    """Open the maker (not blocking) over ``parent`` for ``profile``, offering what the robot's live graph
    has (``graph()``: a ``LiveGraph``, read without waiting, again each second) and the profile declares,
    then the types Rockly knows; with the offer named ``chosen`` (of ``kind``, "" for any) chosen.
    ``asker``: see BlockMakerDialog."""
    known = known_offers(profile)
    dialog = BlockMakerDialog(profile, language, robot_offers(profile, graph()) + known, parent, asker=asker)
    dialog.follow_graph(graph, known)
    dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
    if chosen:
        dialog.choose_named(chosen, kind)
    dialog.open()
    return dialog
