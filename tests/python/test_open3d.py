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


def test_open3d_reads_the_obj_colors_meshbridge_writes(tmp_path):
    """OBJ vertex colours are written as "v x y z r g b" unless some alpha carries information:
    Open3D 0.16 reads "v x y z r g b a" as 0 points."""
    import os
    import subprocess

    cli = os.environ.get("MESHBRIDGE_CLI", "")
    if not cli:
        pytest.skip("MESHBRIDGE_CLI not set: no CLI to write the OBJ")
    (tmp_path / "c.ply").write_text(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
        "property uchar alpha\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n")
    result = subprocess.run([cli, "repair", tmp_path / "c.ply", tmp_path / "c.obj"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    mesh = o3d.io.read_triangle_mesh(str(tmp_path / "c.obj"))
    assert len(mesh.vertices) == 3 and len(mesh.triangles) == 1
    assert mesh.has_vertex_colors()
    assert np.allclose(np.asarray(mesh.vertex_colors), np.eye(3))


def test_open3d_reads_the_texture_coordinates_of_a_repaired_obj(tmp_path):
    """Two textured cubes on one edge (every corner its own vt, a vn per side of a cube),
    repaired OBJ to OBJ: Open3D reads a uv for every triangle corner, and exactly the input's."""
    import os
    import subprocess

    cli = os.environ.get("MESHBRIDGE_CLI", "")
    if not cli:
        pytest.skip("MESHBRIDGE_CLI not set: no CLI to repair the OBJ")
    sides = [[(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)], [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)],
             [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)], [(0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)],
             [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)], [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]]
    normals = [(-1, 0, 0), (1, 0, 0), (0, -1, 0), (0, 1, 0), (0, 0, -1), (0, 0, 1)]
    index, v, vt, f, given = {}, [], [], [], set()
    for offset in [(0, 0, 0), (1, 1, 0)]:
        for side, corners in enumerate(sides):
            # Triangles (Open3D 0.16 skips OBJ polygons of more corners), each corner its own vt.
            for triangle in ((0, 1, 2), (0, 2, 3)):
                face = []
                for k in triangle:
                    p = tuple(o + c for o, c in zip(offset, corners[k]))
                    if p not in index:
                        index[p] = len(index) + 1
                        v.append("v %d %d %d" % p)
                    uv = (len(vt) / 128.0, 1 - len(vt) / 128.0)
                    given.add((tuple(float(x) for x in p), uv))
                    vt.append("vt %s %s" % uv)
                    face.append("%d/%d/%d" % (index[p], len(vt), side + 1))
                f.append("f " + " ".join(face))
    text = "\n".join(v + vt + ["vn %d %d %d" % n for n in normals] + f) + "\n"
    (tmp_path / "cubes.obj").write_text(text)
    result = subprocess.run([cli, "repair", tmp_path / "cubes.obj", tmp_path / "out.obj"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "not written" not in result.stderr, result.stderr
    mesh = o3d.io.read_triangle_mesh(str(tmp_path / "out.obj"))
    # (Open3D gives every corner with a uv of its own a point of its own: 72 points.)
    assert len(mesh.triangles) == 24
    assert mesh.has_triangle_uvs() and mesh.has_vertex_normals()
    uvs = np.asarray(mesh.triangle_uvs)
    assert uvs.shape == (72, 2)
    # Every corner Open3D read is one of the input's (position, uv), and all 72 are there.
    points = np.asarray(mesh.vertices)
    read = {(tuple(points[t[k]].tolist()), tuple(uvs[3 * i + k].tolist()))
            for i, t in enumerate(np.asarray(mesh.triangles)) for k in range(3)}
    assert read == given, sorted(read ^ given)[:4]
