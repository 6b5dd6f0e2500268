#!/usr/bin/env bash
# Installs the Debian packages Strata builds, tests and plots with, when any is missing.
# With --test, also what only the test tree needs: a browser and an HTML validator for the demo
# report's test (tests/report_browser_test.sh). With --peers, also what
# ../shared/tools/peers/peers.sh builds its VTK peer with (issue 25's side-by-side runs). Safe to
# run repeatedly: it does nothing when everything is present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev libopenimageio-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri libepoxy-dev
  doctest-dev libcli11-dev nlohmann-json3-dev libeigen3-dev
  xvfb xauth assimp-testmodels gnuplot-nox
)
case "${1:-}" in
  --test) packages+=(chromium tidy) ;;
  --peers) packages+=(libvtk9-dev libopenmpi-dev) ;;
  "") ;;
  *) echo "usage: install-deps.sh [--test | --peers]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
