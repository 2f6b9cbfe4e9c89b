# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes built in code for the Python tests and benchmarks (numpy only)."""

import numpy as np

# Unit cube corners c = (c&1, (c>>1)&1, (c>>2)&1); 12 outward triangles.
CUBE_TRIANGLES = np.array(
    [
        [0, 2, 3], [0, 3, 1],  # z = 0, normal -z
        [4, 5, 7], [4, 7, 6],  # z = 1, +z
        [0, 1, 5], [0, 5, 4],  # y = 0, -y
        [2, 6, 7], [2, 7, 3],  # y = 1, +y
        [0, 4, 6], [0, 6, 2],  # x = 0, -x
        [1, 3, 7], [1, 7, 5],  # x = 1, +x
    ],
    dtype=np.int64,
)
CUBE_CORNERS = np.array([[c & 1, (c >> 1) & 1, (c >> 2) & 1] for c in range(8)], dtype=np.float64)


def cubes(offsets):
    """Closed unit cubes at integer `offsets` (k, 3), welded by position: (vertices, faces)."""
    offsets = np.asarray(offsets, dtype=np.int64)
    corners = (offsets[:, None, :] + CUBE_CORNERS.astype(np.int64)[None, :, :]).reshape(-1, 3)
    unique, inverse = np.unique(corners, axis=0, return_inverse=True)
    inverse = inverse.reshape(-1)
    faces = (CUBE_TRIANGLES[None, :, :] + 8 * np.arange(len(offsets))[:, None, None]).reshape(-1, 3)
    return unique.astype(np.float64), inverse[faces].astype(np.int64)


def two_cubes_sharing_an_edge():
    """14 vertices, 24 triangles, one edge with 4 faces (DESIGN section 1)."""
    return cubes([[0, 0, 0], [1, 1, 0]])


def checkerboard(n):
    """3D checkerboard of ceil(n^3 / 2) unit cubes touching along edges (every shared edge has 4
    faces). Correct repair: 8 vertices and 12 faces per cube, every cube closed and separate."""
    i, j, k = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    cells = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1)
    return cubes(cells[cells.sum(axis=1) % 2 == 0])


def write_obj(path, vertices, faces):
    """A plain OBJ with coordinates that read back bit-identical."""
    with open(path, "w") as out:
        out.write("".join("v %.17g %.17g %.17g\n" % tuple(p) for p in vertices))
        out.write("".join("f " + " ".join(str(int(i) + 1) for i in face) + "\n" for face in faces))
