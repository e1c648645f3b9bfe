#!/usr/bin/env bash
# python-venv.sh BUILD_DIR [--quiet] - the Python package in a virtual
# environment BUILD_DIR/venv (made when missing, with pip's build tools
# and pytest from the package index, PyPI unless pip is told otherwise;
# ASE too when the index has it, for the 3-D file tests, else skipped),
# installed from this checkout by `pip install` through scikit-build-core.
# The CMake build of the package is kept in BUILD_DIR/python, so a second
# call rebuilds only what changed. Needs python3 with its headers and venv
# module (scripts/install-deps.sh python).
# Exit status: 0 done; 3 the environment cannot be made here (no python3,
# or no venv module); 4 the build tools could not be installed (no package
# index reachable: no network); anything else, the package's build failed.
set -euo pipefail
B=${1:?usage: python-venv.sh BUILD_DIR [--quiet]}
quiet=${2:-}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$B"
B=$(cd "$B" && pwd)
V="$B/venv"
log() { [ "$quiet" = --quiet ] || echo "python-venv: $*" >&2; }
# The system's Python (Debian's /usr/bin/python3 on a fresh machine).
PY=${PYTHON:-python3}
if [ ! -x "$V/bin/python" ]; then
  command -v "$PY" >/dev/null 2>&1 || { echo "python-venv: $PY not found (scripts/install-deps.sh python)" >&2; exit 3; }
  log "creating $V"
  if ! "$PY" -m venv "$V" 2>"$B/venv-create.log"; then
    rm -rf "$V"
    echo "python-venv: $PY -m venv failed (python3-venv missing? scripts/install-deps.sh python): $(tail -n 1 "$B/venv-create.log")" >&2
    exit 3
  fi
fi
# pip 23.1 or later: -C (config settings) below.
if ! "$V/bin/python" -c "import scikit_build_core, numpy, pytest, pip
assert tuple(int(x) for x in pip.__version__.split('.')[:2]) >= (23, 1)" 2>/dev/null; then
  log "installing pip, the build tools and pytest from the package index"
  # Few retries: without network every one of them only waits.
  export PIP_RETRIES=${PIP_RETRIES:-1} PIP_TIMEOUT=${PIP_TIMEOUT:-15} PIP_DISABLE_PIP_VERSION_CHECK=1
  if ! { "$V/bin/python" -m pip install -q --upgrade pip &&
         "$V/bin/python" -m pip install -q "scikit-build-core>=0.11" "numpy>=1.23" pytest; } 2>"$B/venv-pip.log"; then
    echo "python-venv: could not install pip, scikit-build-core, numpy and pytest (no package index reachable?):" \
      "$(grep -v '^ *$' "$B/venv-pip.log" | tail -n 1)" >&2
    exit 4
  fi
fi
# ASE (optional): the Python tests read the 3-D XYZ and LAMMPS files back
# with it; without it (no package index) those tests are skipped.
if ! "$V/bin/python" -c "import ase" 2>/dev/null; then
  PIP_RETRIES=${PIP_RETRIES:-1} PIP_TIMEOUT=${PIP_TIMEOUT:-15} PIP_DISABLE_PIP_VERSION_CHECK=1 \
    "$V/bin/python" -m pip install -q ase 2>"$B/venv-ase.log" ||
    log "ASE not installed (its file tests will be skipped): $(grep -v '^ *$' "$B/venv-ase.log" | tail -n 1)"
fi
log "building and installing cfpo (build folder $B/python)"
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
"$V/bin/python" -m pip install -q --no-build-isolation --no-deps \
  -C build-dir="$B/python" "$ROOT"
log "done. Activate with:  source $V/bin/activate"
