#!/usr/bin/env bash
# python-test.sh BUILD_DIR - CTest's "python" test: installs the package
# into BUILD_DIR/venv (scripts/python-venv.sh: made on a fresh machine,
# updated otherwise), then runs python/tests with pytest against the
# commands of BUILD_DIR (the byte-identity tests need them). Where the
# environment cannot be made here (no python3 or venv module) or its
# build tools cannot be installed (no package index reachable: no
# network), the test is skipped with the reason (exit 77, CTest's
# SKIP_RETURN_CODE); a failed build of the package itself fails it.
set -uo pipefail
B=${1:?usage: python-test.sh BUILD_DIR}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=$(cd "$B" && pwd)
"$ROOT/scripts/python-venv.sh" "$B" --quiet
rc=$?
case $rc in
  0) ;;
  3 | 4) echo "SKIP: the Python package's tests: no environment to build it in (see the line above)"; exit 77 ;;
  *) echo "FAIL: the Python package did not build (python-venv.sh exit $rc)" >&2; exit 1 ;;
esac
cd "$B" || exit 1
CFPO_BUILD="$B" exec "$B/venv/bin/python" -m pytest -q -p no:cacheprovider "$ROOT/python/tests"
