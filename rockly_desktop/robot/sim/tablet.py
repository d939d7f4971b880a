"""What a simulated robot may ask the person at its tablet, in Rockly's own words.

A simulator is given a tablet port: ``ask(question, text, timeout, interrupt) -> str``
(blocking until the person answers; a ``TabletQuestion`` says which answer it wants) and
``notify(text)`` (a message that waits for nothing). The window shows dialogs
(``ui/docks/tablet.py``), ``rockly run``/``rockly sim`` answer from ``--answer`` (``answer_list.py``).
A profile maps its robot's own dialog codes onto these.
"""
from enum import Enum


class TabletQuestion(str, Enum):
    """The kind of a tablet question, and so the answer ``ask`` returns."""

    YES_NO = "yes_no"   # answered 'yes' or 'no'
    TEXT = "text"       # answered with the text typed
    OK = "ok"           # a message the person confirms; answered ''
