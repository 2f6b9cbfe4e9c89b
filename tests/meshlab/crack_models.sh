# SPDX-License-Identifier: GPL-3.0-or-later
# The crack models of tests/unit/close_gaps_test.cpp, written as files for the MeshLab runners
# (tests/meshlab for 2020.09, tests/meshlab2025 for 2025.07), and the log lines both runners
# check on them. Sourced after check_helpers.sh (expect_eq, pass, fail).
#
# Debian's meshlabserver 2020.09 aborts on OBJ input: the models are OFF, or STL written from OFF.

# write_cube_twice FILE OFFSET: a 10 mm cube at 100 mm from the origin, 12 triangles, whose -x,
# -y, -z sides use vertices 0..7 and whose +x, +y, +z sides use 8..15, the same corners moved by
# (OFFSET, -OFFSET, OFFSET). 6 corners are on both kinds of side; 7 and 8 are isolated.
write_cube_twice() {
  awk -v off="$2" 'BEGIN {
    print "OFF"; print "16 12 0"
    for (copy = 0; copy < 2; ++copy)
      for (i = 0; i < 8; ++i) {
        d = copy ? off : 0
        printf "%.17g %.17g %.17g\n", 100 + 10 * (i % 2) + d, 100 + 10 * (int(i / 2) % 2) - d, \
          100 + 10 * int(i / 4) + d
      }
    split("0 4 6 2|0 1 5 4|0 2 3 1|1 3 7 5|2 6 7 3|4 5 7 6", quads, "|")
    for (q = 1; q <= 6; ++q) {
      split(quads[q], c, " ")
      base = q <= 3 ? 0 : 8
      printf "3 %d %d %d\n", base + c[1], base + c[2], base + c[3]
      printf "3 %d %d %d\n", base + c[1], base + c[3], base + c[4]
    }
  }' >"$1"
}

# write_t_junction_box FILE: the box [0,2]x[0,1]x[0,1] of 7 quads, outward; its top is two quads
# meeting at x = 1 (vertices 8 and 9), its front and back one quad each, so 8 and 9 lie on their
# top sides (two T-junction cracks, 6 boundary edges).
write_t_junction_box() {
  cat >"$1" <<'MODEL'
OFF
10 7 0
0 0 0
2 0 0
0 1 0
2 1 0
0 0 1
2 0 1
0 1 1
2 1 1
1 0 1
1 1 1
4 0 2 3 1
4 0 1 5 4
4 2 6 7 3
4 0 4 6 2
4 1 3 7 5
4 4 8 9 6
4 8 5 7 9
MODEL
}

# off_to_stl IN.off OUT.stl: ASCII STL of an OFF file (polygons fanned from their first corner,
# normals left 0: readers recompute them).
off_to_stl() {
  awk 'NR == 1 { next }
    !nv { nv = $1; nf = $2; next }
    v < nv { x[v] = $1; y[v] = $2; z[v] = $3; ++v; next }
    f < nf {
      for (i = 3; i <= $1; ++i) {
        print "  facet normal 0 0 0"; print "    outer loop"
        n = split($2 " " $(i) " " $(i + 1), t, " ")
        for (k = 1; k <= n; ++k) printf "      vertex %.9g %.9g %.9g\n", x[t[k]], y[t[k]], z[t[k]]
        print "    endloop"; print "  endfacet"
      }
      ++f
    }
    BEGIN { print "solid meshbridge" }
    END { print "endsolid meshbridge" }' "$1" >"$2"
}

# expect_in_log WHAT LOG TEXT: LOG holds TEXT (a fixed string) somewhere on one line
expect_in_log() {
  if grep -qF -- "$3" "$2"; then pass "$1: '$3'"; else fail "$1: no line with '$3' in $2"; fi
}
# expect_not_in_log WHAT LOG TEXT
expect_not_in_log() {
  if grep -qF -- "$3" "$2"; then fail "$1: unexpected '$3' in $2"; else pass "$1: no '$3'"; fi
}

# The gap closing lines of the cube written twice with one float32 step (2^-17) between copies
# (automatic tolerance (110 + 2^-17) / 2^21, the largest coordinate being a copy of corner 7;
# the largest move is sqrt(3) * 2^-17).
cube_detect_line="gaps (weld tolerance 5.24521e-05, automatic): Repair would weld 6 vertices (largest move 1.32145e-05, 0 refused: same polygon) and close 0 T-junction cracks (0 sides split)"
cube_repair_line="gaps (tolerance 5.24521e-05): 6 vertices welded (largest move 1.32145e-05, 0 refused: same polygon), 0 T-junctions closed (0 sides split)"
box_detect_line="gaps (weld tolerance 9.53674e-07, automatic): Repair would weld 0 vertices (largest move 0, 0 refused: same polygon) and close 2 T-junction cracks (2 sides split)"
box_repair_line="gaps (tolerance 9.53674e-07): 0 vertices welded (largest move 0, 0 refused: same polygon), 2 T-junctions closed (2 sides split)"

# write_open_boxes FILE: two open boxes for hole filling, 20 vertices, 13 quads, outward. The
# unit cube at the origin lacks its top (a hole of 4 edges); the box [3,5]x[0,1]x[0,1], whose
# bottom, front and back are two quads each, lacks its top too (a hole of 6 edges).
write_open_boxes() {
  awk 'BEGIN {
    print "OFF"; print "20 13 0"
    for (i = 0; i < 8; ++i) printf "%d %d %d\n", i % 2, int(i / 2) % 2, int(i / 4)
    for (z = 0; z < 2; ++z) for (y = 0; y < 2; ++y) for (x = 0; x < 3; ++x)
      printf "%d %d %d\n", 3 + x, y, z
    print "4 0 4 6 2"; print "4 0 1 5 4"; print "4 0 2 3 1"; print "4 1 3 7 5"; print "4 2 6 7 3"
    for (i = 8; i < 10; ++i) {
      printf "4 %d %d %d %d\n", i, i + 3, i + 4, i + 1   # bottom
      printf "4 %d %d %d %d\n", i, i + 1, i + 7, i + 6   # front
      printf "4 %d %d %d %d\n", i + 3, i + 9, i + 10, i + 4   # back
    }
    print "4 8 14 17 11"; print "4 10 13 19 16"
  }' >"$1"
}
