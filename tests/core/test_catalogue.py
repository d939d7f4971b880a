"""Texts in every language (core/catalogue.py): the .po reader, lookups, and every catalogue Rockly ships
complete: every key in every language, with the same placeholders."""
import shutil
import subprocess
from pathlib import Path

import pytest

from rockly_desktop.core.app_texts import app_catalogue, languages
from rockly_desktop.core.catalogue import Catalogue, placeholders, read_po

REPO = Path(__file__).resolve().parents[2]
CATALOGUES = [REPO / "resources" / "locale", REPO / "profiles" / "hobbit" / "locale",
              REPO / "profiles" / "turtlebot" / "locale"]

TEMPLATE = '''# a header comment
msgid ""
msgstr ""
"Language: en\\n"

#, python-brace-format
msgctxt "greet"
msgid "Hello, {name}!"
msgstr ""

msgctxt "long"
msgid ""
"a text on "
"two lines with \\"quotes\\"\\n"
msgstr ""

msgctxt "thing"
msgid "the ball"
msgstr ""

msgctxt "bumped"
msgid "bumped into {thing}"
msgstr ""
'''
GERMAN = '''msgid ""
msgstr "Language: de\\n"

msgctxt "greet"
msgid "Hello, {name}!"
msgstr "Hallo, {name}!"

#, fuzzy
msgctxt "long"
msgid ""
"a text on "
"two lines with \\"quotes\\"\\n"
msgstr "ein alter Text"

msgctxt "thing"
msgid "the old ball"
msgstr "der alte Ball"

msgctxt "bumped"
msgid "bumped into {thing}"
msgstr "gegen {thing} gestoßen"
'''


@pytest.fixture
def catalogue(tmp_path):
    (tmp_path / "messages.pot").write_text(TEMPLATE, encoding="utf-8")
    (tmp_path / "de.po").write_text(GERMAN, encoding="utf-8")
    return Catalogue(tmp_path)


def test_a_po_file_is_read_by_key_with_joined_lines_and_escapes_and_without_its_header(tmp_path, catalogue):
    entries = read_po(tmp_path / "messages.pot")
    assert list(entries) == ["greet", "long", "thing", "bumped"]
    assert entries["long"].english == 'a text on two lines with "quotes"\n'
    assert read_po(tmp_path / "de.po")["long"].fuzzy and not read_po(tmp_path / "de.po")["greet"].fuzzy


def test_a_po_file_with_an_unknown_escape_or_an_unquoted_text_is_refused_with_its_line(tmp_path):
    (tmp_path / "bad.po").write_text('msgctxt "k"\nmsgid "a \\q b"\nmsgstr ""\n', encoding="utf-8")
    with pytest.raises(ValueError, match=r"bad.po:2: unknown escape \\q"):
        read_po(tmp_path / "bad.po")
    short = 'msgctxt "a"\nmsgid "A"\n\nmsgctxt "b"\nmsgid "B"\nmsgstr ""\n'
    (tmp_path / "short.po").write_text(short, encoding="utf-8")
    with pytest.raises(ValueError, match="short.po:4: the entry before has no msgstr"):
        read_po(tmp_path / "short.po")
    (tmp_path / "open.po").write_text('msgctxt "k"\nmsgid "not closed\nmsgstr ""\n', encoding="utf-8")
    with pytest.raises(ValueError, match="open.po:2: not a quoted text"):
        read_po(tmp_path / "open.po")


def test_a_text_is_looked_up_by_key_with_its_values(catalogue):
    assert catalogue.text("greet", "de", name="Mia") == "Hallo, Mia!"
    assert catalogue.text("greet", "en", name="Mia") == "Hello, Mia!"
    assert catalogue.languages == ("en", "de")


def test_an_untranslated_fuzzy_or_outdated_translation_shows_the_english_text(catalogue):
    assert catalogue.text("greet", "fr", name="Mia") == "Hello, Mia!"             # no fr.po
    assert catalogue.text("long", "de").startswith("a text on")                    # fuzzy
    assert catalogue.text("thing", "de") == "the ball"                             # its English changed since


def test_a_local_text_is_english_as_a_string_and_puts_its_values_into_the_same_language(catalogue):
    text = catalogue("bumped", thing=catalogue("thing"))
    assert str(text) == "bumped into the ball"
    assert text.in_language("de") == "gegen the ball gestoßen"   # "thing" has no current German text
    with pytest.raises(KeyError):
        catalogue("no such key")


def test_a_third_language_is_one_more_file(tmp_path):
    folder = tmp_path / "locale"
    shutil.copytree(REPO / "resources" / "locale", folder)
    (folder / "fr.po").write_text('msgctxt "run"\nmsgid "Run"\nmsgstr "Lancer"\n', encoding="utf-8")
    french = Catalogue(folder)
    assert french.languages == ("en", "de", "fr")
    assert (french.text("run", "fr"), french.text("stop", "fr")) == ("Lancer", "STOP")


def test_rockly_speaks_the_languages_of_its_catalogue():
    assert languages() == app_catalogue().languages == ("en", "de")


@pytest.mark.parametrize("folder", CATALOGUES, ids=lambda folder: str(folder.relative_to(REPO)))
def test_every_catalogue_has_every_key_in_every_language_with_the_same_placeholders(folder):
    catalogue = Catalogue(folder)
    english = catalogue.entries()
    assert english and all(entry.translation == "" for entry in english.values())  # the template
    for language in catalogue.languages[1:]:
        translated = catalogue.entries(language)
        assert sorted(translated) == sorted(english), language
        for key, entry in translated.items():
            assert entry.english == english[key].english, f"{language}: {key} translates an old English text"
            assert entry.translation and not entry.fuzzy, f"{language}: {key} is not translated"
            assert placeholders(entry.translation) == placeholders(entry.english), f"{language}: {key}"
            entry.translation.format(**dict.fromkeys(placeholders(entry.english), 1))  # its format specs work


@pytest.mark.skipif(shutil.which("msgfmt") is None, reason="gettext's msgfmt is not installed")
@pytest.mark.parametrize("folder", CATALOGUES, ids=lambda folder: str(folder.relative_to(REPO)))
def test_gettexts_own_check_accepts_every_catalogue(folder):
    for path in sorted(folder.glob("*.po")):
        checked = subprocess.run(["msgfmt", "--check-format", "-o", "/dev/null", str(path)],
                                 capture_output=True, text=True, check=False)
        assert checked.returncode == 0, checked.stderr
