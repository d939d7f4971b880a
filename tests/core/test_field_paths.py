"""Field paths of message dicts: the drag text of a field, numeric paths, the rows of a message tree."""
from rockly_desktop.core.field_paths import (
    MAX_INDEXED_ITEMS,
    child_fields,
    field_mime_text,
    numeric_paths,
    parse_mime_text,
)

X = "pose.pose.position.x"


def test_drag_text_parsing():
    assert field_mime_text("/odom", X) == f"/odom|{X}"
    assert parse_mime_text(f" /odom | {X} \n|x\n/a|\nplain\n/scan|ranges[3]") == [("/odom", X), ("/scan", "ranges[3]")]
    assert parse_mime_text("") == []


def test_numeric_paths():
    message = {"a": {"b": 1, "c": "text", "d": False}, "e": [0.5, {"f": 2}], "g": 3.0}
    assert numeric_paths(message) == ["a.b", "e[0]", "e[1].f", "g"]


def test_numeric_paths_offer_the_first_list_elements_only():
    assert numeric_paths({"ranges": list(range(100))}) == [f"ranges[{i}]" for i in range(MAX_INDEXED_ITEMS)]
    assert numeric_paths(3.0) == [] and numeric_paths([1, 2]) == []  # a field needs a name


def test_child_fields_name_the_paths_field_value_can_read():
    message = {"pose": {"x": 1.0}, "bad key": 2, "ranges": [1.0, [2.0, 3.0]]}
    assert list(child_fields(message, "", 50)) == [("pose", {"x": 1.0}, "pose"), ("bad key", 2, None),
                                                   ("ranges", [1.0, [2.0, 3.0]], "ranges")]
    assert list(child_fields(message["pose"], "pose", 50)) == [("x", 1.0, "pose.x")]
    assert list(child_fields(message["ranges"], "ranges", 50)) == [("[0]", 1.0, "ranges[0]"),
                                                                   ("[1]", [2.0, 3.0], "ranges[1]")]
    assert list(child_fields([2.0, 3.0], "ranges[1]", 50)) == [("[0]", 2.0, None), ("[1]", 3.0, None)]
    assert list(child_fields({"a": 1}, None, 50)) == [("a", 1, None)]
    assert [label for label, _child, _path in child_fields(list(range(10)), "data", 3)] == ["[0]", "[1]", "[2]"]
