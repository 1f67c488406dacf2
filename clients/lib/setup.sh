# SPDX-License-Identifier: Apache-2.0
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
  jq                          # the demo reads values out of nested run summaries (JSON) in the shell
  slurm-wlm munge             # `wrc sweep --slurm`'s test: a single-node Slurm cluster of its own on loopback
)

wrc_missing_packages() {
  local p missing=()
  for p in "${WRC_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]}"
}

# Set-up output: one short line per step on stderr; the package manager's and the compiler's output
# go to the log file named on the first line, whose end is shown only when a step fails.
WRC_SETUP_LOG=${WRC_SETUP_LOG:-$WRC_BUILD_DIR/setup.log}

# wrc_step TITLE COMMAND...: runs COMMAND with its output appended to the set-up log; prints
# "wrc: TITLE ... done (Ns)" or, on a failure, the log's last 60 lines and its path.
wrc_step() {
  local title=$1 start=$SECONDS
  shift
  printf 'wrc: %s ... ' "$title" >&2
  if "$@" >>"$WRC_SETUP_LOG" 2>&1; then
    printf 'done (%ds)\n' $((SECONDS - start)) >&2
  else
    printf 'FAILED\n' >&2
    echo "wrc: the last lines of $WRC_SETUP_LOG:" >&2
    tail -n 60 "$WRC_SETUP_LOG" | sed 's/^/    /' >&2
    echo "wrc: $title failed; the whole output is in $WRC_SETUP_LOG" >&2
    return 1
  fi
}

wrc_apt_install() {
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq || { echo "wrc: apt-get update failed"; return 1; }
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$@"
}

wrc_install_packages() {
  local missing
  missing=$(wrc_missing_packages)
  [ -z "$missing" ] && return 0
  # shellcheck disable=SC2086
  wrc_step "installing $(wc -w <<<"$missing") Debian packages ($missing)" wrc_apt_install $missing
}

# wrc_build: configure (once) and build everything into $WRC_BUILD_DIR.
wrc_build() {
  if [ ! -f "$WRC_BUILD_DIR/CMakeCache.txt" ]; then
    wrc_step "configuring (cmake, Release)" cmake -S "$WRC_ROOT" -B "$WRC_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release || return 1
  fi
  wrc_step "building with $(nproc) jobs" cmake --build "$WRC_BUILD_DIR" -j "$(nproc)" || return 1
}

wrc_setup() {
  mkdir -p "$(dirname "$WRC_SETUP_LOG")"
  : >"$WRC_SETUP_LOG"
  echo "wrc: set-up output goes to $WRC_SETUP_LOG" >&2
  wrc_install_packages && wrc_build
}
