#!/usr/bin/env bash
# Builds the base image of fedsim's containers locally (no image registry is reachable from the
# machines fedsim is built on): a minimal Debian 12 root filesystem made with debootstrap from
# the Debian mirror, imported into podman (or docker) as localhost/fedsim-base:bookworm.
# Then the fedsim image (Containerfile) is built on it from a built tree.
#
#   deploy/containers/build-base-image.sh [--mirror URL] [--engine podman|docker] [--fedsim]
#     --fedsim  also build localhost/fedsim:latest from this checkout's build/ (after the base)
#
# Needs root, debootstrap and podman or docker. Not run in CI (it downloads ~150 MB and takes
# minutes); tests/hosts/containers_test.sh checks the files and runs each federate as its
# container would. See docs/hosts.md.
set -euo pipefail

MIRROR=http://deb.debian.org/debian
ENGINE=""
BUILD_FEDSIM=0
while [ $# -gt 0 ]; do
  case "$1" in
    --mirror) MIRROR="$2"; shift 2 ;;
    --engine) ENGINE="$2"; shift 2 ;;
    --fedsim) BUILD_FEDSIM=1; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "build-base-image: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$ENGINE" ]; then
  if command -v podman >/dev/null; then ENGINE=podman; elif command -v docker >/dev/null; then ENGINE=docker; fi
fi
case "$ENGINE" in
  podman|docker) ;;
  *) echo "build-base-image: need podman or docker (--engine)" >&2; exit 2 ;;
esac
command -v debootstrap >/dev/null || { echo "build-base-image: apt-get install debootstrap" >&2; exit 2; }
[ "$(id -u)" = 0 ] || { echo "build-base-image: debootstrap needs root" >&2; exit 2; }

HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
ROOTFS=$(mktemp -d /tmp/fedsim-rootfs.XXXXXX)
trap 'rm -rf "$ROOTFS"' EXIT

echo "build-base-image: debootstrap bookworm from $MIRROR"
debootstrap --variant=minbase bookworm "$ROOTFS" "$MIRROR"
rm -rf "$ROOTFS"/var/cache/apt/archives/*.deb "$ROOTFS"/var/lib/apt/lists/*
tar -C "$ROOTFS" -c . | "$ENGINE" import - localhost/fedsim-base:bookworm
echo "build-base-image: imported localhost/fedsim-base:bookworm"

if [ "$BUILD_FEDSIM" = 1 ]; then
  [ -x "$ROOT/build/bin/fedsim-timing" ] || { echo "build-base-image: build fedsim first (cmake --build --preset default)" >&2; exit 2; }
  "$ENGINE" build -f "$HERE/Containerfile" -t localhost/fedsim:latest "$ROOT"
  echo "build-base-image: built localhost/fedsim:latest"
fi
