#!/usr/bin/env python3
"""Move (English, German) text pairs from a Python dict into Rockly's catalogues.

    scripts/move-texts.py rockly_desktop/ui/texts.py            # its `_TEXTS = {...}` goes to resources/locale
    scripts/move-texts.py BRANCH:rockly_desktop/ui/texts.py     # the file as a git branch has it
    scripts/move-texts.py FILE --name _KINDS --prefix problem_kind_
    scripts/move-texts.py FILE --catalogue profiles/hobbit/locale --keep

FILE holds a module-level ``NAME = {"key": ("English", "German"), ...}``. Each pair becomes an
entry (msgctxt key, msgid English) in ``messages.pot`` and ``de.po`` of the catalogue folder;
a key already there with the same texts is skipped, one with other texts is an error (listing
them all; ``--replace`` writes the new texts over the old ones). The assignment is then removed
from FILE (``--keep`` leaves it; a ``REV:PATH`` is read with ``git show`` and never changed).
Merging a branch that added pairs to ui/texts.py's old ``_TEXTS``: keep this branch's
ui/texts.py (``git checkout --ours rockly_desktop/ui/texts.py``), then run the script on
``BRANCH:rockly_desktop/ui/texts.py``; only its new or changed pairs reach the catalogue.
"""
import argparse
import ast
import re
import string
import subprocess
import sys
from pathlib import Path

HEADER = ('msgid ""\nmsgstr ""\n"Project-Id-Version: {project}\\n"\n"Language: {language}\\n"\n'
          '"MIME-Version: 1.0\\n"\n"Content-Type: text/plain; charset=UTF-8\\n"\n'
          '"Content-Transfer-Encoding: 8bit\\n"\n')


def po_string(text: str) -> str:
    """``text`` as a quoted .po string."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\t", "\\t")
    return f'"{escaped}"'


def po_entry(key: str, english: str, translation: str) -> str:
    """One .po entry (with the python-brace-format flag when the English text has placeholders)."""
    has_values = any(name is not None for _, name, _, _ in string.Formatter().parse(english))
    flag = "#, python-brace-format\n" if has_values else ""
    return f"\n{flag}msgctxt {po_string(key)}\nmsgid {po_string(english)}\nmsgstr {po_string(translation)}\n"


def replace_entry(path: Path, key: str, entry: str) -> None:
    """Put ``entry`` in place of the entry of ``key`` in the catalogue file ``path``."""
    text = path.read_text(encoding="utf-8")
    old = re.compile(r"\n(#[^\n]*\n)*msgctxt " + re.escape(po_string(key)) + r"\n(?:(?:msgid|msgstr|\")[^\n]*\n?)*")
    path.write_text(old.sub(lambda _match: entry, text, count=1), encoding="utf-8")


def find_dict(source: str, name: str):
    """(first line, last line, value) of the module-level assignment ``name = {...}`` in ``source``."""
    for node in ast.parse(source).body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if any(isinstance(target, ast.Name) and target.id == name for target in targets):
                return node.lineno, node.end_lineno, ast.literal_eval(node.value)
    raise SystemExit(f"no module-level {name} = {{...}} found")


def read_keys(path: Path) -> dict:
    """key -> (msgid, msgstr) of the entries already in a catalogue file."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    from rockly_desktop.core.catalogue import read_po

    return {key: (entry.english, entry.translation) for key, entry in read_po(path).items()} if path.is_file() else {}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", help="a Python file, or REV:PATH of one in git")
    parser.add_argument("--name", default="_TEXTS", help="the dict's name (default _TEXTS)")
    parser.add_argument("--prefix", default="", help="put this before every key")
    parser.add_argument("--catalogue", type=Path, default=Path("resources/locale"), help="the catalogue folder")
    parser.add_argument("--project", default="Rockly", help="Project-Id-Version of new catalogue files")
    parser.add_argument("--keep", action="store_true", help="leave the dict in FILE")
    parser.add_argument("--replace", action="store_true", help="write changed texts over the catalogue's")
    args = parser.parse_args(argv)
    in_git = ":" in args.file and not Path(args.file).exists()
    if in_git:
        source = subprocess.run(["git", "show", args.file], capture_output=True, text=True, check=True).stdout
    else:
        source = Path(args.file).read_text(encoding="utf-8")
    first, last, pairs = find_dict(source, args.name)
    files = {"en": args.catalogue / "messages.pot", "de": args.catalogue / "de.po"}
    known = {language: read_keys(path) for language, path in files.items()}
    added = {language: [] for language in files}
    changed = []
    for key, (english, german) in pairs.items():
        key = args.prefix + key
        if key in known["en"]:
            if known["en"][key][0] != english or known["de"].get(key, (None, None))[1] != german:
                changed.append((key, english, german))
            continue
        added["en"].append(po_entry(key, english, ""))
        added["de"].append(po_entry(key, english, german))
    if changed and not args.replace:
        listed = "\n".join(f"  {key}: {english!r} / {german!r}" for key, english, german in changed)
        raise SystemExit(f"these keys are in {args.catalogue} with other texts (--replace takes these):\n{listed}")
    args.catalogue.mkdir(parents=True, exist_ok=True)
    for key, english, german in changed:
        for language, path in files.items():
            replace_entry(path, key, po_entry(key, english, "" if language == "en" else german))
    for language, path in files.items():
        if not path.is_file():
            path.write_text(HEADER.format(project=args.project, language=language), encoding="utf-8")
        with path.open("a", encoding="utf-8") as catalogue:
            catalogue.write("".join(added[language]))
    if not args.keep and not in_git:
        lines = source.splitlines(keepends=True)
        Path(args.file).write_text("".join(lines[:first - 1] + lines[last:]), encoding="utf-8")
    print(f"{len(added['en'])} texts added to {args.catalogue}, {len(changed)} changed, "
          f"{len(pairs) - len(added['en']) - len(changed)} were there already")
    return 0


if __name__ == "__main__":
    sys.exit(main())
