#!/usr/bin/env bash
# Installs every Debian package FoldingMeshes needs (Debian 12), and brings the ones already
# installed up to the version a newcomer would get (a fresh machine gets the newest packages;
# an older image must not hide what they break, see issue 23: libexpat1's security updates).
# Idempotent: safe to run twice; it only calls apt-get when something is missing or outdated.
set -euo pipefail
PACKAGES=(
  build-essential cmake ninja-build git
  paraview paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev libqt5x11extras5-dev qtxmlpatterns5-dev-tools
  mpi-default-dev mpi-default-bin
  libeigen3-dev
  libdraco-dev   # the compact folding-tree file (.fmz) codes leaf geometry with Draco
  xvfb xauth
  python3-numpy python3-dev python3-mpi4py
  # libraries whose CMake packages ParaView's bundled VTK looks for at find_package time
  libhdf5-dev libboost-dev libexpat1-dev libfreetype-dev libgdal-dev libgl2ps-dev libglew-dev
  libjpeg-dev liblz4-dev liblzma-dev libxml2-dev libnetcdf-dev libpng-dev libtheora-dev
  libtiff-dev libx11-dev zlib1g-dev libdouble-conversion-dev libutfcpp-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libgl-dev
  # runtime libraries whose updates change behaviour we depend on (kept current, never pinned)
  libexpat1
)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

installed_version() { dpkg-query -W -f='${Status} ${Version}' "$1" 2>/dev/null | sed -n 's/^install ok installed //p' || true; }
candidate_version() { apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: //p' || true; }

missing=()
for p in "${PACKAGES[@]}"; do
  [ -n "$(installed_version "$p")" ] || missing+=("$p")
done

# Package lists older than a day (or absent) are refreshed, so "outdated" means outdated today.
lists_fresh=$(find /var/lib/apt/lists -maxdepth 1 -name '*_Packages*' -mmin -1440 2>/dev/null | head -n 1)
if [ ${#missing[@]} -gt 0 ] || [ -z "$lists_fresh" ]; then
  if ! $SUDO apt-get update -q; then
    if [ ${#missing[@]} -gt 0 ]; then
      echo "setup: apt-get update failed and packages are missing: ${missing[*]}" >&2
      exit 1
    fi
    echo "setup: apt-get update failed (offline?); checking against the cached package lists" >&2
  fi
fi

outdated=()
for p in "${PACKAGES[@]}"; do
  have=$(installed_version "$p")
  [ -n "$have" ] || continue
  want=$(candidate_version "$p")
  if [ -n "$want" ] && [ "$want" != "(none)" ] && [ "$want" != "$have" ] &&
     dpkg --compare-versions "$want" gt "$have"; then
    outdated+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ] && [ ${#outdated[@]} -eq 0 ]; then
  echo "setup: all packages present and current"
  exit 0
fi
[ ${#missing[@]} -eq 0 ] || echo "setup: installing ${missing[*]}"
[ ${#outdated[@]} -eq 0 ] || echo "setup: upgrading ${outdated[*]}"
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" "${outdated[@]}"
