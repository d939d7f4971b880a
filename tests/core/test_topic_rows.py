"""The Topic monitor's rows: the graph's topics merged with what the store heard; cell texts and sort keys."""
import math

from rockly_desktop.core.state_store import TopicInfo
from rockly_desktop.core.topic_rows import NO_VALUE, age_text, row_cells, topic_entries

ODOM = TopicInfo("/odom", "nav_msgs/Odometry", 120, 50.0, 0.02)
OLD = TopicInfo("/old", "std_msgs/String", 3, 0.0, 12.5)


def test_without_a_graph_the_store_topics_have_no_publisher_count():
    assert topic_entries({"/odom": ODOM}) == [("/odom", "nav_msgs/Odometry", None, 120, 50.0, 0.02, 0)]


def test_the_graph_lists_silent_topics_and_the_store_adds_topics_nobody_publishes_now():
    graph = [("/odom", "", 1), ("/scan", "sensor_msgs/LaserScan", 2)]
    assert topic_entries({"/odom": ODOM, "/old": OLD}, graph) == [
        ("/odom", "nav_msgs/Odometry", 1, 120, 50.0, 0.02, 0),       # the type the store knows
        ("/scan", "sensor_msgs/LaserScan", 2, 0, 0.0, 0.0, 0),       # listed, never heard
        ("/old", "std_msgs/String", 0, 3, 0.0, 12.5, 0)]             # heard before, no publisher now
    assert topic_entries({}, []) == []


def test_rocklys_own_publishers_count_in_and_are_said_apart():
    graph = [("/cmd_vel", "geometry_msgs/Twist", 0), ("/odom", "nav_msgs/Odometry", 1)]
    own = {"/cmd_vel": 1, "/odom": 1, "/old": 1}
    assert topic_entries({"/odom": ODOM, "/old": OLD}, graph, own) == [
        ("/cmd_vel", "geometry_msgs/Twist", 1, 0, 0.0, 0.0, 1),      # only Rockly publishes it
        ("/odom", "nav_msgs/Odometry", 2, 120, 50.0, 0.02, 1),       # the robot and Rockly
        ("/old", "std_msgs/String", 1, 3, 0.0, 12.5, 1)]             # not (yet) in the graph: Rockly's


def test_cells_of_a_topic_with_and_without_messages():
    texts, keys = row_cells(("/odom", "nav_msgs/Odometry", 1, 120, 50.0, 0.02))
    assert texts == ("/odom", "nav_msgs/Odometry", "1", "50.0", "0.0")
    assert keys == ("/odom", "nav_msgs/odometry", 1.0, 50.0, 0.02)
    texts, keys = row_cells(("/Scan", "sensor_msgs/LaserScan", None, 0, 0.0, 0.0))
    assert texts == ("/Scan", "sensor_msgs/LaserScan", NO_VALUE, NO_VALUE, NO_VALUE)
    assert keys == ("/scan", "sensor_msgs/laserscan", -1.0, -1.0, math.inf)


def test_ages_lose_their_decimal_from_100_s():
    assert (age_text(0.04), age_text(99.94), age_text(150.4)) == ("0.0", "99.9", "150")


def test_rate_and_age_are_written_with_the_readers_decimal_mark():
    texts, _keys = row_cells(("/odom", "nav_msgs/Odometry", 1, 120, 50.0, 0.25), "de")
    assert texts[3:] == ("50,0", "0,2")
    assert age_text(150.4, "de") == "150" and age_text(2.5, "en") == "2.5"
