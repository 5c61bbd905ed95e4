#!/usr/bin/env bash
# usage: run_cli.sh EXPECTED_EXIT EXPECTED_SUBSTRING COMMAND [ARGS...]
# A points file named "-" in ARGS is not special; stdin is /dev/null unless STDIN_FILE is set.
set -u
want_code=$1; want_text=$2; shift 2
out=$(mktemp); err=$(mktemp)
if [ -n "${STDIN_FILE:-}" ]; then "$@" <"$STDIN_FILE" >"$out" 2>"$err"; else "$@" </dev/null >"$out" 2>"$err"; fi
code=$?
status=0
if [ "$code" != "$want_code" ]; then echo "exit code $code, expected $want_code"; status=1; fi
if ! grep -qF -- "$want_text" "$out" "$err"; then echo "output lacks: $want_text"; status=1; fi
if [ "$want_code" = 2 ]; then
  # Bad input: exactly one line on stderr, nothing on stdout.
  [ "$(wc -l <"$err")" = 1 ] || { echo "stderr is not one line"; status=1; }
  [ -s "$out" ] && { echo "stdout not empty on error"; status=1; }
fi
if [ $status != 0 ]; then echo "--- stdout"; head -20 "$out"; echo "--- stderr"; cat "$err"; fi
rm -f "$out" "$err"
exit $status
