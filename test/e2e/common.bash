# Preamble of the end-to-end scripts of test/e2e/, sourced first by each. ctest runs every test/e2e/*.sh as
#   bash SCRIPT.sh TUTORIAL_BIN_DIR DATA_DIR
# from a scratch directory (this file's name does not end in .sh, so it is no test itself).
#
# Usage, at the top of a script:
#   source "$(dirname "${BASH_SOURCE[0]}")/common.bash" TUTORIAL "$@"
# Sets BIN (TUTORIAL_BIN_DIR/TUTORIAL, which must be executable), BIN_DIR, DATA, and WORK, a fresh directory
# under the current one that becomes the current directory and is removed at exit. Defines
#   fail MESSAGE   reports a failed check on stderr; with E2E_FAIL_FAST=1 set before sourcing, exits 1 at once,
#                  otherwise counts it in FAILS and the script goes on
#   pass MESSAGE   reports a passed check on stdout
#   e2e_finish     the script's last line: exit 1 if a check failed, else 0
#   expect_error CODE PATTERN ARGS...
#                  runs BIN ARGS and checks a bad input's contract: exit status CODE, exactly one line on stderr,
#                  matching the grep pattern PATTERN (stdout in ./expect_error.out, stderr in
#                  ./expect_error.err)
#   run_or_stop WHAT ARGS...
#                  runs BIN ARGS (stdout in ./run.log, stderr in ./run.err): a pass naming WHAT with the output, or a
#                  fail and the script ends there (nothing after a failed run can be checked)
set -u

if [ $# -lt 3 ]; then
  echo "usage: bash $(basename "$0") TUTORIAL_BIN_DIR DATA_DIR" >&2
  exit 2
fi
BIN_DIR="$2"
DATA="$3"
BIN="$BIN_DIR/$1"
WORK=$(mktemp -d "$PWD/$(basename "$0" .sh).XXXXXX") || exit 1
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

FAILS=0
fail() {
  echo "FAIL: $*" >&2
  if [ "${E2E_FAIL_FAST:-0}" = 1 ]; then
    exit 1
  fi
  FAILS=$((FAILS + 1))
}
pass() { echo "ok: $*"; }
expect_error() {
  local code=$1 pattern=$2
  shift 2
  "$BIN" "$@" > expect_error.out 2> expect_error.err
  local rc=$?
  [ $rc -eq "$code" ] || fail "$* : exit code $rc, expected $code"
  [ "$(wc -l < expect_error.err)" -eq 1 ] || fail "$* : expected one line on stderr, got: $(cat expect_error.err)"
  grep -q -- "$pattern" expect_error.err || fail "$* : stderr does not mention '$pattern': $(cat expect_error.err)"
}
run_or_stop() {
  local what=$1
  shift
  if "$BIN" "$@" >run.log 2>run.err; then
    pass "$what ran: $(cat run.log)"
  else
    fail "$what failed: $(cat run.err)"
    e2e_finish
  fi
}
e2e_finish() {
  if [ "$FAILS" -ne 0 ]; then
    echo "$FAILS check(s) failed" >&2
    exit 1
  fi
  echo "all checks passed"
  exit 0
}

[ -x "$BIN" ] || { echo "FAIL: no executable $BIN" >&2; exit 1; }
