"""The state store fed from a real ROS graph: topics of a separate node, their types, rates."""
from ros_helpers import feed_hears
from waiting import eventually

from rockly_desktop.robot.interrupt import Interrupt


def test_topics_of_a_separate_node_are_listed_with_type_publishers_and_rate(ros_robot):
    feed = ros_robot.follow_graph()
    eventually(lambda: any(topic == "/odom" for topic, _, _ in feed.graph_topics()))
    assert ("/odom", "nav_msgs/Odometry", 1) in feed.graph_topics()
    eventually(lambda: any(info.topic == "/odom" and info.count > 60 for info in ros_robot.state.topics()))
    odom = next(info for info in ros_robot.state.topics() if info.topic == "/odom")
    assert odom.msg_type == "nav_msgs/Odometry"
    # Real rates and ages depend on the machine's load; the arithmetic is checked with a fake clock in tests/core.
    assert odom.rate > 0 and odom.age < 2.0


def test_panel_fields_come_from_the_robot(ros_robot, hobbit):
    ros_robot.follow_graph()
    feed_hears(ros_robot, {"/head/emo": "std_msgs/String"})
    commands = hobbit.load_object("api")(ros_robot.backend(Interrupt()))
    commands.show_emotion("CONCERNED")
    eventually(lambda: ros_robot.state.value("/head/emo", "data") == "CONCERNED")
    eventually(lambda: ros_robot.state.value("/battery_state", "percentage") is not None)
    assert 0 < ros_robot.state.value("/battery_state", "percentage") <= 1


def test_the_parameter_server_is_asked_for_its_names_only_while_they_are_wished(ros_robot, monkeypatch):
    import rospy

    from rockly_desktop.robot.ros1 import state_feed

    polls, asks = [], []
    ask_master, parameter_names = state_feed.ask_master, state_feed.parameter_names
    monkeypatch.setattr(state_feed, "ask_master", lambda uri, method, *args: polls.append(method)
                        or ask_master(uri, method, *args))
    monkeypatch.setattr(state_feed, "parameter_names", lambda uri: asks.append(uri) or parameter_names(uri))
    rospy.set_param("/wished/volume", 3)
    ros_robot.want_parameters(False)
    ros_robot.follow_graph()
    eventually(lambda: polls.count("getSystemState") >= 3, timeout=30)
    assert asks == [] and ros_robot.graph_parameters() == []

    ros_robot.want_parameters(True)
    eventually(lambda: "/wished/volume" in ros_robot.graph_parameters(), timeout=30)
    ros_robot.want_parameters(False)
    assert ros_robot.graph_parameters() == []
    polled = polls.count("getSystemState")
    eventually(lambda: polls.count("getSystemState") >= polled + 2, timeout=30)  # a poll on its way may end first
    asked = len(asks)
    eventually(lambda: polls.count("getSystemState") >= polled + 5, timeout=30)
    assert len(asks) == asked


def test_what_a_rockly_agent_publishes_counts_as_rocklys_and_the_simulated_robots_topics_do_not(ros_robot, ros_master,
                                                                                              tmp_path):
    from agent_tools import AgentProcess

    feed = ros_robot.follow_graph()
    agent = AgentProcess(tmp_path / "library", "--master", ros_master.uri, backend="ros1")
    try:
        answers = "/rockly_agent/from_agent"   # the agent node publishes it (named rockly_PID_… as the simulator)

        def counted():  # as of one look at the graph (its topics and Rockly's are kept one after the other)
            topics, own = feed.graph_topics(), feed.own_publishers()
            return (own.get(answers) == 1 and (answers, "std_msgs/String", 0) in topics
                    and ("/odom", "nav_msgs/Odometry", 1) in topics   # the simulated robot is not Rockly here
                    and "/odom" not in own)
        eventually(counted, 30)
    finally:
        agent.stop()
