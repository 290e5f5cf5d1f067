#!/usr/bin/env bash
# Installs every Debian package FoldingMeshes needs (Debian 12). Idempotent: safe to run twice.
set -euo pipefail
PACKAGES=(
  build-essential cmake ninja-build git
  paraview paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev libqt5x11extras5-dev qtxmlpatterns5-dev-tools
  mpi-default-dev mpi-default-bin
  libeigen3-dev
  xvfb xauth
  python3-numpy python3-dev python3-mpi4py
  # libraries whose CMake packages ParaView's bundled VTK looks for at find_package time
  libhdf5-dev libboost-dev libexpat1-dev libfreetype-dev libgdal-dev libgl2ps-dev libglew-dev
  libjpeg-dev liblz4-dev liblzma-dev libxml2-dev libnetcdf-dev libpng-dev libtheora-dev
  libtiff-dev libx11-dev zlib1g-dev libdouble-conversion-dev libutfcpp-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libgl-dev
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
