#!/usr/bin/env bash
# install-deps.sh [--check] [GROUP...] - what the project needs, by group:
#   core    the build: compilers, CMake, MPI, FFTW, zlib, libpng (cfpo,
#           cfpo-analyze and the baselines that need no CGAL)
#   cgal    CGAL and its number types: the baselines that triangulate (FPO,
#           LFPO, CCDT, BNOT, Lloyd), cfpo-analyze's Delaunay measures, and
#           what needs every baseline (the Python package, make bench, the
#           tests of those); without it CMake leaves them out and says so
#   fuzz    clang and libFuzzer (make fuzz)
#   python  Python's headers and venv module (make python, the python test)
#   bench   python3 and gnuplot (make bench, make replot, make bench-core)
# No group: core and cgal (what plain `make` asks for). On a Debian-based system, as root, the missing Debian
# packages of those groups are installed with apt-get (idempotent: when
# everything is present it returns in well under a second). Anywhere else
# (no dpkg/apt-get, not root, or CFPO_NO_APT=1) nothing is installed: what is missing is found by looking
# for the commands, headers and pkg-config modules themselves, and only
# reported, with the Debian package names; the script then succeeds, and
# CMake (or the target) says what stops the build, if anything does. A
# failed apt-get (no network) is reported the same way.
# --check: report only, and exit 1 when something is missing.
set -euo pipefail

check_only=0
groups=()
for a in "$@"; do
  case "$a" in
    --check) check_only=1 ;;
    core | cgal | fuzz | python | bench) groups+=("$a") ;;
    *) echo "install-deps: unknown argument '$a' (groups: core cgal fuzz python bench; --check)" >&2; exit 2 ;;
  esac
done
[ ${#groups[@]} -gt 0 ] || groups=(core cgal)

# Debian packages of each group.
pkgs_core=(
  build-essential   # gcc, g++, make
  cmake             # build system and CTest
  pkg-config
  libopenmpi-dev    # MPI headers and mpicc
  openmpi-bin       # mpirun
  libfftw3-dev      # FFTW3 for the spectra
  zlib1g-dev        # crc32: checkpoint checksums
  libpng-dev        # PNG density images (cfpo --density)
)
pkgs_cgal=(
  libcgal-dev       # CGAL (periodic Delaunay): FPO, LFPO, CCDT, BNOT, Lloyd, the Delaunay measures
  libgmp-dev libmpfr-dev  # CGAL's exact number types
)
pkgs_fuzz=(clang libclang-rt-dev)       # libFuzzer and its sanitizers
pkgs_python=(python3-dev python3-venv)  # the extension module; its virtual environment
pkgs_bench=(python3 gnuplot-nox)        # the benchmark driver; its figures

# Whether what a Debian package provides is here, without dpkg: a
# command, a header, a pkg-config module or a test compile.
have() { command -v "$1" >/dev/null 2>&1; }
header() { # header LANG NAME
  printf '#include <%s>\n' "$2" | "$([ "$1" = c++ ] && echo "${CXX:-c++}" || echo "${CC:-cc}")" \
    -x "$1" -E - >/dev/null 2>&1
}
present() {
  case "$1" in
    build-essential) have "${CC:-cc}" && have "${CXX:-c++}" && have make ;;
    cmake | pkg-config | clang | python3) have "$1" ;;
    libopenmpi-dev) have mpicc ;;
    openmpi-bin) have mpirun || have mpiexec ;;
    libfftw3-dev) pkg-config --exists fftw3 2>/dev/null || header c fftw3.h ;;
    zlib1g-dev) pkg-config --exists zlib 2>/dev/null || header c zlib.h ;;
    libpng-dev) pkg-config --exists libpng 2>/dev/null || header c png.h ;;
    libcgal-dev) header c++ CGAL/version.h ;;
    libgmp-dev) header c gmp.h ;;
    libmpfr-dev) header c mpfr.h ;;
    gnuplot-nox) have gnuplot ;;
    libclang-rt-dev)
      have clang && printf 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' |
        clang -x c -fsanitize=fuzzer -o /dev/null - >/dev/null 2>&1 ;;
    python3-dev)
      have python3 && [ -f "$(python3 -c 'import sysconfig; print(sysconfig.get_paths()["include"])' 2>/dev/null)/Python.h" ] ;;
    python3-venv) have python3 && python3 -c 'import venv, ensurepip' >/dev/null 2>&1 ;;
    *) return 1 ;;
  esac
}

wanted=()
for g in "${groups[@]}"; do
  case "$g" in
    core) wanted+=("${pkgs_core[@]}") ;;
    cgal) wanted+=("${pkgs_cgal[@]}") ;;
    fuzz) wanted+=("${pkgs_fuzz[@]}") ;;
    python) wanted+=("${pkgs_python[@]}") ;;
    bench) wanted+=("${pkgs_bench[@]}") ;;
  esac
done

apt=1
if [ "${CFPO_NO_APT:-0}" != 0 ] || ! have dpkg-query || ! have apt-get || [ ! -f /etc/debian_version ] \
   || [ "$(id -u)" -ne 0 ]; then
  apt=0
fi

missing=()
for p in "${wanted[@]}"; do
  if [ $apt -eq 1 ]; then
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    case "$status" in *" installed") continue ;; esac
  else
    present "$p" && continue
  fi
  missing+=("$p")
done

[ ${#missing[@]} -eq 0 ] && exit 0
if [ $check_only -eq 1 ]; then
  echo "install-deps: missing (${groups[*]}): ${missing[*]} (Debian package names)" >&2
  exit 1
fi
if [ $apt -eq 0 ]; then
  echo "install-deps: not found (${groups[*]}): ${missing[*]} (Debian package names)." >&2
  echo "install-deps: nothing installed here (not Debian with apt-get as root, or CFPO_NO_APT set);" \
    "install them with this system's package manager if the build needs them." >&2
  exit 0
fi

echo "install-deps: installing missing Debian packages: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
# A failure (no network) is reported, not fatal: CMake, or the target that
# needs the package, then says what is missing.
if apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; then
  echo "install-deps: done" >&2
else
  echo "install-deps: apt-get failed (no network?); going on without: ${missing[*]}" >&2
fi
