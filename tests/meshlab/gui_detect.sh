#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Drives the real MeshLab GUI the way a user does and takes a screenshot of its 3D view: starts
# its own Xvfb (so it also works inside a chroot, where xvfb-run's cookie file is out of reach),
# starts MeshLab on MODEL with fresh (default) settings, opens Filters' search (Ctrl+F), types the
# filter's name, opens it, presses Apply, closes the dialog, waits for MeshLab's log line and a
# stable picture, and grabs the screen. Used by the real-GUI tests of MeshLab 2020.09
# (tests/meshlab) and 2025.07 (tests/meshlab2025, inside the sid root) and by
# scripts/meshlab_screenshot.sh.
#
# Every step waits for a condition (a window, a log line, two equal screenshots in a row), with
# a time limit; no step sleeps blindly. A session that fails is tried once more.
#
# Usage: gui_detect.sh MESHLAB MODEL OUT_DIR [FILTER]
#   MESHLAB  the GUI binary (in a private root that holds our plugin)
#   MODEL    the file MeshLab opens (as `meshlab MODEL`)
#   OUT_DIR  receives: screen.png (whole screen), view.png (the 3D view), view.txt (its red and
#            green pixels, from COUNT_PIXELS), meshlab.log (MeshLab's stderr, where every log
#            entry also arrives as "LOG: <level> <text>"), session.txt (the steps)
#   FILTER   the filter's menu name (default "Detect Singular Defects (Bridged Half-Edge)")
# Environment: COUNT_PIXELS (meshbridge_count_pixels, required), SIZE (screen, default
#   1400x1100: a 3D view about 1000 pixels square), DRAG (optional "DX DY": after the filter,
#   drag the view by DX, DY pixels with the left button, i.e. turn the model as a user does),
#   ZOOM (optional N: then turn the mouse wheel N steps forward at the view's centre, i.e. zoom
#   in towards it; MeshLab's info panel shows the new field of view).
set -uo pipefail

