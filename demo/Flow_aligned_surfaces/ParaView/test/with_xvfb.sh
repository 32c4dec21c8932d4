#!/usr/bin/env bash
# Runs a command under a private Xvfb: with_xvfb.sh COMMAND [ARGS...].
# Xvfb picks its own free display number and reports it (-displayfd), so tests started at the
# same time never race for one (xvfb-run -a can: two instances may pick the same number).
# The exit status is the command's; the server is stopped afterwards.
set -euo pipefail
report=$(mktemp)
trap 'rm -f "$report"' EXIT
Xvfb -displayfd 3 -nolisten tcp -noreset -screen 0 1280x1024x24 3>"$report" 2>/dev/null &
server=$!
for _ in $(seq 200); do
  [ -s "$report" ] && break
  if ! kill -0 "$server" 2>/dev/null; then echo "with_xvfb: Xvfb did not start" >&2; exit 1; fi
  sleep 0.1
done
if [ ! -s "$report" ]; then echo "with_xvfb: Xvfb reported no display within 20 s" >&2; kill "$server"; exit 1; fi
export DISPLAY=":$(head -n1 "$report")"
status=0
"$@" || status=$?
kill "$server" 2>/dev/null || true
wait "$server" 2>/dev/null || true
exit "$status"
