# SPDX-License-Identifier: GPL-3.0-or-later
"""MeshLab's own non-manifold repairs against ours, through the real pymeshlab, in one run.

Each (file, method) runs in a process of its own (a MeshLab assertion aborts the process; it is
reported in the cell): the file is loaded (not timed), the filter call alone is timed, then the
mesh pymeshlab holds is counted by meshbridge.check on its arrays (MeshLab's own
get_topological_measures aborts on some inputs with an assertion, edgeNonManifFFNum ==
edgeNonManifNum). Methods:

  edges/remove   meshing_repair_non_manifold_edges(method=0, 'Remove Faces')
  edges/split    meshing_repair_non_manifold_edges(method=1, 'Split Vertices')
  vertices       meshing_repair_non_manifold_vertices()
  MeshBridge     meshing_repair_singular_defects_bridged() (defaults)

Prints a per-file markdown table (faces kept, components, boundary edges, singular edges and
vertices left, time) and a summary by method. Run by scripts/pymeshlab_compare.sh inside the sid
root (PYTHONPATH with pymeshlab and meshbridge, MESHBRIDGE_PLUGIN).

Usage: python3 pymeshlab_compare.py FILE... """

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pymeshlab

METHODS = [
    ("MeshLab edges, remove faces", "meshing_repair_non_manifold_edges", {"method": 0}),
    ("MeshLab edges, split vertices", "meshing_repair_non_manifold_edges", {"method": 1}),
    ("MeshLab vertices", "meshing_repair_non_manifold_vertices", {}),
    ("MeshBridge", "meshing_repair_singular_defects_bridged", {}),
]


def measure(ms):
    import meshbridge

    m = ms.current_mesh()
    c = meshbridge.check(m.vertex_matrix().astype("float64"), m.face_matrix())
    return {"faces": m.face_number(), "components": c["components"],
            "boundary_edges": c["boundary_edges"], "nm_edges": c["singular_edges"],
            "nm_vertices": c["singular_vertices"]}


def one(method, path):
    """Runs one method on one file in this process; prints the counts as JSON."""
    pymeshlab.load_plugin(os.environ["MESHBRIDGE_PLUGIN"])
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(path))
    if method < 0:
        print(json.dumps(measure(ms)))
        return
    _, filter_name, params = METHODS[method]
    start = time.perf_counter()
    ms.apply_filter(filter_name, **params)
    seconds = time.perf_counter() - start
    print(json.dumps({**measure(ms), "ms": seconds * 1000}))


def run(method, path):
    p = subprocess.run([sys.executable, __file__, "--one", str(method), str(path)],
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        why = lines[-1] if lines else f"exit {p.returncode}"
        if "Assertion" in p.stderr:
            why = "MeshLab aborts: " + p.stderr.split("Assertion", 1)[1].split("'")[1]
        return {"error": why[:80]}
    return json.loads(p.stdout.splitlines()[-1])


def main(files):
    rows, skipped = [], []
    for path in files:
        before = run(-1, path)
        if "error" in before:
            skipped.append(f"{path.name} ({before['error']})")
            continue
        rows.append((path, before, [run(i, path) for i in range(len(METHODS))]))

    print("| file | faces | comp. | bnd. | singular e/v | " +
          " | ".join(name for name, _, _ in METHODS) + " |")
    print("|---|---:|---:|---:|---:|" + "---|" * len(METHODS))
    for path, before, results in rows:
        cells = []
        for r in results:
            if "error" in r:
                cells.append("error: " + r["error"])
                continue
            kept = 100.0 * r["faces"] / before["faces"] if before["faces"] else 0
            cells.append(f"{r['faces']} ({kept:.0f}%), {r['components']} comp., "
                         f"{r['boundary_edges']} bnd., {r['nm_edges']}/{r['nm_vertices']} sing., "
                         f"{r['ms']:.0f} ms")
        print(f"| {path.name} | {before['faces']} | {before['components']} | "
              f"{before['boundary_edges']} | {before['nm_edges']}/{before['nm_vertices']} | " +
              " | ".join(cells) + " |")

    print()
    print(f"Summary over {len(rows)} files ({sum(b['faces'] for _, b, _ in rows)} faces, "
          f"{sum(b['components'] for _, b, _ in rows)} components, "
          f"{sum(b['boundary_edges'] for _, b, _ in rows)} boundary edges, "
          f"{sum(1 for _, b, _ in rows if b['nm_edges'] or b['nm_vertices'])} files with "
          "singular edges or vertices in):")
    print()
    print("| method | faces kept | files left with singular edges/vertices | components | boundary edges | time |")
    print("|---|---:|---:|---:|---:|---:|")
    total_in = sum(b["faces"] for _, b, _ in rows)
    for i, (name, _, _) in enumerate(METHODS):
        done = [res[i] for _, _, res in rows if "error" not in res[i]]
        faces = sum(r["faces"] for r in done)
        left = sum(1 for r in done if r["nm_edges"] or r["nm_vertices"])
        errors = len(rows) - len(done)
        print(f"| {name} | {faces} ({100.0 * faces / total_in:.1f}%) | {left}"
              f"{f' (+{errors} errors)' if errors else ''} | "
              f"{sum(r['components'] for r in done)} | {sum(r['boundary_edges'] for r in done)} | "
              f"{sum(r['ms'] for r in done) / 1000:.2f} s |")
    if skipped:
        print()
        print("Not loaded by this MeshLab: " + ", ".join(skipped))


if __name__ == "__main__":
    if sys.argv[1:2] == ["--one"]:
        one(int(sys.argv[2]), Path(sys.argv[3]))
    else:
        main([Path(p) for p in sys.argv[1:]])
