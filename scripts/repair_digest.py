#!/usr/bin/env python3
"""One digest of what meshbridge.repair() makes of many inputs under many options: the repaired
vertices and polygons, the three origin maps, and the report (counts and element lists). A
refactoring that must keep outputs bit-identical (issue 32) prints the same digest before and
after.

usage: PYTHONPATH=<build>/python python3 scripts/repair_digest.py [-v] [--drop-key KEY]...
       FILE_OR_FOLDER...

Folders are searched for .obj .off .ply .stl .3mf files (sorted). Each file is read once and
repaired under every option set of OPTION_SETS; -v prints one digest per file and option set.
--drop-key KEY leaves the report's top-level KEY out of the digest (to compare builds across a
change that only adds a report key; the meshes and origin maps still count whole).
"""

import hashlib
import json
import sys
import warnings
from pathlib import Path

import numpy as np

import meshbridge

SUFFIXES = {".obj", ".off", ".ply", ".stl", ".3mf"}
OPTION_SETS = [
    {},
    {"detect_before_after": False},
    {"remove_duplicate_faces": True, "remove_degenerate_faces": True,
     "remove_isolated_vertices": True},
    {"remove_zero_area_faces": True, "nested_shells": "cavity"},
    {"fill_holes": 32},
    {"weld": 0, "close_t_junctions": False},
    {"pairing": "combinatorial"},
    {"orient": False, "stitch": False},
    {"cut_nonorientable": True},
]


def inputs(arguments):
    for argument in arguments:
        path = Path(argument)
        if path.is_dir():
            yield from sorted(p for p in path.rglob("*") if p.suffix.lower() in SUFFIXES)
        else:
            yield path


def digest_of(result, dropped=()):
    vertices, faces, report = result
    report = {k: v for k, v in report.items() if k not in dropped}
    h = hashlib.sha256()
    h.update(np.ascontiguousarray(vertices, dtype=np.float64).tobytes())
    if isinstance(faces, list):
        h.update(json.dumps(faces).encode())
    else:
        h.update(np.ascontiguousarray(faces, dtype=np.int64).tobytes())
    for origin in (result.vertex_origin, result.face_origin, result.corner_origin):
        h.update(np.ascontiguousarray(origin, dtype=np.int64).tobytes())
    h.update(json.dumps(report, sort_keys=True).encode())
    return h.hexdigest()


def main(argv):
    verbose = "-v" in argv
    dropped = {argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--drop-key"}
    paths = [a for i, a in enumerate(argv)
             if a not in ("-v", "--drop-key") and (i == 0 or argv[i - 1] != "--drop-key")]
    total = hashlib.sha256()
    runs = 0
    for path in inputs(paths):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                soup = meshbridge.read(path)
            except (meshbridge.ReadError, meshbridge.InvalidMeshError) as error:
                total.update(str(error).encode())  # unreadable: its message counts
                continue
        for options in OPTION_SETS:
            try:
                d = digest_of(meshbridge.repair(soup, elements=True, **options), dropped)
            except meshbridge.InvalidMeshError as error:
                d = hashlib.sha256(str(error).encode()).hexdigest()
            total.update(d.encode())
            runs += 1
            if verbose:
                print(d[:16], path, json.dumps(options, sort_keys=True))
    print(f"{total.hexdigest()}  ({runs} repairs)")


if __name__ == "__main__":
    main(sys.argv[1:])
