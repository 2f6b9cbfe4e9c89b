# SPDX-License-Identifier: GPL-3.0-or-later
# Checks shared by the MeshLab integration runners (tests/meshlab for 2020.09 through
# meshlabserver, tests/meshlab2025 for 2025.07 through the headless runner). Sourced; needs
# MLCHECK and, for input_off, `model`. Counts failures in `failures`.

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok:   $*"; }
# value KEY FILE: the value of KEY=... in a key=value file (empty if missing)
value() { sed -n "s/^$1=//p" "$2" | tail -n1; }
expect_eq() {  # expect_eq WHAT ACTUAL EXPECTED
  if [ "$2" = "$3" ]; then pass "$1 = $2"; else fail "$1 = '$2', expected '$3'"; fi
}
input_off() {  # MODEL as in.off (Debian's meshlabserver 2020.09 aborts on any OBJ input)
  [ -f "$model" ] || { echo "no model $model"; exit 1; }
  "$MLCHECK" to-off "$model" in.off
}
check_expectations() {  # check_expectations REPORT k=v...
  local report=$1; shift
  local kv
  for kv in "$@"; do
    expect_eq "${kv%%=*}" "$(value "${kv%%=*}" "$report")" "${kv#*=}"
  done
}
expect_attributes_kept_and_manifold() {  # IN OUT: OUT has IN's attributes and no singular element
  "$MLCHECK" same-attributes "$1" "$2" >same.txt || true
  cat same.txt
  expect_eq "attribute mismatches" "$(value mismatches same.txt)" 0
  "$MLCHECK" report "$2" >output.txt
  expect_eq "core: singular edges after" "$(value singular_edges output.txt)" 0
  expect_eq "core: singular vertices after" "$(value singular_vertices output.txt)" 0
}
finish_checks() {  # DIR: exit 1 naming DIR if any check failed
  if [ "$failures" -ne 0 ]; then
    echo "$failures check(s) failed; files in $1"
    exit 1
  fi
}
