# SPDX-License-Identifier: GPL-3.0-or-later
"""Python call overhead of meshbridge.repair against the C++ repair, side by side in one process.

    PYTHONPATH=build/release/python:tests/python python3 python/bench/call_overhead.py [N] [RUNS]

Input: the 3D checkerboard of cubes (N = 56: 87,808 cubes, 1,053,696 triangles) as numpy arrays
(float64 vertices, int64 faces). Each run times, alternately:
  C++     : repair() on a prepared soup, timed inside C++ (meshbridge._core._repair_seconds);
  Python  : meshbridge.repair(vertices, faces): numpy -> soup, repair, report JSON -> dict,
            result arrays (no copy);
with the default options (before/after detection on, as the CLI). Prints the best of RUNS for
each and the ratio Python / C++ (goal: < 1.10).
"""

import sys
import time

import numpy as np

import meshbridge
from meshbridge import _core

import mesh_models


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 56
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    vertices, faces = mesh_models.checkerboard(n)
    soup = meshbridge.Soup(vertices, faces)
    options = _core.RepairOptions()
    cpp, python = [], []
    for _ in range(runs):
        cpp.append(_core._repair_seconds(soup, options))
        start = time.perf_counter()
        result = meshbridge.repair(vertices, faces)
        python.append(time.perf_counter() - start)
        del result
    report = meshbridge.repair(vertices, faces).report
    assert report["vertices_out"] == 8 * (len(faces) // 12)
    print(f"checkerboard n={n}: {len(vertices):,} vertices, {len(faces):,} triangles; best of {runs}")
    print(f"| call | seconds |\n|---|---:|\n| C++ repair() | {min(cpp):.3f} |\n"
          f"| Python meshbridge.repair(vertices, faces) | {min(python):.3f} |")
    print(f"ratio Python / C++: {min(python) / min(cpp):.3f} (median {np.median(python) / np.median(cpp):.3f})")


if __name__ == "__main__":
    main()
