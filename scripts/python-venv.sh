#!/usr/bin/env bash
# python-venv.sh BUILD_DIR [--quiet] - the Python package in a virtual
# environment BUILD_DIR/venv (made when missing, with pip's build tools
# and pytest from PyPI), installed from this checkout by `pip install`
# through scikit-build-core. The CMake build of the package is kept in
# BUILD_DIR/python, so a second call rebuilds only what changed. Needs the
# Debian packages of scripts/install-deps.sh (python3-venv among them).
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
  log "creating $V"
  "$PY" -m venv "$V"
fi
if ! "$V/bin/python" -c "import scikit_build_core, numpy, pytest" 2>/dev/null; then
  log "installing the build tools and pytest from PyPI"
  "$V/bin/python" -m pip install -q --upgrade pip
  "$V/bin/python" -m pip install -q "scikit-build-core>=0.11" "numpy>=1.23" pytest
fi
log "building and installing cfpo (build folder $B/python)"
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
"$V/bin/python" -m pip install -q --no-build-isolation --no-deps \
  -C build-dir="$B/python" "$ROOT"
log "done. Activate with:  source $V/bin/activate"
