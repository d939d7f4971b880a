#!/usr/bin/env bash
# Make .venv-ros2: ROS 2 for Rockly's ROS 2 helper process, from the pinned wheels in
# requirements-ros2.txt. Idempotent: a venv whose stamp matches the requirements is kept.
set -euo pipefail
cd "$(dirname "$0")/.."

venv=.venv-ros2
stamp=$venv/.requirements
if [ -f "$stamp" ] && cmp -s requirements-ros2.txt "$stamp"; then
  exit 0
fi
[ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r requirements-ros2.txt
"$venv/bin/python" -c "import rclpy, std_msgs.msg, test_msgs.action"
cp requirements-ros2.txt "$stamp"
echo "ROS 2 is set up in $venv"
