"""How deeply a YAML text can nest at most, read from the text alone, before any parser sees it.

libyaml's composer recurses once per level: a few kilobytes of ``[[[[…`` crash the process
(a segfault, nothing Python can catch), and its event parser slows to minutes on them. So
every YAML text Rockly reads is first measured here, in one pass over its characters, and
refused when it could nest deeper than ``MAX_NESTING``.

The figure is an upper bound, never less than the real depth: the indentation levels open at a
line, the sequence dashes that begin it (``- - x``), and the brackets and braces open at any
point of it (quoted text included, so a bracket inside a string counts too). Real files stay
far below the limit: Rockly's deepest is about ten.
"""
MAX_NESTING = 200


def nesting_bound(text: str) -> int:
    """An upper bound of how deeply ``text`` nests when read as YAML."""
    deepest = flow = 0
    indents = [0]
    for line in text.splitlines():
        stripped = line.lstrip(" ")
        if not stripped or stripped.startswith("#"):
            continue
        indent = len(line) - len(stripped)
        while indents[-1] > indent:
            indents.pop()
        if indent > indents[-1]:
            indents.append(indent)
        dashes = start = 0
        while stripped[start:start + 1] in ("-", "?") and stripped[start + 1:start + 2] in (" ", ""):
            dashes += 1
            start += 2
            while stripped[start:start + 1] == " ":
                start += 1
        line_flow = flow
        for character in stripped[start:]:
            if character in "[{":
                flow += 1
                line_flow = max(line_flow, flow)
            elif character in "]}" and flow:
                flow -= 1
        deepest = max(deepest, len(indents) + dashes + line_flow)
    return deepest


def too_deep(text: str):
    """The bound of ``text`` when it is over ``MAX_NESTING`` (the text must be refused), else None."""
    bound = nesting_bound(text)
    return bound if bound > MAX_NESTING else None
