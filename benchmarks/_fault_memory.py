"""Memory under a camera's stream: Rockly's RSS after 60 s of a 1 MB x 100 Hz ROS 2 image topic,
against the RSS after 60 s of the same topic with 16-byte images (the baseline), in the same run.

Each stream runs in a fresh process (so neither inherits the other's memory) that does what the
window does with a ROS 2 robot: its link follows the graph (the state store of every topic) and
a run's recorder listens to the store. The camera is a plain rclpy node in its own process
(``tests/robot/ros2/ros2_camera_node.py``, sensor-data QoS), on a domain of this run's own.

The bound stated (and checked by the tests at 60 Hz): the state store keeps at most 16 MB of a
topic's history (128 MB for all topics), the recorder's queue at most 64 MB (as much again while
it writes), so the image stream may cost at most 16 + 2 x 64 MB over the baseline, 250 MB with
the allocator's room. Before issue 19, memory grew ~220 MB/s and was never released.

    python benchmarks/_fault_memory.py
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CAMERA_NODE = REPO / "tests" / "robot" / "ros2" / "ros2_camera_node.py"
ROS2_PYTHON = REPO / ".venv-ros2" / "bin" / "python"
SECONDS = 60
RATE = 100
IMAGE_BYTES = 1 << 20
SMALL_BYTES = 16
BOUND_MB = 250
TOPIC = "/camera/image_raw"


def _rss_mb(pid="self") -> float:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def stream(size: int, domain: int) -> dict:
    """In this process: follow a camera of ``size``-byte images for SECONDS; RSS figures (MB) and counts."""
    sys.path.insert(0, str(REPO))
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.recording.recorder import Recorder
    from rockly_desktop.robot.ros2.client import Ros2Helper
    from rockly_desktop.robot.ros2.environment import Ros2Settings
    from rockly_desktop.robot.ros2.link import Ros2Robot

    settings = Ros2Settings(domain_id=domain, discovery="localhost")
    camera = subprocess.Popen([str(ROS2_PYTHON), str(CAMERA_NODE), str(size), str(RATE)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True, env=settings.environment())
    json.loads(camera.stdout.readline())
    robot = Ros2Robot(ProfileRegistry.discover().get("turtlebot"), settings)
    with tempfile.TemporaryDirectory() as folder:
        recorder = Recorder(Path(folder) / "run.mcap", robot.recording_encoder())
        recorder.start({"program": "camera"})
        robot.state.add_listener(recorder.topic)
        started_rss = _rss_mb()
        robot.follow_graph()
        time.sleep(SECONDS)
        info = next((info for info in robot.state.topics() if info.topic == TOPIC), None)
        figures = {"rss": _rss_mb(), "started_rss": started_rss, "helper_rss": _rss_mb(robot.helper.process.pid),
                   "heard": info.count if info else 0, "kept": info.kept if info else 0,
                   "held_mb": robot.state.held_bytes() / 2 ** 20,
                   "not_recorded": sum(recorder.stats()["dropped"].values())}
        robot.state.remove_listener(recorder.topic)
        recorder.close()
        robot.shutdown()
        Ros2Helper.close_current()
    camera.stdin.close()
    figures["published"] = json.loads(camera.stdout.readline() or "{}").get("published", 0)
    camera.wait(10)
    return figures


def _in_a_process(size: int, domain: int) -> dict:
    code = f"import sys, json; sys.path.insert(0, {str(REPO / 'benchmarks')!r}); import _fault_memory as m; " \
           f"print(json.dumps(m.stream({size}, {domain})))"
    env = dict(os.environ, PYTHONPATH=str(REPO))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=REPO,
                          timeout=SECONDS * 4)
    if done.returncode != 0:
        raise RuntimeError(done.stderr[-2000:])
    return json.loads(done.stdout.strip().splitlines()[-1])


def run():
    """Measure both streams and print the figures, the growth over the baseline and the bound."""
    domain = 150 + os.getpid() % 80
    print(f"Memory after {SECONDS} s of a ROS 2 camera at {RATE} Hz (window's link + state store + recorder):")
    small = _in_a_process(SMALL_BYTES, domain)
    large = _in_a_process(IMAGE_BYTES, domain)
    for name, figures in ((f"{SMALL_BYTES}-byte images (baseline)", small), ("1 MB images", large)):
        print(f"  {name:32s} Rockly RSS {figures['rss']:7.0f} MB (at connect {figures['started_rss']:.0f} MB), "
              f"helper {figures['helper_rss']:5.0f} MB, published {figures['published']}, "
              f"heard {figures['heard']}, kept {figures['kept']} ({figures['held_mb']:.1f} MB), "
              f"dropped by the recorder's queue {figures['not_recorded']}")
    growth = large["rss"] - small["rss"]
    print(f"  1 MB stream over baseline: {growth:+.0f} MB Rockly, {large['helper_rss'] - small['helper_rss']:+.0f} MB "
          f"helper (ratio {large['rss'] / small['rss']:.2f}); bound {BOUND_MB} MB: "
          f"{'held' if growth <= BOUND_MB else 'EXCEEDED'}")
    return {"baseline_rss_mb": small["rss"], "image_rss_mb": large["rss"], "growth_mb": growth, "bound_mb": BOUND_MB}


if __name__ == "__main__":
    run()
