"""XML text escaping, as ``xml.sax.saxutils`` does it, without importing it: that module pulls in
urllib, http.client and ssl, 13 ms of Rockly's start."""


def escape(text: str) -> str:
    """``text`` with ``&``, ``<`` and ``>`` escaped for XML (as xml.sax.saxutils.escape)."""
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def quoteattr(text: str) -> str:
    """``text`` escaped and quoted as an XML attribute value (as xml.sax.saxutils.quoteattr)."""
    text = escape(text).replace("\n", "&#10;").replace("\r", "&#13;").replace("\t", "&#9;")
    if '"' not in text:
        return f'"{text}"'
    if "'" not in text:
        return f"'{text}'"
    return '"{}"'.format(text.replace('"', "&quot;"))
