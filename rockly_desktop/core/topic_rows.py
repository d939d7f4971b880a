"""The Topic monitor's rows: every topic the graph lists or the state store heard, with the
cells' texts and sort keys (columns topic, type, publishers, rate, age)."""
import math

from rockly_desktop.core.numbers import number_format

NO_VALUE = "–"
"""A cell without a value (no message yet, no publisher count)."""


def topic_entries(infos: dict, graph_topics=None, own: dict = None) -> list:
    """[(topic, type, publishers or None, count, rate, age, Rockly's among the publishers)] from the
    store's ``{topic: TopicInfo}``.

    Without ``graph_topics`` (the simulator), the store's topics with no publisher count; with
    the graph's [(topic, type, the others' publishers)], its topics (silent ones too) and then those
    heard before that nobody publishes now (0 publishers). Rockly's ``own`` publishers ({topic: count})
    count in: a topic a program drives has its publisher.
    """
    if graph_topics is None:
        return [(info.topic, info.msg_type, None, info.count, info.rate, info.age, 0) for info in infos.values()]
    own = own or {}
    entries, listed = [], set()
    for topic, msg_type, publishers in graph_topics:
        info, mine = infos.get(topic), own.get(topic, 0)
        entries.append((topic, msg_type or (info.msg_type if info else ""), publishers + mine,
                        info.count if info else 0, info.rate if info else 0.0, info.age if info else 0.0, mine))
        listed.add(topic)
    for topic, info in infos.items():
        if topic not in listed:
            mine = own.get(topic, 0)
            entries.append((topic, info.msg_type, mine, info.count, info.rate, info.age, mine))
    return entries


def age_text(age: float, language: str = "en") -> str:
    """Seconds since the last message: one decimal below 100 s, in ``language``'s decimal mark."""
    return number_format(language).format("{:.1f}" if age < 100 else "{:.0f}", age)


def row_cells(entry, language: str = "en") -> tuple:
    """(texts, sort keys) of one entry's five cells, numbers in ``language``'s way; a topic without
    messages has no rate or age. The publishers are a plain count here (the window says which of
    them are Rockly's)."""
    topic, msg_type, publishers, count, rate, age = entry[:6]
    seen = count > 0
    texts = (topic, msg_type, NO_VALUE if publishers is None else str(publishers),
             number_format(language).format("{:.1f}", rate) if seen else NO_VALUE,
             age_text(age, language) if seen else NO_VALUE)
    keys = (topic.lower(), msg_type.lower(), -1.0 if publishers is None else float(publishers),
            rate if seen else -1.0, age if seen else math.inf)
    return texts, keys
