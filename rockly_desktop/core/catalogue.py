"""Texts in every language from gettext catalogues: one ``.po`` file per language in one folder.

A folder holds ``messages.pot``, the English texts (the template translators start from), and
one ``LANG.po`` per other language (``de.po``). Every entry is keyed by its ``msgctxt``; its
``msgid`` is the English text, its ``msgstr`` the translation, with ``{name}`` placeholders
(``#, python-brace-format``, which Poedit, Weblate and ``msgfmt --check`` check). A
translation is used only while its ``msgid`` is the current English text and it is not
marked fuzzy (what ``msgmerge`` does to a changed text): otherwise the English one is shown,
as gettext does. Read with the standard library only (no compiled ``.mo`` files).

An entry without a ``msgctxt`` translates a text that is written in English where it is
used, by its ``msgid`` (``translate``): how a profile's ``.po`` file gives a language its
YAML (blocks, toolbox, manifest) does not spell out.

``LocalText`` is a text not yet put into a language (a robot command's error, an obstacle's
name): ``str()`` gives English, ``in_language(language)`` any other; values that are
``LocalText`` themselves are put into the same language.
"""
import re
import string
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from rockly_desktop.core.numbers import number_format

ENGLISH = "en"
TEMPLATE = "messages.pot"


@dataclass(frozen=True)
class Entry:
    """One entry of a .po file: its key (msgctxt), English (msgid), translation (msgstr), fuzzy or not."""

    key: str                # None for an entry without msgctxt
    english: str
    translation: str
    fuzzy: bool = False


def read_po(path) -> dict:
    """The entries of the .po (or .pot) file ``path`` by key; the header and entries without a key are left out."""
    return {entry.key: entry for entry in read_po_entries(path) if entry.key is not None}


def read_po_entries(path) -> list:
    """Every entry of the .po (or .pot) file ``path`` but the header (``key`` None: no msgctxt)."""
    entries, current, flags, last = [], {}, set(), None

    def finish():
        if current.get("msgid") or current.get("msgctxt") is not None:
            entries.append(Entry(current.get("msgctxt"), current.get("msgid", ""), current.get("msgstr", ""),
                                 "fuzzy" in flags))

    for number, line in enumerate(Path(path).read_text(encoding="utf-8").splitlines(), start=1):
        line = line.strip()
        starts_entry = line.startswith(("#", "msgctxt ", "msgid ")) or not line
        if starts_entry and last == "msgstr":  # the entry before is complete
            finish()
            current, flags, last = {}, set(), None
        if not line:
            continue
        if line.startswith("#,"):
            flags.update(flag.strip() for flag in line[2:].split(","))
        if line.startswith("#"):
            continue
        word, rest = (last, line) if line.startswith('"') else line.split(" ", 1)
        if word not in ("msgctxt", "msgid", "msgstr") or not rest.startswith('"'):
            raise ValueError(f"{path}:{number}: cannot read {line!r}")
        if word in ("msgctxt", "msgid") and "msgid" in current and not line.startswith('"'):
            raise ValueError(f"{path}:{number}: the entry before has no msgstr")
        text = _po_string(rest, f"{path}:{number}")
        current[word] = current.get(word, "") + text if line.startswith('"') else text
        last = word
    if last == "msgstr":
        finish()
    return entries


_PO_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", '"': '"', "\\": "\\"}
_PO_ESCAPE = re.compile(r"\\(.)")


def _po_string(quoted: str, where: str) -> str:
    """The text of a quoted .po string (C escapes: \\n \\t \\r \\" \\\\); ValueError for anything else.
    By hand rather than ast.literal_eval, which compiles each line (a third of the start's catalogue time)."""
    if len(quoted) < 2 or not quoted.startswith('"') or not quoted.endswith('"'):
        raise ValueError(f"{where}: not a quoted text: {quoted!r}")

    def unescape(match):
        if match.group(1) not in _PO_ESCAPES:
            raise ValueError(f"{where}: unknown escape \\{match.group(1)} in {quoted!r}")
        return _PO_ESCAPES[match.group(1)]

    return _PO_ESCAPE.sub(unescape, quoted[1:-1])


def placeholders(text: str) -> set:
    """The ``{name}`` placeholders of ``text`` (format specs left out)."""
    return {name for _, name, _, _ in string.Formatter().parse(text) if name is not None}


class Catalogue:
    """The texts of one folder of catalogues (``messages.pot`` and ``LANG.po``), read when first needed."""

    def __init__(self, folder):
        self.folder = Path(folder)
        self._languages = {}
        self._by_english = {}

    @cached_property
    def languages(self) -> tuple:
        """English and every language with a ``.po`` file here (looked for once)."""
        found = sorted(path.stem for path in self.folder.glob("*.po"))
        return (ENGLISH, *(language for language in found if language != ENGLISH))

    def entries(self, language: str = ENGLISH) -> dict:
        """The raw entries of ``language``'s file by key (the template's for English; empty when none)."""
        self._read(language)
        return self._languages[language]

    def translate(self, english: str, language: str):
        """The translation of the English text ``english`` into ``language`` by an entry without
        msgctxt (not fuzzy), or None."""
        self._read(language)
        return self._by_english[language].get(english)

    def _read(self, language: str):
        if language in self._languages:
            return
        path = self.folder / (TEMPLATE if language == ENGLISH else f"{language}.po")
        entries = read_po_entries(path) if path.is_file() else []
        self._by_english[language] = {entry.english: entry.translation for entry in entries
                                      if entry.key is None and entry.translation and not entry.fuzzy}
        self._languages[language] = {entry.key: entry for entry in entries if entry.key is not None}

    def __contains__(self, key: str) -> bool:
        return key in self.entries()

    def template(self, key: str, language: str) -> str:
        """The text ``key`` in ``language`` without its values (English when not translated); KeyError if unknown."""
        english = self.entries()[key].english
        if language != ENGLISH:
            translated = self.entries(language).get(key)
            if translated and translated.translation and not translated.fuzzy and translated.english == english:
                return translated.translation
        return english

    def text(self, key: str, language: str, **values) -> str:
        """The text ``key`` in ``language`` with ``values`` filled in (``LocalText`` values in the same language,
        numbers with the language's decimal mark: "0,15 m/s" in German)."""
        template = self.template(key, language)
        if not values:
            return template
        return number_format(language).format(template, **{name: _in_language(value, language)
                                                             for name, value in values.items()})

    def __call__(self, key: str, **values) -> "LocalText":
        """The text ``key`` with ``values``, to be put into a language later; KeyError if unknown."""
        if key not in self:  # an unknown key fails where it is written, not where it is shown
            raise KeyError(key)
        return LocalText(self, key, values)


def _in_language(value, language):
    return value.in_language(language) if hasattr(value, "in_language") else value


@dataclass(frozen=True)
class LocalText:
    """A catalogue's text with its values, in any language: ``str()`` is English."""

    catalogue: Catalogue = field(repr=False, compare=False)
    key: str
    values: dict = field(default_factory=dict)

    def in_language(self, language: str) -> str:
        """The text in ``language`` (English where it has no translation)."""
        return self.catalogue.text(self.key, language, **self.values)

    def __str__(self) -> str:
        return self.in_language(ENGLISH)
