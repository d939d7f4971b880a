"""The manifest reference, written from ``MANIFEST_FIELDS`` so the docs cannot drift from it.

``rockly profiles reference`` prints it; docs/writing-a-robot-profile.md holds the same
text between ``REFERENCE_START`` and ``REFERENCE_END`` (a test keeps the two equal).
"""
from rockly_desktop.profiles.manifest import MANIFEST_FIELDS

REFERENCE_START = "<!-- manifest-reference:start -->"
REFERENCE_END = "<!-- manifest-reference:end -->"


def _cell(text: str) -> str:
    """``text`` made safe for one Markdown table cell (``<package>`` stays visible, ``|`` splits no cell)."""
    for raw, escaped in (("&", "&amp;"), ("<", "&lt;"), (">", "&gt;"), ("|", "\\|"), ("\n", " ")):
        text = text.replace(raw, escaped)
    return text


def manifest_reference_markdown() -> str:
    """A Markdown table of the ``profile.yaml`` fields: name | required | meaning."""
    rows = ["| Field | Required | Meaning |", "| --- | --- | --- |"]
    rows += [f"| `{spec.name}` | {'yes' if spec.required else 'no'} | {_cell(spec.description)} |"
             for spec in MANIFEST_FIELDS]
    return "\n".join(rows) + "\n"
