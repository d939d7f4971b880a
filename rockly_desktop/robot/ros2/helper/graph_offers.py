"""What a ROS 2 graph offers beyond its topics (for the block maker): services and actions with
their types, and the nodes' parameters, asked through each node's ``list_parameters`` service.

Types are named as Rockly's profiles name them: ``pkg/Type`` for a service, ``pkg/NameAction``
for an action (as on ROS 1; the helper takes either form).
"""
import threading
import time

ACTION_PART = "/_action/"
# every node's own parameter services (and its type description), no robot's
NODE_OWN_SERVICES = ("/describe_parameters", "/get_parameter_types", "/get_parameters", "/list_parameters",
                     "/set_parameters", "/set_parameters_atomically", "/get_type_description")


def _short(type_name: str) -> str:
    """``pkg/srv/Type`` as ``pkg/Type``."""
    parts = type_name.split("/")
    return f"{parts[0]}/{parts[-1]}"


def typed_services(services) -> list:
    """(service, ``pkg/Type``) of ``services`` ((name, types) as rclpy lists them) that a robot offers:
    not an action's own parts, nor a node's parameter services."""
    return sorted((name, _short(types[0]) if types else "") for name, types in services
                  if ACTION_PART not in name and not name.endswith(NODE_OWN_SERVICES))


def typed_actions(services) -> list:
    """(action, ``pkg/NameAction``) of the action servers among ``services`` (their ``send_goal`` service,
    typed ``pkg/action/Name_SendGoal``)."""
    suffix = f"{ACTION_PART}send_goal"
    return sorted((name[:-len(suffix)], _short(types[0])[:-len("_SendGoal")] + "Action" if types else "")
                  for name, types in services if name.endswith(suffix))


def parameter_names(service_names, client_for, seconds: float) -> list:
    """``node:param`` of every node whose ``list_parameters`` service is among ``service_names`` and
    answers within ``seconds`` (all are asked at once); ``client_for(name)`` gives a client of it."""
    from rcl_interfaces.srv import ListParameters

    asked = []
    for name in service_names:
        if name.endswith("/list_parameters"):
            client = client_for(name)
            if client.service_is_ready():
                done = threading.Event()
                future = client.call_async(ListParameters.Request())
                future.add_done_callback(lambda _future, done=done: done.set())
                asked.append((name[:-len("/list_parameters")], client, future, done))
    deadline = time.monotonic() + seconds
    names = []
    for owner, client, future, done in asked:
        if done.wait(max(0.0, deadline - time.monotonic())) and future.exception() is None:
            names += [f"{owner}:{parameter}" for parameter in future.result().result.names]
        else:
            client.remove_pending_request(future)
    return sorted(names)
