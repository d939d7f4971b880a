#!/usr/bin/env bash
# Install the Debian packages Rockly needs, only those that are missing.
# Works as root (apt-get directly) or as a user with sudo.
set -euo pipefail

packages=(
  # Python from Debian, so Debian's rospy is visible inside the venv
  python3 python3-venv python3-pip
  # QtWebEngine, offscreen and under X
  libnss3 libasound2 libdbus-1-3 libegl1 libgl1 libgbm1 libfontconfig1 libglib2.0-0
  libxkbcommon0 libxkbfile1 libxcomposite1 libxdamage1 libxrandr2 libxtst6 libxcb-dri3-0
  libxcb-cursor0 libxcb-icccm4 libxcb-image0 libxcb-keysyms1 libxcb-randr0
  libxcb-render-util0 libxcb-shape0 libxcb-xkb1 libxkbcommon-x11-0 libx11-xcb1
  fonts-dejavu-core
  # desktop-file-validate checks the launcher
  desktop-file-utils
  # ROS 1 runtime, lean set (no Boost/C++ toolchain)
  python3-rospy python3-rosmaster python3-std-msgs python3-std-srvs python3-geometry-msgs
  python3-sensor-msgs python3-actionlib python3-genpy python3-genmsg
  ros-std-msgs ros-geometry-msgs ros-actionlib-msgs ros-nav-msgs
  # their definition files: the typed ROS blocks read the fields from them
  ros-sensor-msgs ros-std-srvs
)

missing=()
# Blockly is fetched with `npm pack` at set-up; a machine may already have npm from
# another source (e.g. NodeSource's nodejs, which conflicts with Debian's npm).
command -v npm >/dev/null 2>&1 || missing+=(npm)
for pkg in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$pkg" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$pkg")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
echo "Installing Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
