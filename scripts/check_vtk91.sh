#!/usr/bin/env bash
# Builds and tests a commit of FoldingMeshes against Debian 12's plain VTK 9.1 (libvtk9-dev,
# -DFOLDINGMESHES_USE_PARAVIEW=OFF: no plugin, no pvpython/pvbatch/GUI tests) without touching
# the machine's ParaView: Debian's VTK 9.1 and ParaView 5.11 packages conflict, so VTK 9.1 lives
# in a Debian 12 chroot made with debootstrap.
#
#   sudo bash scripts/check_vtk91.sh [REF]      # REF: a commit of this repository, default HEAD
#
# Steps (each is skipped when already done, so the script is safe to run again):
#   1. apt-get install debootstrap on the host if it is missing (installs nothing else there);
#   2. debootstrap --variant=minbase bookworm into $CHROOT (default /work/chroot-vtk91), with
#      bookworm, bookworm-updates and bookworm-security as apt sources;
#   3. mounts /proc and, read-only, the shared data folder next to the repository
#      ($SHARED_DIR, default <repo>/../shared) as /work/shared in the chroot, so that
#      FOLDINGMESHES_DATA_DIR's default (<source>/../shared/data/meshes) finds the meshes;
#      both are unmounted on exit (also on failure);
#   4. apt-get install in the chroot whatever of $PACKAGES is missing. find_package(VTK) of
#      Debian's VTK 9.1 looks for the dependencies of *every* VTK module, Qt5 Widgets/OpenGL
#      included, hence the Qt5 packages; python3-numpy is for the Python examples;
#   5. copies `git archive REF` to /work/src in the chroot (committed content only: uncommitted
#      changes are NOT tested), configures a fresh /work/src/build (Release, Ninja,
#      -DFOLDINGMESHES_USE_PARAVIEW=OFF), builds with $JOBS jobs (default 2) and runs
#      ctest --output-on-failure (rendering tests go through xvfb-run). Exits with ctest's status.
#
# Environment: FOLDINGMESHES_VTK91_CHROOT, FOLDINGMESHES_SHARED_DIR, FOLDINGMESHES_JOBS.
# Needs root (debootstrap, chroot, mount) and Debian's package mirror; the chroot is kept for
# the next run (about 3 GB with a build).
set -euo pipefail

if [ "$(id -u)" -ne 0 ]; then
  exec sudo -E bash "$0" "$@"
fi

REPO="$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)"
REF="${1:-HEAD}"
CHROOT="${FOLDINGMESHES_VTK91_CHROOT:-/work/chroot-vtk91}"
SHARED_DIR="${FOLDINGMESHES_SHARED_DIR:-$REPO/../shared}"
JOBS="${FOLDINGMESHES_JOBS:-2}"
MIRROR="http://deb.debian.org/debian"
PACKAGES=(
  build-essential cmake ninja-build
  libvtk9-dev python3-vtk9 libeigen3-dev libdraco-dev
  # asked for by find_package(VTK) of libvtk9-dev (GUISupportQt, ViewsQt, RenderingQt)
  qtbase5-dev libqt5opengl5-dev
  python3-numpy
  xvfb xauth
)
: "${CHROOT:?}"
COMMIT="$(git -C "$REPO" rev-parse --verify "$REF^{commit}")"
export DEBIAN_FRONTEND=noninteractive

# ---- 1. debootstrap on the host ----
if ! command -v debootstrap > /dev/null; then
  echo "check_vtk91: installing debootstrap on the host"
  apt-get install -y -q --no-install-recommends debootstrap
fi

# ---- 2. the chroot ----
if [ ! -x "$CHROOT/usr/bin/apt-get" ]; then
  echo "check_vtk91: debootstrap bookworm -> $CHROOT"
  mkdir -p "$CHROOT"
  debootstrap --variant=minbase bookworm "$CHROOT" "$MIRROR"
fi
cat > "$CHROOT/etc/apt/sources.list" << EOF
deb $MIRROR bookworm main
deb $MIRROR bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
cp /etc/resolv.conf "$CHROOT/etc/resolv.conf"

in_chroot() {
  chroot "$CHROOT" /usr/bin/env -i HOME=/root LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    DEBIAN_FRONTEND=noninteractive /bin/bash -c "$1"
}

# ---- 3. mounts (before apt: package scripts may want /proc), undone on exit ----
MOUNTED=()
cleanup() {
  local i
  for ((i = ${#MOUNTED[@]} - 1; i >= 0; i--)); do
    umount "${MOUNTED[i]}" || echo "check_vtk91: could not unmount ${MOUNTED[i]}" >&2
  done
}
trap cleanup EXIT
if ! mountpoint -q "$CHROOT/proc"; then
  mount -t proc proc "$CHROOT/proc"
  MOUNTED+=("$CHROOT/proc")
fi
mkdir -p "$CHROOT/work/shared"
if [ -d "$SHARED_DIR" ] && ! mountpoint -q "$CHROOT/work/shared"; then
  mount --bind "$SHARED_DIR" "$CHROOT/work/shared"
  MOUNTED+=("$CHROOT/work/shared")
  mount -o remount,ro,bind "$CHROOT/work/shared"
fi
[ -d "$SHARED_DIR" ] || echo "check_vtk91: $SHARED_DIR not found, real-mesh tests will fail" >&2

# ---- 4. packages in the chroot ----
missing=()
for p in "${PACKAGES[@]}"; do
  in_chroot "dpkg-query -W -f='\${Status}' $p 2>/dev/null | grep -q 'install ok installed'" ||
    missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "check_vtk91: installing in the chroot: ${missing[*]}"
  in_chroot "apt-get update -q && apt-get install -y -q --no-install-recommends ${missing[*]}"
fi

# ---- 5. source, configure, build, test ----
echo "check_vtk91: testing $COMMIT ($(git -C "$REPO" log -1 --format=%s "$COMMIT" | cut -c1-60))"
rm -rf "$CHROOT/work/src"
mkdir -p "$CHROOT/work/src"
git -C "$REPO" archive "$COMMIT" | tar -x -C "$CHROOT/work/src"
in_chroot "cd /work/src &&
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DFOLDINGMESHES_USE_PARAVIEW=OFF &&
  cmake --build build --parallel $JOBS"
status=0
in_chroot "cd /work/src/build && ctest --output-on-failure --timeout 900" || status=$?
echo "check_vtk91: $COMMIT against $(in_chroot "dpkg-query -W -f='libvtk9-dev \${Version}' libvtk9-dev"): ctest exit $status"
exit $status
