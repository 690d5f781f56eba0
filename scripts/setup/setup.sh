#!/usr/bin/env bash
# Installs the Debian 12 packages rollcheck needs (idempotent), then configures
# and builds it in Release under build/. Run as root on a fresh machine.
# Arguments name the targets to build (the main job needs the two programs
# only, not the tests and benchmarks); none builds everything.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)

packages=(
  build-essential cmake pkg-config ninja-build git jq ccache
  libdolfinx-dev libdolfinx-real-dev python3-ffcx
  libgmsh-dev libeigen3-dev libhdf5-openmpi-dev libqhull-dev
  libopenmpi-dev openmpi-bin
  libtomlplusplus-dev libcli11-dev libspdlog-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenblas0-pthread liblapack-dev
  libnlopt-cxx-dev
  python3-matplotlib python3-h5py python3-numpy python3-jinja2 python3-meshio
  chromium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  # One update per set-up, and only when something is missing.
  apt-get update -qq
  apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# Configured once: a build re-runs CMake itself when a CMakeLists.txt changes,
# and stamps the commit itself (cmake/commit_stamp.cmake).
[[ -f "$here/build/build.ninja" ]] || cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$here/build" -j "$(nproc)" "${targets[@]}"
