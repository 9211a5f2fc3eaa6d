#!/usr/bin/env bash
# Installs every Debian package Thespis needs (the whole list of DESIGN.md, also the ones later
# parts use), and only those that are missing, then the reference glTF readers the tests check
# exports with (tests/js: the Khronos glTF-Validator and three.js, from the npm registry, at the
# versions package-lock.json pins). Safe to run again; does nothing when all are there.
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
  libespeak-ng-dev espeak-ng libpocketsphinx-dev pocketsphinx-en-us libexpat1-dev
  python3-distributed clang nodejs
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

# Debian's npm comes apart from nodejs; a Node.js that brings its own npm needs none.
if ! command -v npm >/dev/null && ! dpkg-query -W -f='${Status}' npm 2>/dev/null | grep -q "install ok installed"; then
  missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed."
else
  echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update
  "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi

# The glTF checkers, again only when the lock file changed since they were installed.
js="$(dirname "$0")/../tests/js"
if [ ! -f "$js/node_modules/.package-lock.json" ] || [ "$js/package-lock.json" -nt "$js/node_modules/.package-lock.json" ]; then
  echo "install-deps: installing the glTF checkers in tests/js (npm ci)"
  npm ci --prefix "$js" --no-audit --no-fund
fi
