#!/usr/bin/env bash
# Installs every Debian package fedsim needs to build, test and run. Idempotent: packages already
# present are skipped by apt. Run as root (or with sudo available).
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # a compiler cache: a fresh clone compiles from an earlier build's objects (CMakeLists.txt)
  ccache
  # middleware: Fast DDS 2.9 + Fast CDR + IDL compiler (fastddsgen needs a JRE)
  libfastrtps-dev libfastcdr-dev libfoonathan-memory-dev fastddsgen fastdds-tools default-jre-headless
  # maths, geodesy, config, logging, CLI
  libeigen3-dev libgeographiclib-dev libyaml-cpp-dev nlohmann-json3-dev libspdlog-dev libcli11-dev
  # navigation database (SQLite with R*Tree) and its gzip-compressed sources
  libsqlite3-dev zlib1g-dev
  # rendering, plots, images
  libosmesa6-dev libpng-dev libjpeg62-turbo-dev gnuplot-nox graphviz
  # headless OpenGL through EGL (--gl egl|auto): libglvnd's libEGL and Mesa's EGL (surfaceless llvmpipe here)
  libegl-dev libegl-mesa0
  # cockpit displays: text through FreeType with the DejaVu fonts
  libfreetype-dev fonts-dejavu-core
  # instructor station: HTTP + WebSocket server (civetweb), and its browser test (Debian's
  # chromium driven by playwright-core from npm, installed below; Node.js with npm)
  libcivetweb-dev chromium nodejs
  # pilot inceptors: joysticks, yokes, pedals through evdev (and uinput virtual devices in tests)
  libevdev-dev
  # tests
  libgtest-dev libgmock-dev
  # another vendor's DDS for the external-trainer example and its interop tests (examples/,
  # docs/interop.md): Eclipse Cyclone DDS's C library and its IDL compiler
  cyclonedds-dev cyclonedds-tools
  # process tools used by tests (pgrep/pkill) and network namespaces
  procps iproute2 strace
  # deploy/containers' checks read compose and Kubernetes YAML (tests/hosts/containers_check.py)
  python3-yaml
  # monitoring: tshark decodes fedsim's RTPS traffic (docs/monitoring.md and its test)
  tshark
  # DDS Security credentials (deploy/security/make-security.sh, docs/security.md)
  openssl
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  # tshark's package asks whether non-root users may capture: no (and never a prompt).
  echo 'wireshark-common wireshark-common/install-setuid boolean false' | $SUDO debconf-set-selections
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Debian's own nodejs package comes without npm (NodeSource's includes it).
if ! command -v npm > /dev/null; then
  $SUDO apt-get install -y -qq --no-install-recommends npm
fi
# The browser tests' packages (tests/browser/package-lock.json: playwright-core, which drives
# the system's chromium and downloads no browser).
browser_tests="$(cd "$(dirname "$0")/../tests/browser" && pwd)"
# (again when the lock file is newer than what was installed from it)
if [ ! -f "$browser_tests/node_modules/.package-lock.json" ] ||
   [ "$browser_tests/package-lock.json" -nt "$browser_tests/node_modules/.package-lock.json" ]; then
  echo "install-deps: npm ci in tests/browser"
  npm ci --prefix "$browser_tests" --no-audit --no-fund --loglevel=error
fi
