# SPDX-License-Identifier: GPL-3.0-or-later
# Self-intersection models for the MeshLab runners (tests/meshlab for 2020.09, tests/meshlab2025
# for 2025.07): two closed cubes whose shells cross, as triangles, so MeshLab's faces are the
# file's and every count can be compared exactly with the core's (`mlcheck report`).

# write_crossing_cubes FILE [SHIFT]: the unit cube [0,1]^3 and the same cube moved by SHIFT
# (default 0.5) along x, y and z, 12 outward triangles each (24 faces, 16 vertices, no shared
# vertex). With SHIFT 0.5 their shells cross; with SHIFT 2 they lie apart.
write_crossing_cubes() {
  awk -v shift="${2:-0.5}" 'BEGIN {
    print "OFF"; print "16 24 0"
    for (copy = 0; copy < 2; ++copy)
      for (i = 0; i < 8; ++i) {
        d = copy ? shift : 0
        printf "%.17g %.17g %.17g\n", (i % 2) + d, (int(i / 2) % 2) + d, int(i / 4) + d
      }
    split("0 4 6 2|0 1 5 4|0 2 3 1|1 3 7 5|2 6 7 3|4 5 7 6", quads, "|")
    for (copy = 0; copy < 2; ++copy)
      for (q = 1; q <= 6; ++q) {
        split(quads[q], c, " ")
        base = 8 * copy
        printf "3 %d %d %d\n", base + c[1], base + c[2], base + c[3]
        printf "3 %d %d %d\n", base + c[1], base + c[3], base + c[4]
      }
  }' >"$1"
}
