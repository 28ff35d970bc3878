#!/usr/bin/env bash
# Installs what Strata needs from Debian 12's packages (when missing) and builds it (Release).
# Usage: bash scripts/setup.sh [--peers] [BUILD_DIR]   (default: build)
#   --peers: also what `strata bench` measures against: the renderers `--vs-embree` and
#            `--vs-cycles` race (embree-tools' pathtracer, blender); without embree-tools the
#            default-view test skips Embree's Cornell box.
set -euo pipefail
cd "$(dirname "$0")/.."
peers=0
if [ "${1:-}" = "--peers" ]; then peers=1; shift; fi
build_dir=${1:-build}

packages=(
  cmake g++ ninja-build pkg-config
  libembree-dev libtbb-dev libglm-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev
  libopenexr-dev libjpeg-dev libwebp-dev libstb-dev doctest-dev libdraco-dev libmeshoptimizer-dev
  libglfw3-dev libimgui-dev libepoxy-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev
  libopenmpi-dev openmpi-bin
  python3-glad xvfb xauth gnuplot-nox clang libclang-rt-14-dev
  dpkg-dev lintian  # dpkg-shlibdeps: the .deb's dependencies (cpack -G DEB); lintian checks it
  assimp-testmodels  # test data: real OBJ and glTF models (tests/app/test_default_view.cpp, the bench)
)
if ((peers)); then packages+=(embree-tools blender); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=(); [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
