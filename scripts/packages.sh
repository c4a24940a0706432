# Installs the Debian packages given as arguments that are not installed yet (sourced by
# scripts/test and scripts/demo).
ensure_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "simdphys: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# What building and testing simdphys needs (nlohmann-json for scene files, CLI11 for the simdphys
# command, stb_image_write for its and the examples' PNG pictures, pybind11, numpy and pytest for
# the Python module, Open MPI for the batch runner across processes).
SIMDPHYS_BUILD_PACKAGES=(g++ cmake ninja-build make pkg-config libeigen3-dev libhwy-dev libgtest-dev
  libbenchmark-dev libomp-dev nlohmann-json3-dev libcli11-dev libstb-dev pybind11-dev python3-dev
  python3-numpy python3-pytest openmpi-bin libopenmpi-dev)

jobs() { nproc 2>/dev/null || echo 2; }

# The presets build with Ninja (its object files need not wait for the libraries they link to, so
# both cores stay busy: a fifth off the Release build here). A build folder configured by another
# generator is removed first, since CMake cannot switch a folder's generator.
use_ninja_folder() {
  local cache="build/$1/CMakeCache.txt"
  if [ -f "$cache" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$cache"; then
    echo "simdphys: build/$1 was made by another generator; starting it afresh"
    rm -rf "build/$1"
  fi
}
