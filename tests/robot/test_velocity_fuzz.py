"""Whatever a program sends on a drive topic under a speed limit, what the simulated robot gets holds it:
refused with a RobotCommandError, or a velocity of numbers within the limit (hypothesis)."""
import math

from hypothesis import given, settings
from hypothesis import strategies as st

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.sim.simulator import twist_velocity
from rockly_desktop.robot.wrappers.limits import LimitedBackend, Limits

LIMIT, TURN = 0.1, 30.0
scalars = st.one_of(st.floats(), st.integers(-10**20, 10**20), st.booleans(), st.none(),
                    st.text(max_size=5), st.sampled_from(["1.0", "1e9", "inf", "nan", "-2"]))
values = st.recursive(scalars, lambda inner: st.one_of(st.lists(inner, max_size=3),
                                                        st.dictionaries(st.sampled_from("xyzw"), inner, max_size=3)),
                      max_leaves=6)
vectors = st.one_of(values, st.dictionaries(st.sampled_from(["x", "y", "z", "w"]), values, max_size=4))
twists = st.dictionaries(st.sampled_from(["linear", "angular", "twist", "header", "speed"]), vectors, max_size=3)
types = st.sampled_from(["geometry_msgs/Twist", "geometry_msgs/msg/Twist", "geometry_msgs/TwistStamped",
                         "lab_msgs/Twist", "std_msgs/String", "Twist", ""])


@settings(max_examples=400, deadline=None)
@given(msg_type=types, message=st.one_of(twists, values))
def test_a_drive_topic_under_a_limit_gets_numbers_within_it_or_nothing(msg_type, message):
    world, got = SimWorld(), []
    world.subscribe("/cmd_vel", got.append)
    limited = LimitedBackend(SimBackend(world, Interrupt()), Limits(max_speed=LIMIT, max_turn=TURN), ["/cmd_vel"])
    try:
        limited.publish("/cmd_vel", msg_type, message)
    except RobotCommandError:
        assert got == []
        return
    velocity = twist_velocity(got[0])
    assert velocity is not None, got[0]
    linear, angular = velocity
    assert abs(linear) <= LIMIT and abs(angular) <= math.radians(TURN) + 1e-12
