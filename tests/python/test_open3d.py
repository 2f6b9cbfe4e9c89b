# SPDX-License-Identifier: GPL-3.0-or-later
"""Interop with a real library: Open3D (Debian's python3-open3d) before and after repair."""

import numpy as np
import pytest

import meshbridge
import mesh_models

o3d = pytest.importorskip("open3d")


def to_open3d(vertices, faces):
    mesh = o3d.geometry.TriangleMesh()
    mesh.vertices = o3d.utility.Vector3dVector(np.asarray(vertices, dtype=np.float64))
    mesh.triangles = o3d.utility.Vector3iVector(np.asarray(faces, dtype=np.int32))
    return mesh


def test_open3d_two_cubes_sharing_an_edge_become_edge_manifold():
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    before = to_open3d(vertices, faces)
    assert len(before.triangles) == 24 and len(before.vertices) == 14
    assert before.is_edge_manifold() is False
    assert len(before.get_non_manifold_edges()) == 1

    # Open3D's arrays straight into meshbridge and back.
    out_v, out_f, report = meshbridge.repair(np.asarray(before.vertices), np.asarray(before.triangles))
    after = to_open3d(out_v, out_f)
    print(f"Open3D before: {len(before.vertices)} v, {len(before.triangles)} t, edge manifold "
          f"{before.is_edge_manifold()}, vertex manifold {before.is_vertex_manifold()}; after: "
          f"{len(after.vertices)} v, {len(after.triangles)} t, edge manifold "
          f"{after.is_edge_manifold()}, vertex manifold {after.is_vertex_manifold()}, watertight "
          f"{after.is_watertight()}")
    assert after.is_edge_manifold() is True
    assert after.is_vertex_manifold() is True
    assert len(after.triangles) == 24  # every triangle kept
    assert len(after.vertices) == 16
    assert report["faces_out"] == 24
    triangle_clusters, cluster_sizes, _ = after.cluster_connected_triangles()
    assert sorted(np.asarray(cluster_sizes).tolist()) == [12, 12]
    assert after.is_orientable()


def test_open3d_checkerboard_every_cube_separate():
    vertices, faces = mesh_models.checkerboard(5)
    mesh = to_open3d(vertices, faces)
    assert mesh.is_edge_manifold() is False
    out_v, out_f, _ = meshbridge.repair(vertices, faces)
    after = to_open3d(out_v, out_f)
    # (Open3D's is_watertight() also asks for no self-intersection, and the repaired cubes still
    # touch along their former shared edges, so it stays False here by design.)
    assert after.is_edge_manifold() and after.is_vertex_manifold()
    _, sizes, _ = after.cluster_connected_triangles()
    assert len(after.triangles) == len(faces)
    assert np.asarray(sizes).tolist() == [12] * (len(faces) // 12)
