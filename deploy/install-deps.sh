#!/usr/bin/env bash
# Installs every Debian package fedsim needs to build, test and run. Idempotent: packages already
# present are skipped by apt. Run as root (or with sudo available).
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # middleware: Fast DDS 2.9 + Fast CDR + IDL compiler (fastddsgen needs a JRE)
  libfastrtps-dev libfastcdr-dev libfoonathan-memory-dev fastddsgen fastdds-tools default-jre-headless
  # maths, geodesy, config, logging, CLI
  libeigen3-dev libgeographiclib-dev libyaml-cpp-dev nlohmann-json3-dev libspdlog-dev libcli11-dev
  # navigation database (SQLite with R*Tree) and its gzip-compressed sources
  libsqlite3-dev zlib1g-dev
  # rendering, plots, images
  libosmesa6-dev libpng-dev libjpeg62-turbo-dev gnuplot-nox graphviz
  # cockpit displays: text through FreeType with the DejaVu fonts
  libfreetype-dev fonts-dejavu-core
  # pilot inceptors: joysticks, yokes, pedals through evdev (and uinput virtual devices in tests)
  libevdev-dev
  # tests
  libgtest-dev libgmock-dev
  # process tools used by tests (pgrep/pkill) and network namespaces
  procps iproute2 strace
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
