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

# What building and testing simdphys needs.
SIMDPHYS_BUILD_PACKAGES=(g++ cmake make pkg-config libeigen3-dev libhwy-dev libgtest-dev
  libbenchmark-dev libomp-dev)
# What the examples need beyond that: stb_image_write for the renderer's PNG.
SIMDPHYS_EXAMPLE_PACKAGES=(libstb-dev)

jobs() { nproc 2>/dev/null || echo 2; }
