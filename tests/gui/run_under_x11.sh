#!/usr/bin/env bash
# Runs a GUI test on a private X server with a window manager (Xvfb + openbox), as a person
# sees the editor: window activation, focus and platform key bindings differ from the
# offscreen platform (Ctrl+Shift+Z bound twice to Redo only showed up here).
#   run_under_x11.sh TEST_BINARY [ARGS...]
set -u
tmp=$(mktemp -d)
trap 'kill ${wm:-} ${xvfb:-} 2>/dev/null; rm -rf "$tmp"' EXIT
# -displayfd: the server picks a free display and writes its number (parallel tests).
Xvfb -displayfd 5 -screen 0 1600x1000x24 -nolisten tcp 5>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
for _ in $(seq 100); do
  [ -s "$tmp/display" ] && break
  sleep 0.1
done
[ -s "$tmp/display" ] || { echo "run_under_x11: Xvfb did not start" >&2; cat "$tmp/xvfb.log" >&2; exit 1; }
export DISPLAY=":$(head -n1 "$tmp/display")"
openbox >/dev/null 2>&1 &
wm=$!
sleep 0.5
QT_QPA_PLATFORM=xcb "$@"
