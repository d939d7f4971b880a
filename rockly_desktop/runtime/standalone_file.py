"""The text of a standalone export: a Python file that runs a program with the runtime installed
(``rockly export PROGRAM --standalone -o OUT.py``; its command line is ``runtime.standalone``'s).

The file is plain data and five lines of code: ``PROGRAM`` (the source's name, the profile's id and
version, the teacher's limits, the language, the variables' and blocks' names), ``RUN_CODE`` (the
generated Python with its ``__rockly__`` block calls, readable as written) and a call of
``rockly_desktop.runtime.standalone.main``. Without the runtime it says so, in the export's language.
"""
import re

from rockly_desktop import __version__
from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.export import comment_line
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.runtime.standalone import FORMAT, limits_data

# What a triple-quoted literal cannot hold as itself: the backslash and the quote (escaped so that no
# sequence of them ends the literal), a carriage return (Python reads it as a newline), other control
# characters and lone surrogates (not UTF-8).
_ESCAPED = re.compile('[\\\\"\r\x00-\x08\x0b\x0c\x0e-\x1f\x7f\ud800-\udfff]')


def text_literal(text: str) -> str:
    """``text`` as a triple-quoted Python string literal that keeps its lines readable."""
    def escape(match):
        character = match.group()
        return "\\" + character if character in '\\"' else repr(character)[1:-1]
    return '"""' + _ESCAPED.sub(escape, text) + '"""'


def data_literal(value, indent: str = "") -> str:
    """``value`` (dicts of plain values) as a Python literal with one entry of a dict per line."""
    if not isinstance(value, dict) or not value:
        return repr(value)
    inner = indent + "    "
    entries = "".join(f"{inner}{key!r}: {data_literal(item, inner)},\n" for key, item in value.items())
    return "{\n" + entries + indent + "}"


def standalone_text(source: str, profile, run_code: dict, types: dict, limits: Limits, language: str) -> str:
    """The standalone file of a program from ``source`` (its file name) on ``profile``: ``run_code`` is the
    page's ``getRunCode`` answer, ``types`` block id -> block type, ``limits`` the teacher's in force."""
    program = {
        "format": FORMAT,
        "rockly": __version__,
        "source": source,
        "profile": {"id": profile.id, "version": profile.version},
        "limits": limits_data(limits),
        "language": language,
        "variables": dict(run_code.get("variables") or {}),
        "blocks": dict(types),
    }
    code = run_code["code"]
    literal = text_literal(code)
    header = app_text("standalone_header", language, source=source, profile=profile.id, version=profile.version,
                      rockly=__version__)
    usage = app_text("standalone_usage", language)
    missing = app_text("standalone_no_runtime", language)
    return "\n".join([
        "#!/usr/bin/env python3",
        f"# {comment_line(header)}",
        f"#   {comment_line(usage)}",
        "import sys",
        "",
        "PROGRAM = " + data_literal(program),
        "",
        "RUN_CODE = " + literal,
        "",
        'if __name__ == "__main__":',
        "    try:",
        "        from rockly_desktop.runtime.standalone import main",
        "    except ImportError:",
        f"        sys.exit({missing!r})",
        "    sys.exit(main(PROGRAM, RUN_CODE, sys.argv[1:]))",
        "",
    ])
