#!/usr/bin/env bash
# Installs every Debian package Thespis needs (the whole list of DESIGN.md, also the ones later
# parts use), and only those that are missing. Safe to run again; does nothing when all are there.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config ccache make
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-multimedia-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  gstreamer1.0-plugins-base gstreamer1.0-plugins-good
  libopenscenegraph-dev libopencv-dev libopencv-contrib-dev libglm-dev libembree-dev
  libopenexr-dev libtinygltf-dev libstb-dev libsndfile1-dev libzip-dev libssl-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  libeigen3-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri libegl-mesa0 libegl-dev libgl-dev mesa-utils
  libespeak-ng-dev espeak-ng libpocketsphinx-dev pocketsphinx-en-us
  python3-distributed clang
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed."
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update
"${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
