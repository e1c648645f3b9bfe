#!/usr/bin/env bash
# python-test.sh BUILD_DIR - CTest's "python" test: installs the package
# into BUILD_DIR/venv (scripts/python-venv.sh: made on a fresh machine,
# updated otherwise), then runs python/tests with pytest against the
# commands of BUILD_DIR (the byte-identity tests need them).
set -euo pipefail
B=${1:?usage: python-test.sh BUILD_DIR}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=$(cd "$B" && pwd)
"$ROOT/scripts/python-venv.sh" "$B" --quiet
cd "$B"
CFPO_BUILD="$B" exec "$B/venv/bin/python" -m pytest -q -p no:cacheprovider "$ROOT/python/tests"
