# Set-up shared by the `wrc` front end: install missing Debian packages, configure and build.
# Sourced by clients/wrc; defines wrc_setup. Debian packages only (the machines reach no other
# registry); every package is installed only when missing.

# Debian packages wrc needs, with the reason for each.
WRC_PACKAGES=(
  build-essential cmake       # compiler and build
  libeigen3-dev               # linear algebra (spline fits, wheelset equations)
  libsundials-dev             # IDA/CVODE integrators for the wheelset dynamics
  liblcm-dev liblcm-bin       # LCM message bus and lcm-gen
  libssl-dev                  # OpenSSL's SHA-256 for geometry keys and model hashes (not a home-made hash)
  nlohmann-json3-dev          # JSON reports (wrc fit) and run summaries, written by a well-kept library
  liblcm-java libjchart2d-java default-jdk-headless   # lcm-spy, its charts, javac/jar for the types jar
  libgtest-dev libbenchmark-dev   # unit tests and benchmarks
  iproute2 nftables util-linux    # private network namespaces and packet-loss injection in bus tests
  gnuplot-nox                 # `wrc plot`: PNG/SVG pictures through its cairo terminals (pngcairo, svg), no X11
)

wrc_missing_packages() {
  local p missing=()
  for p in "${WRC_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]}"
}

wrc_install_packages() {
  local missing
  missing=$(wrc_missing_packages)
  [ -z "$missing" ] && return 0
  echo "wrc: installing Debian packages: $missing" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq >&2 || { echo "wrc: apt-get update failed" >&2; return 1; }
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing >&2 \
    || { echo "wrc: apt-get install failed for: $missing" >&2; return 1; }
}

# wrc_build: configure (once) and build everything into $WRC_BUILD_DIR.
wrc_build() {
  if [ ! -f "$WRC_BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S "$WRC_ROOT" -B "$WRC_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >&2 || return 1
  fi
  cmake --build "$WRC_BUILD_DIR" -j "$(nproc)" >&2 || return 1
}

wrc_setup() {
  wrc_install_packages && wrc_build
}
