"""Which QoS a topic gets (runs in the ROS 2 helper).

Commands are published reliably. A subscription matches what the topic's publishers offer:
best effort when any of them is best effort (a laser driver's sensor-data QoS, which a
reliable subscription would never receive), transient local when all of them keep their last
message for late joiners (a map), else reliable. Before any publisher is seen, sensor types
(laser scans, images, point clouds...) get sensor-data QoS, which also hears reliable
publishers. A profile overrides any topic in ``ros_interface.qos``: ``{/scan: sensor_data}``,
or ``{reliability: best_effort, durability: transient_local, depth: 1}``.
"""
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data

DEPTH = 10
SENSOR_TYPES = {"LaserScan", "Image", "CompressedImage", "PointCloud2", "PointCloud", "Imu", "Range",
                "CameraInfo", "JointState", "MagneticField"}
_NAMED = {
    "reliable": {"reliability": "reliable"},
    "best_effort": {"reliability": "best_effort"},
    "sensor_data": {"reliability": "best_effort", "depth": 5},
    "transient_local": {"reliability": "reliable", "durability": "transient_local"},
}


def from_setting(setting) -> QoSProfile:
    """A profile's QoS setting (a name above or a dict) as a QoSProfile; ValueError when unknown."""
    if isinstance(setting, str):
        if setting not in _NAMED:
            raise ValueError(f"unknown QoS '{setting}' (known: {', '.join(_NAMED)})")
        setting = _NAMED[setting]
    return QoSProfile(depth=int(setting.get("depth", DEPTH)),
                      reliability=ReliabilityPolicy[setting.get("reliability", "reliable").upper()],
                      durability=DurabilityPolicy[setting.get("durability", "volatile").upper()])


def for_publisher(topic: str, overrides: dict) -> QoSProfile:
    """Reliable, volatile, depth 10, unless the profile says otherwise for ``topic``."""
    if topic in overrides:
        return from_setting(overrides[topic])
    return QoSProfile(depth=DEPTH, reliability=ReliabilityPolicy.RELIABLE)


def for_subscription(topic: str, type_name: str, publishers: list, overrides: dict) -> QoSProfile:
    """A QoS that hears the publishers' (``TopicEndpointInfo``s) offer; see the module's text."""
    if topic in overrides:
        return from_setting(overrides[topic])
    offered = [info.qos_profile for info in publishers]
    if any(qos.reliability == ReliabilityPolicy.BEST_EFFORT for qos in offered):
        return qos_profile_sensor_data
    if offered and all(qos.durability == DurabilityPolicy.TRANSIENT_LOCAL for qos in offered):
        return QoSProfile(depth=DEPTH, reliability=ReliabilityPolicy.RELIABLE,
                          durability=DurabilityPolicy.TRANSIENT_LOCAL)
    if not offered and type_name.rsplit("/", 1)[-1] in SENSOR_TYPES:
        return qos_profile_sensor_data
    return QoSProfile(depth=DEPTH, reliability=ReliabilityPolicy.RELIABLE)
