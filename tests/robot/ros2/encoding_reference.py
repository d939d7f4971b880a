"""What rclpy makes of messages Rockly's side encoded (run with .venv-ros2's Python; for test_cdr_encoding).

Reads one pickled list of ``(type, fields, raw)`` from stdin; ``raw`` is Rockly's CDR bytes, or
None when Rockly's side left the message to the helper. For each, writes back (pickled, in a list)
``(by_fields, decoded)``: the message the helper sends from the fields (``ros_values.to_message``,
rclpy's field checks on, serialised and decoded again), or the error it says; and rclpy's decoding of ``raw``
(``deserialize_message``), or None. Both as the repr of their plain dicts, so NaNs compare.
"""
import importlib.util
import os
import pickle
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[3] / "rockly_desktop"


def load_helper_side():
    """Rockly's helper-side modules, imported from Rockly's folder as the helper does."""
    spec = importlib.util.spec_from_file_location("rockly_desktop", PACKAGE / "__init__.py",
                                                  submodule_search_locations=[str(PACKAGE)])
    package = sys.modules["rockly_desktop"] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(package)


def main():
    os.environ["ROS_PYTHON_CHECK_FIELDS"] = "1"  # as in the helper
    load_helper_side()
    from rclpy.serialization import deserialize_message, serialize_message

    from rockly_desktop.robot.ros2.helper.ros_values import from_message, interface_class, to_message

    answers = []
    for type_name, fields, raw in pickle.load(sys.stdin.buffer):
        message_class = interface_class(type_name, "msg")
        try:
            sent = serialize_message(to_message(message_class, fields))
            by_fields = repr(from_message(deserialize_message(sent, message_class)))
        except Exception as error:  # what the helper would say instead of publishing
            by_fields = error
        decoded = None if raw is None else repr(from_message(deserialize_message(raw, message_class)))
        answers.append((by_fields if isinstance(by_fields, str) else f"refused: {by_fields}", decoded))
    pickle.dump(answers, sys.stdout.buffer)


if __name__ == "__main__":
    main()
