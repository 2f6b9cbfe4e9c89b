#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The monotone invariant of a repair (DESIGN 8a, no new defects) over folders of real meshes.

For every mesh found recursively (.obj .off .ply .stl .3mf, any case), runs
`meshbridge repair FILE OUT.ply --report R.json --elements` with default options and compares
the report's `before` and `after`: a file is *worse* when the output has more boundary edges than
the input plus one per singular edge with an odd number of faces, more non-orientable components,
or any side cut to stay manifold; a closed input (0 boundary edges) that comes out with boundary
edges is *opened*. Prints one line per worse file and a summary line; exit 0 always (a survey,
not a test: tests/unit/corpus_invariant_test.cpp is the test).

Usage: scripts/corpus_monotone.py MESHBRIDGE DIR... [--timeout S]
"""
import json
import os
import subprocess
import sys
import tempfile

EXTENSIONS = {".obj", ".off", ".ply", ".stl", ".3mf"}


def meshes(folders):
    for folder in folders:
        for base, _, names in os.walk(folder):
            for name in sorted(names):
                if os.path.splitext(name)[1].lower() in EXTENSIONS:
                    yield os.path.join(base, name)


def main(argv):
    timeout = 120.0
    if "--timeout" in argv:
        i = argv.index("--timeout")
        timeout = float(argv[i + 1])
        del argv[i : i + 2]
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    tool, folders = argv[1], argv[2:]
    counts = {"files": 0, "repaired": 0, "failed": 0, "worse": 0, "opened": 0, "cut": 0}
    with tempfile.TemporaryDirectory() as work:
        out, report = os.path.join(work, "out.ply"), os.path.join(work, "r.json")
        for path in meshes(folders):
            counts["files"] += 1
            try:
                done = subprocess.run(
                    [tool, "repair", path, out, "--report", report, "--elements"],
                    capture_output=True, timeout=timeout)
            except subprocess.TimeoutExpired:
                counts["failed"] += 1
                print(f"timeout  {path}")
                continue
            if done.returncode != 0:
                counts["failed"] += 1
                continue
            counts["repaired"] += 1
            with open(report) as f:
                r = json.load(f)
            before, after = r["before"], r["after"]
            odd = sum(1 for e in before["elements"]["singular_edges"] if e["contenders"] % 2 == 1)
            grew = after["boundary_edges"] > before["boundary_edges"] + odd
            nonorientable = after["nonorientable_components"] > before["nonorientable_components"]
            cut = r["sides_cut_to_stay_manifold"] > 0
            opened = before["boundary_edges"] == 0 and after["boundary_edges"] > 0
            counts["cut"] += cut
            counts["opened"] += opened
            if opened:
                print(f"opened   {path}: boundary 0 -> {after['boundary_edges']} "
                      f"(odd singular edges {odd})")
            if grew or nonorientable or cut:
                counts["worse"] += 1
                print(f"worse    {path}: boundary {before['boundary_edges']} -> "
                      f"{after['boundary_edges']} (odd singular edges {odd}), non-orientable "
                      f"{before['nonorientable_components']} -> "
                      f"{after['nonorientable_components']}, cut to stay manifold "
                      f"{r['sides_cut_to_stay_manifold']}")
    print("summary: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
