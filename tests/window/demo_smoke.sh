#!/usr/bin/env bash
# Smoke test of the demo window under Xvfb: it opens, a key switches the shading mode (the title says
# which), B switches the lighting model, and Esc quits with exit code 0. The pixel-exact end-to-end test
# of the window is the demo issue's; this one proves the window path works at all.
set -euo pipefail
shadelab=$1
fail() { echo "demo_smoke: FAIL: $*" >&2; exit 1; }

workdir=$(mktemp -d)
trap 'kill "${xvfb_pid:-}" "${demo_pid:-}" 2>/dev/null || true; rm -rf "$workdir"' EXIT

# A display number nobody uses: Xvfb picks one and writes it to fd 3 (-displayfd).
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$workdir/display" 2>"$workdir/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 50); do [ -s "$workdir/display" ] && break; sleep 0.1; done
[ -s "$workdir/display" ] || fail "Xvfb did not start: $(cat "$workdir/xvfb.log")"
export DISPLAY=":$(cat "$workdir/display")"

"$shadelab" >"$workdir/demo.log" 2>&1 &
demo_pid=$!
window=""
for _ in $(seq 100); do
  window=$(xdotool search --name '^shadelab' 2>/dev/null | head -n 1 || true)
  [ -n "$window" ] && break
  kill -0 "$demo_pid" 2>/dev/null || fail "the demo exited early: $(cat "$workdir/demo.log")"
  sleep 0.1
done
[ -n "$window" ] || fail "no shadelab window appeared"

expect_title() { # waits for the title to contain $1
  for _ in $(seq 50); do
    xdotool getwindowname "$window" | grep -q -- "$1" && return 0
    sleep 0.1
  done
  fail "title is '$(xdotool getwindowname "$window")', expected it to contain '$1'"
}

expect_title "phong shading, blinn-phong lighting"
xdotool windowfocus --sync "$window"
for key_mode in "1 flat" "2 gouraud" "4 toon" "3 phong" "f flat" "t toon"; do
  set -- $key_mode
  xdotool key --window "$window" "$1"
  expect_title "$2 shading"
done
xdotool key --window "$window" b
expect_title "toon shading, phong lighting"
xdotool key --window "$window" Escape
for _ in $(seq 50); do kill -0 "$demo_pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$demo_pid" 2>/dev/null && fail "Esc did not quit the demo"
wait "$demo_pid" || fail "the demo exited with code $? after Esc: $(cat "$workdir/demo.log")"
echo "demo_smoke: 1 passed, 0 failed"
