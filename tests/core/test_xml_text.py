"""Rockly's XML escaping says what xml.sax.saxutils says, for any text."""
from xml.sax.saxutils import escape as sax_escape
from xml.sax.saxutils import quoteattr as sax_quoteattr

from hypothesis import given
from hypothesis import strategies as st

from rockly_desktop.core.xml_text import escape, quoteattr


@given(st.text(alphabet=st.sampled_from("ab<>&\"'\n\r\t é"), max_size=30))
def test_escape_and_quoteattr_match_the_standard_library(text):
    assert escape(text) == sax_escape(text)
    assert quoteattr(text) == sax_quoteattr(text)
