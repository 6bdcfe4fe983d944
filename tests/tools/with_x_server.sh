#!/usr/bin/env bash
# with_x_server.sh WIDTHxHEIGHTxDEPTH COMMAND [ARG...]
#
# Runs COMMAND with DISPLAY set to a virtual X server (Xvfb) of its own, started for it and ended
# after it; the X tests' ctest registrations run under it (tests/CMakeLists.txt). Unlike
# `xvfb-run -a`, nothing here can race:
# - the server chooses a free display number itself and reports it on a pipe once it accepts
#   connections (-displayfd), so two tests started at the same moment never pick one number
#   (xvfb-run -a looks for a free number, then starts the server on it);
# - -noreset: the server does not reset when its last client disconnects, so a client that
#   connects just after another closed never meets a server in the middle of a reset
#   (XOpenDisplay returned NULL, "Failed to open display");
# - the server lives exactly as long as COMMAND: it is ended when COMMAND ends, and it dies with
#   this script even when a timeout kills the script (setpriv --pdeathsig).
# Exit status: COMMAND's; 1 (with the server's log on stderr) when no server started.
set -u

if [ $# -lt 2 ]; then
  echo "usage: $0 WIDTHxHEIGHTxDEPTH COMMAND [ARG...]" >&2
  exit 2
fi
screen=$1
shift

if ! command -v Xvfb >/dev/null 2>&1; then
  echo "with_x_server: Xvfb is not installed (scripts/install-deps.sh installs xvfb)" >&2
  exit 1
fi

dir=$(mktemp -d "${TMPDIR:-/tmp}/monoplane-x.XXXXXX")
server_pid=""
cleanup() {
  if [ -n "$server_pid" ]; then
    kill "$server_pid" 2>/dev/null
    wait "$server_pid" 2>/dev/null
  fi
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT
trap 'exit 129' HUP

# The file the server writes its display number to, as a line. A plain file, read again whole on
# each try: a line read from a pipe with a timeout could lose the digits written before the
# newline.
exec {display_fd}>"$dir/display"

death_signal=()
if setpriv --help 2>&1 | grep -q -- --pdeathsig; then
  death_signal=(setpriv --pdeathsig KILL --)
fi
"${death_signal[@]}" Xvfb -displayfd "$display_fd" -noreset -nolisten tcp -screen 0 "$screen" \
  >"$dir/server.log" 2>&1 &
server_pid=$!
exec {display_fd}>&-

number=""
for _ in $(seq 1 1200); do  # up to a minute: a loaded machine starts a server slowly
  # read succeeds only once the whole line, newline included, is there.
  if read -r number <"$dir/display" && [ -n "$number" ]; then
    break
  fi
  number=""
  if ! kill -0 "$server_pid" 2>/dev/null; then
    break
  fi
  sleep 0.05
done
if [ -z "$number" ]; then
  echo "with_x_server: Xvfb -screen 0 $screen did not start; its log:" >&2
  cat "$dir/server.log" >&2
  exit 1
fi

# Not exec: the server must be ended after COMMAND, whatever its status.
DISPLAY=":$number" "$@" &
command_pid=$!
# A signal to this script interrupts `wait`; the trap's exit then runs cleanup, after passing
# the signal on to COMMAND.
trap 'kill -TERM "$command_pid" 2>/dev/null; exit 143' TERM
trap 'kill -INT "$command_pid" 2>/dev/null; exit 130' INT
wait "$command_pid"
exit $?
