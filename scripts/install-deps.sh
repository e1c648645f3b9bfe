#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those that are missing.
# Idempotent: when everything is present it checks and returns in well under a
# second. Usage: scripts/install-deps.sh [--check]   (--check: report, install nothing)
set -euo pipefail

PKGS=(
  build-essential   # gcc, g++, make
  cmake             # build system and CTest
  pkg-config
  libopenmpi-dev    # MPI headers and mpicc
  openmpi-bin       # mpirun
  libfftw3-dev      # FFTW3 for the spectra
  zlib1g-dev        # crc32: checkpoint checksums
  libcgal-dev       # CGAL (periodic Delaunay) for the FPO baseline
  libgmp-dev libmpfr-dev  # CGAL's exact number types
  gnuplot-nox       # figures
  clang libclang-rt-dev  # libFuzzer and its sanitizers (make fuzz)
  python3-dev python3-venv  # the Python package (make python; its tests in make test)
)

check_only=0
[ "${1:-}" = "--check" ] && check_only=1

if ! command -v dpkg-query >/dev/null 2>&1 || [ ! -f /etc/debian_version ]; then
  echo "install-deps: this is not a Debian-based system; install by hand: ${PKGS[*]}" >&2
  exit 1
fi

missing=()
for p in "${PKGS[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  case "$status" in
    *" installed") ;;
    *) missing+=("$p") ;;
  esac
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ $check_only -eq 1 ]; then
  echo "install-deps: missing Debian packages: ${missing[*]}" >&2
  exit 1
fi

echo "install-deps: installing missing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: not root and no sudo; install by hand: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done" >&2
