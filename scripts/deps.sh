#!/usr/bin/env bash
# Installs the Debian 12 packages Throng needs that are missing; does nothing (and needs
# no network) when all are there. Usage: scripts/deps.sh [build|test]
set -euo pipefail

packages=(g++ cmake ninja-build pkg-config ccache
          qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-svg-dev libqt6svg6 qt6-charts-dev
          libyaml-cpp-dev libglm-dev libtinygltf-dev libassimp-dev libeigen3-dev libtbb-dev
          libgl-dev libgl1-mesa-dri libglx-mesa0)
if [ "${1:-build}" = test ]; then
  packages+=(xvfb xauth)
  # What the external glTF readers the export tests run (../shared/tools: the Khronos
  # validator, Blender, three.js, assimp) would install with apt-get on first use: here,
  # one after the other, since tests running in parallel cannot all hold dpkg's lock.
  # (Their npm packages they install themselves, each atomically.) Node and npm only when
  # missing: a machine may have them from elsewhere (NodeSource's nodejs bundles npm and
  # conflicts with Debian's).
  packages+=(assimp-utils blender python3-numpy)
  # The PedPy export's test reads the set's WKT with Shapely, the geometry library PedPy uses.
  packages+=(python3-shapely)
  # The wedge test submits to a real single-node Slurm it starts (tests/cli/local-slurm.sh).
  packages+=(slurmctld slurmd slurm-client munge)
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { echo "deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
echo "deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q >&2
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
