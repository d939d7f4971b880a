"""What the block maker offers with a robot (``offers.robot_offers``): the live graph's topics,
services, actions and parameters marked as live, merged with what the profile declares."""
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.ui.blockmaker.offers import LiveGraph, Offer, robot_offers


def test_the_live_graph_is_offered_marked_and_a_declared_name_is_the_graphs_global_one(hobbit):
    graph = LiveGraph(topics=(("/rosout", "rosgraph_msgs/Log", 1),), services=(("/lamp/switch", "std_srvs/SetBool"),),
                      actions=(("/move_base", "move_base_msgs/MoveBaseAction"),), parameters=("/lamp/brightness",))
    offers = robot_offers(hobbit, graph)
    assert Offer("topic", "/rosout", "rosgraph_msgs/Log", live=True) in offers
    assert Offer("service", "/lamp/switch", "std_srvs/SetBool", live=True) in offers
    assert Offer("parameter", "/lamp/brightness", "", live=True) in offers
    assert [offer for offer in offers if offer.kind == "action"] == [
        Offer("action", "hobbit_arm", "hobbit_msgs/ArmServerAction", live=False),  # declared, not in the graph now
        Offer("action", "move_base", "move_base_msgs/MoveBaseAction", live=True)]  # declared and live: once
    assert Offer("service", "/MMUI", "hobbit_msgs/Request", live=False) in offers


def test_without_a_live_graph_only_the_declared_interface_is_offered_none_of_it_live(hobbit):
    offers = robot_offers(hobbit)
    assert offers and not [offer for offer in offers if offer.live or offer.kind == "parameter"]


def test_the_simulators_graph_is_read_without_waiting(hobbit):
    robot = SimulatedRobot(hobbit)
    try:
        robot.world.params["/max_speed"] = 0.3
        graph = LiveGraph.of(robot)
    finally:
        robot.shutdown()
    assert graph.services == (("/MMUI", "hobbit_msgs/Request"),) and graph.parameters == ("/max_speed",)
    assert Offer("service", "/MMUI", "hobbit_msgs/Request", live=True) in robot_offers(hobbit, graph)
