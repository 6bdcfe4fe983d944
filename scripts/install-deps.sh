#!/usr/bin/env bash
# Installs the Debian 12 packages monoplane builds and runs with (as root, through apt-get), and
# any packages named as arguments (scripts/package.sh's tools). Does nothing when they are all
# present, so repeated runs are fast.
set -euo pipefail

# libembree-dev: Embree, the CPU ray caster that finds where a participant's gaze ray meets the
# scene (scenes/scene_ray_cast.h; docs/gaze.md).
# fonts-wqy-microhei: a CJK font for protocols in Chinese, Japanese or Korean (tests and
# docs/protocols.md, "Languages"): 1.6 MB against fonts-noto-cjk's 57 MB download, Latin included.
packages=(
  build-essential cmake ninja-build pkg-config lld
  libvulkan-dev glslc mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  libglm-dev libstb-dev libcli11-dev libtomlplusplus-dev libboost-math-dev
  libgtest-dev libgmock-dev libbenchmark-dev libsqlite3-dev libssl-dev
  libopenxr-dev libopenxr-loader1 libopenxr-utils openxr-layer-corevalidation libglfw3-dev libimgui-dev libx11-dev xvfb xauth xdotool
  librsvg2-dev fonts-dejavu-core libfreetype-dev fonts-wqy-microhei
  libtinygltf-dev nlohmann-json3-dev libmeshoptimizer-dev assimp-testmodels
  python3 python3-pandas r-base-core r-cran-jsonlite r-cran-dbi r-cran-rsqlite
  libeigen3-dev libnlopt-dev chromium libembree-dev
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
