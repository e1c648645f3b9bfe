# cli_expect.sh - sourced by the command-line tests (test_cli.sh,
# test_density_cli.sh): the pass/fail counters, ok and bad, and
# expect CODE PATTERN ARGS..., which runs "$CFPO" ARGS in the current folder
# and checks the exit code, one stderr line matching PATTERN, nothing on
# stdout and no file left behind.
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }

# expect CODE PATTERN ARGS...: exit code, one stderr line matching PATTERN,
# nothing on stdout, and no file created in the folder.
expect() {
  local code=$1 pat=$2; shift 2
  local before after
  before=$(ls -A | sort)
  "$CFPO" "$@" >out.log 2>err.log
  local rc=$?
  after=$(ls -A | grep -v -e '^out.log$' -e '^err.log$' | sort)
  local lines; lines=$(wc -l <err.log)
  if [ "$rc" -ne "$code" ]; then bad "cfpo $*: exit $rc, expected $code ($(cat err.log))"; return; fi
  if [ "$lines" -ne 1 ]; then bad "cfpo $*: $lines lines on stderr: $(cat err.log)"; return; fi
  if ! grep -q -- "$pat" err.log; then bad "cfpo $*: message '$(cat err.log)' lacks '$pat'"; return; fi
  if [ -s out.log ]; then bad "cfpo $*: printed on stdout: $(cat out.log)"; return; fi
  if [ "$after" != "$(echo "$before" | grep -v -e '^out.log$' -e '^err.log$')" ]; then bad "cfpo $*: left files: $after"; return; fi
  ok
}