meshlab=${1:?meshlab binary}
model=${2:?model}
out=${3:?output dir}
filter=${4:-Detect Singular Defects (Bridged Half-Edge)}
: "${COUNT_PIXELS:?COUNT_PIXELS (meshbridge_count_pixels) is required}"
size=${SIZE:-1400x1100}
width=${size%x*}
height=${size#*x}
mkdir -p "$out"
out=$(cd "$out" && pwd)
log="$out/meshlab.log"
steps="$out/session.txt"

say() { echo "$*" | tee -a "$steps" >&2; }
# wait_for SECONDS COMMAND...: runs COMMAND every 0.1 s until it succeeds; fails after SECONDS.
wait_for() {
  local limit=$1 t=0
  shift
  until "$@" >/dev/null 2>&1; do
    t=$((t + 1))
    [ "$t" -le $((limit * 10)) ] || return 1
    sleep 0.1
  done
}
log_has() { grep -q -- "$1" "$log"; }
window_gone() { ! xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; }

xvfb_pid=
meshlab_pid=
stop() {
  [ -n "$meshlab_pid" ] && kill "$meshlab_pid" 2>/dev/null && wait "$meshlab_pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  meshlab_pid=
  xvfb_pid=
}
trap stop EXIT

# The largest window inside MeshLab's main window that is smaller than it: the 3D view (its
# MDI area). Prints "X Y W H".
view_rectangle() {
  xwininfo -tree -id "$1" | awk -v W="$width" -v H="$height" '
    match($0, /[0-9]+x[0-9]+\+-?[0-9]+\+-?[0-9]+ +\+-?[0-9]+\+-?[0-9]+$/) {
      n = split(substr($0, RSTART, RLENGTH), f, /[x+ ]+/)
      w = f[1]; h = f[2]; x = f[5]; y = f[6]
      if (w * h > best && (w < W || h < H) && w > 200 && h > 200) { best = w * h; r = x " " y " " w " " h }
    }
    END { if (r == "") exit 1; print r }'
}

session() {
  : >"$log"
  local display_file
  display_file=$(mktemp)
  # -displayfd: the server picks a free display number and writes it when it is ready.
  Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp 3>"$display_file" >"$out/xvfb.log" 2>&1 &
  xvfb_pid=$!
  wait_for 20 test -s "$display_file" || { say "Xvfb did not start"; return 1; }
  export DISPLAY=":$(head -n1 "$display_file")"
  rm -f "$display_file"
  say "Xvfb on $DISPLAY"

  # Fresh settings: MeshLab's defaults, nothing from an earlier run.
  local config
  config=$(mktemp -d)
  XDG_CONFIG_HOME="$config" "$meshlab" "$model" >"$out/meshlab.stdout" 2>"$log" &
  meshlab_pid=$!
  local wid=
  main_window() {
    kill -0 "$meshlab_pid" 2>/dev/null || return 2
    wid=$(xdotool search --onlyvisible --name "^MeshLab [0-9]" 2>/dev/null | head -n1)
    [ -n "$wid" ]
  }
  local t=0
  until main_window; do
    kill -0 "$meshlab_pid" 2>/dev/null || { say "MeshLab exited"; return 1; }
    t=$((t + 1))
    [ "$t" -le 600 ] || { say "no MeshLab main window"; return 1; }
    sleep 0.1
  done
  xdotool windowmove "$wid" 0 0 windowsize --sync "$wid" "$width" "$height"
  wait_for 60 log_has "Opened mesh" || { say "MeshLab did not log 'Opened mesh'"; return 1; }
  say "MeshLab window $wid, $(basename "$model") opened"

  # Filters' search box: type the name, take the match, and the filter's dialog opens.
  local dialog=
  for _ in 1 2; do
    xdotool windowactivate --sync "$wid" >/dev/null 2>&1 || xdotool windowfocus --sync "$wid"
    xdotool key --clearmodifiers ctrl+f
    xdotool type --delay 15 "$filter"
    xdotool key Down Return
    dialog=$(timeout 15 xdotool search --sync --onlyvisible --name "^${filter//[()]/.}\$" | head -n1)
    [ -n "$dialog" ] && break
    xdotool key Escape
  done
  [ -n "$dialog" ] || { say "the filter's dialog did not open"; return 1; }
  local X Y WIDTH HEIGHT SCREEN
  eval "$(xdotool getwindowgeometry --shell "$dialog")"
  say "dialog $dialog at ${X},${Y} ${WIDTH}x${HEIGHT}: Apply"
  # Apply is the bottom-right button, Close the bottom-left one (both MeshLab versions).
  xdotool mousemove $((X + WIDTH * 3 / 4)) $((Y + HEIGHT - 14)) click 1
  wait_for 60 log_has "LOG: [0-9]* Applied filter:\\? $filter" \
    || { say "no 'Applied filter' in MeshLab's log"; return 1; }
  xdotool mousemove $((X + WIDTH / 4)) $((Y + HEIGHT - 14)) click 1
  wait_for 15 window_gone "^${filter//[()]/.}\$" || { say "the dialog did not close"; return 1; }
  say "filter applied, dialog closed"

  local view
  view=$(view_rectangle "$wid") || { say "no 3D view found in the window tree"; return 1; }
  read -r vx vy vw vh <<<"$view"
  if [ -n "${DRAG:-}" ]; then
    read -r dx dy <<<"$DRAG"
    local cx=$((vx + vw / 2)) cy=$((vy + vh / 2))
    xdotool mousemove "$cx" "$cy" mousedown 1 mousemove $((cx + dx / 2)) $((cy + dy / 2)) \
      mousemove $((cx + dx)) $((cy + dy)) mouseup 1
  fi
  if [ -n "${ZOOM:-}" ]; then
    xdotool mousemove $((vx + vw / 2)) $((vy + vh / 2))
    for _ in $(seq 1 "$ZOOM"); do xdotool click 5; done
  fi
  # Park the pointer outside the view (the status bar), then wait for a stable picture.
  xdotool mousemove $((width - 5)) $((height - 5))
  local previous="$out/previous.ppm" current="$out/current.ppm" stable=0
  for _ in $(seq 1 40); do
    /usr/bin/import -window root -depth 8 "ppm:$current" || { say "import failed"; return 1; }
    if [ -f "$previous" ] && cmp -s "$previous" "$current"; then
      stable=1
      break
    fi
    mv -f "$current" "$previous"
    sleep 0.25
  done
  [ "$stable" = 1 ] || { say "the picture did not settle"; return 1; }
  say "3D view $vw x $vh at $vx,$vy"
  "$COUNT_PIXELS" "$current" "$vx" "$vy" "$vw" "$vh" >"$out/view.txt" || return 1
  /usr/bin/convert "$current" "$out/screen.png"
  /usr/bin/convert "$current" -crop "${vw}x${vh}+${vx}+${vy}" +repage "$out/view.png"
  rm -f "$previous" "$current"
  rm -rf "$config"
  stop
  return 0
}

: >"$steps"
for attempt in 1 2; do
  say "session $attempt"
  if session; then
    cat "$out/view.txt"
    exit 0
  fi
  stop
done
say "MeshLab GUI session failed twice; MeshLab's log:"
tail -n 30 "$log" >&2
exit 1
