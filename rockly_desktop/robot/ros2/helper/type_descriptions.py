"""A topic's type as its publisher's node describes it (runs in the ROS 2 helper), for a type Rockly has no
definition for: from ROS 2 Iron on, every node serves ``~/get_type_description``
(type_description_interfaces), which gives a type it uses, by name and hash, with the definition files
of it and of every type nested in it (``include_type_sources``).

A topic's publishers say their type's hash (``get_publishers_info_by_topic``); a service's or an
action's servers do not on this ROS 2 (Jazzy), so only topics are described.
"""
import threading
import time

DESCRIPTION_SERVICE = "get_type_description"
ASK_AGAIN_SECONDS = 0.5


def _short(type_name: str) -> str:
    """``pkg/msg/Type`` as ``pkg/Type``."""
    parts = type_name.split("/")
    return f"{parts[0]}/{parts[-1]}"


def described_type(node, topic: str, client_for, seconds: float):
    """``{"type": pkg/Type, "texts": {pkg/Type: .msg text}}`` of ``topic``'s type as one of its publishers'
    nodes describes it within ``seconds`` (in all), or None when none does. ``client_for(service name)`` gives
    a GetTypeDescription client. A publisher not yet discovered, or an answer lost to a server that has not
    matched a new client yet, is asked again (each ask waits ASK_AGAIN_SECONDS) until the time is up."""
    deadline = time.monotonic() + seconds
    me = (node.get_name(), node.get_namespace())
    while time.monotonic() < deadline:
        for info in node.get_publishers_info_by_topic(topic):
            if (info.node_name, info.node_namespace) != me:
                service = f"{info.node_namespace.rstrip('/')}/{info.node_name}/{DESCRIPTION_SERVICE}"
                described = _ask(client_for(service), info, min(ASK_AGAIN_SECONDS, deadline - time.monotonic()))
                if described is not None:
                    return described
        time.sleep(min(0.1, max(0.0, deadline - time.monotonic())))
    return None


def _ask(client, info, seconds: float):
    """What ``client``'s server says of ``info``'s type (as ``described_type``) within ``seconds``, or None."""
    from type_description_interfaces.srv import GetTypeDescription

    if seconds <= 0 or not client.wait_for_service(timeout_sec=seconds):
        return None
    done = threading.Event()
    future = client.call_async(GetTypeDescription.Request(
        type_name=info.topic_type, type_hash=str(info.topic_type_hash), include_type_sources=True))
    future.add_done_callback(lambda _future: done.set())
    if not done.wait(seconds) or future.exception() is not None:
        client.remove_pending_request(future)
        return None
    answer = future.result()
    texts = {_short(source.type_name): source.raw_file_contents for source in answer.type_sources
             if source.encoding == "msg"}
    return {"type": _short(info.topic_type), "texts": texts} if answer.successful and _short(info.topic_type) in texts \
        else None
