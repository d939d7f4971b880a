"""What the robot links share: following the graph through one feed, started once and stopped."""
from rockly_desktop.robot.link_parts import GraphFollowing


class Feed:
    def __init__(self):
        self.stopped = False

    def graph_topics(self):
        return [("/odom", "nav_msgs/Odometry", 1)]

    def own_publishers(self):
        return {"/cmd_vel": 1}

    def want_parameters(self, wanted):
        self.parameters_wanted = wanted

    def stop(self):
        self.stopped = True


def test_the_graph_is_empty_until_followed_and_the_feed_starts_once():
    started = []
    following = GraphFollowing(lambda: started.append(Feed()) or started[-1])
    assert following.graph_topics() == [] and following.own_publishers() == {}
    feed = following.follow()
    assert following.follow() is feed and started == [feed]
    assert following.graph_topics() == [("/odom", "nav_msgs/Odometry", 1)]
    assert following.own_publishers() == {"/cmd_vel": 1}


def test_stopping_stops_the_feed_says_it_was_followed_and_empties_the_graph():
    following = GraphFollowing(Feed)
    assert following.stop() is False
    feed = following.follow()
    assert following.stop() is True and feed.stopped
    assert following.graph_topics() == [] and following.stop() is False
    assert following.follow() is not feed  # followed again (a ROS 2 link's new helper): a new feed
