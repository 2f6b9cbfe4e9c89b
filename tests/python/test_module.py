# SPDX-License-Identifier: GPL-3.0-or-later
"""meshbridge on numpy arrays: read/write/check/repair, dtypes, provenance, errors, the GIL."""

import os
import sys
import threading
import warnings
from pathlib import Path

import numpy as np
import pytest

import meshbridge
import mesh_models

MODELS = Path(os.environ.get("MESHBRIDGE_SOURCE_DIR", Path(__file__).parents[2])) / "resources" / "models"
REALWORLD2 = MODELS.parents[1] / "tests" / "data" / "realworld2"


def manifold_edges(faces):
    """Every undirected edge of `faces` (list of polygons) -> number of sides on it."""
    counts = {}
    for polygon in faces:
        polygon = [int(v) for v in polygon]
        for a, b in zip(polygon, polygon[1:] + polygon[:1]):
            key = (min(a, b), max(a, b))
            counts[key] = counts.get(key, 0) + 1
    return counts


def assert_repair_invariants(result, faces_in):
    """Every face kept, every edge on at most 2 sides, no singular element left."""
    assert len(result.faces) == faces_in
    assert max(manifold_edges(result.faces).values()) <= 2
    after = meshbridge.check(result.vertices, result.faces)
    assert after["singular_edges"] == 0
    assert after["singular_vertices"] == 0
    assert len(result.face_origin) == len(result.faces)
    assert len(result.vertex_origin) == len(result.vertices)


# (model, vertices in, faces in, vertices out, components after, boundary edges after)
CANONICAL = [
    ("twocubes", 14, 24, 16, 2, 0),
    ("hourglass", 7, 8, 8, 2, 0),
    ("bowtie", 5, 2, 6, 2, 6),
    ("book_of_three", 5, 3, 7, 2, 7),
    ("plate_box_rib", 36, 72, 40, 2, 0),
    ("prisms24", 38, 120, 144, 24, 0),
]


@pytest.mark.parametrize("name,v_in,f_in,v_out,components,boundary", CANONICAL)
def test_repair_canonical_models_exact_counts(name, v_in, f_in, v_out, components, boundary):
    soup = meshbridge.read(MODELS / f"{name}.obj")
    assert (soup.num_vertices, soup.num_faces) == (v_in, f_in)
    result = meshbridge.repair(soup)
    report = result.report
    assert (report["vertices_in"], report["faces_in"]) == (v_in, f_in)
    assert (report["vertices_out"], report["faces_out"]) == (v_out, f_in)
    assert report["after"]["components"] == components
    assert report["after"]["boundary_edges"] == boundary
    assert report["after"]["singular_edges"] == report["after"]["singular_vertices"] == 0
    assert report["schema_version"] == 3 and report["kind"] == "repair"
    assert report["file"] == str(MODELS / f"{name}.obj")
    assert report["read"] == soup.read_info
    assert len(result.vertices) == v_out
    assert_repair_invariants(result, f_in)


def test_two_cubes_provenance_splits_exactly_the_shared_edge():
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    report = meshbridge.check(vertices, faces)
    assert report["singular_edges"] == 1 and report["singular_vertices"] == 2
    assert report["file"] == "" and "read" not in report and "elements" not in report
    result = meshbridge.repair(vertices, faces)
    out_v, out_f, rep = result  # unpacks as a 3-tuple
    assert out_v.shape == (16, 3) and out_v.dtype == np.float64
    assert out_f.shape == (24, 3) and out_f.dtype == np.int32
    assert rep["faces_out"] == 24 and rep["after"]["components"] == 2
    # Order preserved: face i of the output is face i of the input.
    np.testing.assert_array_equal(result.face_origin, np.arange(24))
    # 14 originals + one copy of each of the two shared vertices.
    assert result.vertex_origin.shape == (16,)
    np.testing.assert_array_equal(np.sort(result.vertex_origin[14:]), np.sort(
        np.array(sorted({int(a) for a in np.flatnonzero(np.bincount(faces[:12].ravel(), minlength=14) * np.bincount(faces[12:].ravel(), minlength=14))}))))
    # Every output vertex sits where its origin was, and every output face is its origin face
    # up to the vertex copies (and a flip, which repair counts).
    np.testing.assert_array_equal(out_v, vertices[result.vertex_origin])
    mapped = result.vertex_origin[out_f]
    for f in range(24):
        assert sorted(mapped[f]) == sorted(faces[f])
    assert result.corner_origin.shape == (72,)


@pytest.mark.parametrize("vdtype", [np.float64, np.float32, np.int32])
@pytest.mark.parametrize("fdtype", [np.int32, np.int64, np.uint32, np.uint64, np.int16])
def test_dtypes_give_identical_results(vdtype, fdtype):
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    reference = meshbridge.repair(vertices, faces)
    result = meshbridge.repair(vertices.astype(vdtype), faces.astype(fdtype))
    np.testing.assert_array_equal(result.vertices, reference.vertices)
    np.testing.assert_array_equal(result.faces, reference.faces)
    assert result.report == reference.report


def test_strided_and_fortran_arrays_are_read_in_place():
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    reference = meshbridge.repair(vertices, faces)
    wide = np.zeros((14, 6))
    wide[:, ::2] = vertices  # non-contiguous rows
    fortran = np.asfortranarray(faces.astype(np.int32))
    result = meshbridge.repair(wide[:, ::2], fortran)
    np.testing.assert_array_equal(result.faces, reference.faces)
    np.testing.assert_array_equal(result.vertices, reference.vertices)
    lists = meshbridge.repair(vertices.tolist(), faces.tolist())
    np.testing.assert_array_equal(lists.faces, reference.faces)


def test_polygons_of_mixed_arity():
    # A cube of 6 quads with one quad split into two triangles: 7 faces, 8 vertices.
    v = mesh_models.CUBE_CORNERS
    polygons = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7], [1, 7, 5]]
    report = meshbridge.check(v, polygons)
    assert report["faces"] == 7 and report["watertight"] is True
    result = meshbridge.repair(v, polygons)
    assert isinstance(result.faces, list)
    assert [len(p) for p in result.faces] == [4, 4, 4, 4, 4, 3, 3]
    quads = meshbridge.repair(v, np.array(polygons[:5], dtype=np.int64))
    assert quads.faces.shape == (5, 4)
    soup = meshbridge.Soup(v, polygons)
    np.testing.assert_array_equal(soup.face_begin, [0, 4, 8, 12, 16, 20, 23, 26])
    assert soup.corner_vertices.shape == (26,)


def test_read_write_round_trip(tmp_path):
    soup = meshbridge.read(MODELS / "twocubes.obj")
    assert soup.path.endswith("twocubes.obj")
    assert soup.read_info["declared_faces"] == 24
    assert soup.vertices.flags.writeable is False
    result = meshbridge.repair(soup)
    for ext in ("obj", "off", "ply"):
        out = tmp_path / f"out.{ext}"
        meshbridge.write(out, result)
        back = meshbridge.read(out)
        assert (back.num_vertices, back.num_faces) == (16, 24)
        assert meshbridge.check(back)["watertight"] is True
    meshbridge.write(str(tmp_path / "plain.off"), result.vertices, result.faces)
    assert meshbridge.read(tmp_path / "plain.off").num_faces == 24


def test_read_warns_about_records_not_kept_as_they_are(tmp_path):
    path = tmp_path / "pinched.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 1 4 5\nf 1 2\n")
    with pytest.warns(UserWarning, match=r"pinched.obj: 2 face records: 0 kept, 1 split"):
        soup = meshbridge.read(path)
    assert soup.reading.startswith("2 face records: 0 kept, 1 split (pinched")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a file read as it is: no warning
        assert meshbridge.read(MODELS / "twocubes.obj").reading is None
    # A record with no corner at all is in no soup, yet a face of the file set aside.
    bare = tmp_path / "bare.obj"
    bare.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf\n")
    with pytest.warns(UserWarning, match=r"1 without any corner"):
        soup = meshbridge.read(bare)
    report = meshbridge.check(soup)
    assert (report["faces"], report["faces_set_aside"], report["has_defects"]) == (2, 1, True)
    repaired = meshbridge.repair(soup).report
    assert (repaired["faces_in"], repaired["faces_set_aside"], repaired["faces_out"]) == (2, 1, 1)


def test_read_names_what_a_soup_does_not_hold(tmp_path):
    path = tmp_path / "coloured.obj"
    path.write_text(
        "mtllib a.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
        "g lid\nusemtl red\nf 1/1/1 2/1/1 3/1/1\n"
    )
    with pytest.warns(UserWarning, match=r"coloured.obj: a Soup holds positions and polygons"):
        soup = meshbridge.read(path)
    assert soup.not_held == [
        "vertex colours (2 vertices)",
        "OBJ groups and materials (2 o/g/usemtl lines, 1 mtllib line)",
        "1 texture coordinate (vt)",
        "1 normal (vn)",
    ]
    ply = tmp_path / "normals.ply"
    ply.write_text(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"
    )
    with pytest.warns(UserWarning, match=r"PLY vertex properties nx, ny, nz, on 3 vertices"):
        assert meshbridge.read(ply).not_held == ["PLY vertex properties nx, ny, nz, on 3 vertices"]
    import pickle

    assert pickle.loads(pickle.dumps(soup)).not_held == soup.not_held
    assert meshbridge.Soup(soup.vertices, soup.faces).not_held == []


def test_write_refuses_what_it_cannot_write_and_leaves_no_file(tmp_path):
    v = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    for name in ("a.stl", "a.obj", "a.ply", "a.off", "a.3mf"):
        with pytest.raises(meshbridge.InvalidMeshError, match=r"not written: face 0, corner 2"):
            meshbridge.write(tmp_path / name, v, [[0, 1, 1000000]])
    with pytest.raises(meshbridge.WriteError, match=r"vertex 0 has coordinate 1e\+300"):
        meshbridge.write(tmp_path / "huge.stl", [[1e300, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(meshbridge.WriteError, match=r"face 0 names a vertex twice"):
        meshbridge.write(tmp_path / "degenerate.3mf", v, [[0, 1, 1]])
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_stl_keeps_the_repair_by_moving_split_copies_apart(tmp_path):
    result = meshbridge.repair(meshbridge.read(MODELS / "twocubes.obj"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the default moves the copies: nothing to warn about
        written = meshbridge.write(tmp_path / "moved.stl", result)
    assert written["reread_singular_edges"] == 0 and written["reread_singular_vertices"] == 0
    assert written["copies_moved"] == 4  # the two vertices of the shared edge, two copies each
    assert 0 < written["separation"] < 1e-5  # a few float32 steps at the cubes' size (2)
    again = meshbridge.check(meshbridge.read(tmp_path / "moved.stl"))
    assert (again["singular_edges"], again["singular_vertices"], again["boundary_edges"]) == (0, 0, 0)
    assert again["components"] == 2


def test_stl_that_welds_the_repair_back_warns_with_counts(tmp_path):
    result = meshbridge.repair(meshbridge.read(MODELS / "twocubes.obj"))
    with pytest.warns(UserWarning, match=r"re-creates 1 singular edge and 2 singular vertices"):
        written = meshbridge.write(tmp_path / "out.stl", result, separate=False)
    assert written["copies_moved"] == 0
    assert meshbridge.check(meshbridge.read(tmp_path / "out.stl"))["singular_edges"] == 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a clean STL and other formats: no warning
        meshbridge.write(tmp_path / "out.ply", result)
        meshbridge.write(tmp_path / "ico.stl", meshbridge.read(MODELS / "icosphere.obj"))


def test_report_lists_on_request():
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    counts = meshbridge.check(vertices, faces)
    full = meshbridge.check(vertices, faces, elements=True)
    assert "elements" not in counts
    (shared,) = [edge for edge, sides in manifold_edges(faces).items() if sides == 4]
    assert full["elements"]["singular_edges"] == [{"vertices": list(shared), "contenders": 4}]
    assert {k: v for k, v in full.items() if k != "elements"} == counts
    repaired = meshbridge.repair(vertices, faces, elements=True).report
    assert repaired["before"]["elements"]["singular_edges"] == full["elements"]["singular_edges"]
    assert repaired["after"]["elements"]["singular_edges"] == []


def test_reports_equal_the_cli_json_key_for_key(tmp_path):
    """The dicts come from the core's report tree, not from text: they equal json.loads of what
    `meshbridge check --json` prints for the same file, key order included, the forecast of
    what repair would do (`gaps`, `repair`) too."""
    import json
    import subprocess

    cli = os.environ.get("MESHBRIDGE_CLI", "")
    if not cli:
        pytest.skip("MESHBRIDGE_CLI not set (the CLI is not built)")
    # Two cubes on one edge plus a third crossing the first: singular edges, crossings, a
    # non-ASCII file name.
    pair, pair_faces = mesh_models.two_cubes_sharing_an_edge()
    third, third_faces = mesh_models.cubes([(0, 0, 0)])
    vertices = np.vstack([pair, third + [0.5, 0.25, 0.25]])
    faces = np.vstack([pair_faces, third_faces + len(pair)])
    path = tmp_path / "würfel.obj"
    mesh_models.write_obj(path, vertices, faces)
    printed = subprocess.run([cli, "check", path, "--json", "--elements", "--self-intersections"],
                             capture_output=True, text=True, timeout=120)
    assert printed.returncode == 1, printed.stderr
    theirs = json.loads(printed.stdout)
    ours = meshbridge.check(meshbridge.read(path), elements=True, self_intersections=True)
    assert ours["repair"]["changes"] is True and "gaps" in ours
    assert ours == theirs
    assert list(ours) == list(theirs)
    assert ours["self_intersections"]["face_pairs"] > 0
    assert ours["file"] == str(path)
    repaired = meshbridge.repair(meshbridge.read(path)).report
    assert isinstance(repaired["before"]["singular_edges"], int)
    assert repaired["before"] == {k: v for k, v in theirs.items() if k in repaired["before"]}


@pytest.mark.parametrize(
    "faces,message",
    [
        (np.array([[0, 1, 99]]), "face 0, corner 2: vertex index 99 is out of range"),
        (np.array([[0, 1, 2**63]], dtype=np.uint64), "face 0, corner 2: vertex index 9223372036854775808 is out of range"),
        ([[0, 1, 2**70]], "face 0, corner 2: vertex index 1180591620717411303424 is out of range"),
        ([[0, 1, 2], [0, -1, 2]], "face 1, corner 1: vertex index -1 is negative"),
        (np.array([[0, 1, 2], [2, 1, -5]], dtype=np.int32), "face 1, corner 2: vertex index -5 is negative"),
        ([[0, 1, 2], [0, 1]], "face 1 has 2 corner(s)"),
        ([[0, 1, 2], [0, 1.5, 2]], "face 1, corner 1: expected an integer vertex index, got float"),
        ([[0, 1, 2], 7], "face 1: expected a sequence of vertex indices, got int"),
        (np.array([[0.0, 1.0, 2.0]]), "faces: expected integer vertex indices, got dtype float64"),
        (np.array([[0, 1]]), "faces must have shape (m, k) with k >= 3"),
        (np.array([0, 1, 2]), "got shape (3,)"),
    ],
)
def test_bad_faces_raise_naming_the_element(faces, message):
    vertices = np.zeros((4, 3))
    with pytest.raises(meshbridge.InvalidMeshError) as error:
        meshbridge.repair(vertices, faces)
    assert message in str(error.value)
    assert isinstance(error.value, ValueError)


def test_bad_vertices_raise_naming_the_element():
    faces = [[0, 1, 2]]
    with pytest.raises(meshbridge.InvalidMeshError, match=r"vertices must have shape \(n, 3\), got shape \(3, 2\)"):
        meshbridge.check(np.zeros((3, 2)), faces)
    bad = np.zeros((3, 3))
    bad[1, 2] = np.nan
    with pytest.raises(meshbridge.InvalidMeshError, match="vertex 1 has a non-finite coordinate"):
        meshbridge.repair(bad, faces)
    with pytest.raises(meshbridge.InvalidMeshError, match="got dtype <U1"):
        meshbridge.check(np.array([["a", "b", "c"]] * 3), faces)


def test_bad_options_and_files():
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    with pytest.raises(TypeError, match="unknown option 'orientt'"):
        meshbridge.repair(vertices, faces, orientt=False)
    with pytest.raises(ValueError, match="pairing must be"):
        meshbridge.repair(vertices, faces, pairing="random")
    combinatorial = meshbridge.repair(vertices, faces, pairing="combinatorial", stitch=False)
    assert combinatorial.report["faces_out"] == 24
    with pytest.raises(meshbridge.ReadError, match="missing.obj: cannot open"):
        meshbridge.read("missing.obj")
    with pytest.raises(TypeError, match="faces are missing"):
        meshbridge.check(vertices)


def test_write_keeps_a_non_manifold_mesh_as_it_is(tmp_path):
    # MeshBridge's own writers hold any soup (OpenMesh's refused the singular edge).
    out = tmp_path / "two_cubes.obj"
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    meshbridge.write(out, vertices, faces)
    back = meshbridge.read(out)
    np.testing.assert_array_equal(back.vertices, np.asarray(vertices, dtype=np.float64))
    np.testing.assert_array_equal(np.asarray(back.faces), np.asarray(faces))
    assert meshbridge.check(back.vertices, back.faces)["singular_edges"] == 1


def test_failed_write_names_the_file_and_leaves_the_old_one(tmp_path):
    out = tmp_path / "keep.obj"
    out.write_text("previous")
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    with pytest.raises(meshbridge.WriteError, match="missing"):
        meshbridge.write(tmp_path / "missing" / "a.obj", vertices, faces)
    with pytest.raises(meshbridge.WriteError, match="keep.xyz"):
        meshbridge.write(tmp_path / "keep.xyz", vertices, faces)
    assert out.read_text() == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.obj"]


def test_checkerboard_every_cube_closed_and_separate():
    vertices, faces = mesh_models.checkerboard(6)
    cubes = len(faces) // 12
    assert cubes == 108
    result = meshbridge.repair(vertices, faces)
    assert result.report["vertices_out"] == 8 * cubes
    assert result.report["after"]["components"] == cubes
    assert result.report["after"]["boundary_edges"] == 0
    assert_repair_invariants(result, len(faces))


def test_results_outlive_their_inputs():
    vertices, faces = mesh_models.checkerboard(4)
    result = meshbridge.repair(vertices, faces)
    out = result.vertices
    del result, vertices, faces
    import gc

    gc.collect()
    assert out.shape == (8 * 32, 3) and np.isfinite(out).all()
    soup_faces = meshbridge.read(MODELS / "twocubes.obj").faces  # the soup itself is gone
    assert soup_faces.shape == (24, 3) and soup_faces.max() == 13


def test_gil_is_released_during_repair():
    """With a huge switch interval, the GIL changes hands only when its holder lets it go, so
    the main thread runs while the worker thread is inside repair exactly when repair releases
    it. (Up to 5 tries of a repair of about 0.2 s, in case the machine is too loaded to wake the
    main thread in time: other tests run beside this one.)"""
    vertices, faces = mesh_models.checkerboard(32)
    soup = meshbridge.Soup(vertices, faces)
    old = sys.getswitchinterval()
    seen = []
    try:
        sys.setswitchinterval(1000.0)
        for _ in range(5):
            state = {"done": False}
            started = threading.Event()

            def work():
                started.set()
                meshbridge.repair(soup)
                state["done"] = True

            worker = threading.Thread(target=work)
            worker.start()
            started.wait()
            seen.append(state["done"])  # False: we ran while repair was running
            worker.join()
            if not seen[-1]:
                break
    finally:
        sys.setswitchinterval(old)
    assert seen[-1] is False, f"the main thread never ran during repair: {seen}"


def test_soup_and_result_pickle_exactly():
    import pickle

    soup = meshbridge.read(MODELS / "prisms24.obj")
    back = pickle.loads(pickle.dumps(soup))
    assert repr(back) == repr(soup) and back.read_info == soup.read_info
    np.testing.assert_array_equal(back.vertices, soup.vertices)
    assert back.faces == soup.faces  # mixed arity: lists
    result = meshbridge.repair(soup)
    again = pickle.loads(pickle.dumps(result))
    assert again.report == result.report
    np.testing.assert_array_equal(again.vertex_origin, result.vertex_origin)
    np.testing.assert_array_equal(again.vertices, result.vertices)


def test_a_pickled_soup_checks_and_repairs_as_the_file(tmp_path):
    """Every reading count survives pickling (Dask sends soups between processes): face records
    without corners (counted by check and repair), the position weld of a per-face-vertex file,
    and float32 coordinates (repair's weld tolerance)."""
    import pickle

    path = tmp_path / "records.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf\nf 1 3 4\n")
    for soup in (meshbridge.read(path), meshbridge.read(REALWORLD2 / "cura_weedo_x40.3mf")):
        back = pickle.loads(pickle.dumps(soup))
        assert back.read_info == soup.read_info
        assert meshbridge.check(back) == meshbridge.check(soup)
        assert meshbridge.repair(back).report == meshbridge.repair(soup).report
    assert meshbridge.check(meshbridge.read(path))["read"]["faces_kept"] == 2
    cura = meshbridge.read(REALWORLD2 / "cura_weedo_x40.3mf").read_info
    assert cura["vertices_welded_by_position"] > 0


def test_a_keyhole_polygon_is_read_and_pickled_as_one():
    import pickle

    with pytest.warns(UserWarning, match=r"1 keyhole polygon \(an outline and holes joined"):
        soup = meshbridge.read(REALWORLD2 / "assimp_concave_polygon.obj")
    assert soup.read_info["faces_split"] == 1 and soup.read_info["keyhole_polygons"] == 1
    assert "pinched" not in soup.reading
    assert pickle.loads(pickle.dumps(soup)).read_info == soup.read_info
    report = meshbridge.check(soup)
    assert report["keyhole_polygons"] == 1 and report["degenerate_faces"] == 0


def test_weld_closes_a_crack_at_the_distance_given():
    # Two triangles that should share the edge 0-2; the second has its own copy of vertex 2,
    # 0.001 away: a crack.
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1.001, 1, 0]], dtype=float)
    faces = np.array([[0, 1, 2], [0, 4, 3]])
    assert meshbridge.REPAIR_OPTIONS["weld"] == "auto"
    apart = meshbridge.repair(vertices, faces, weld=0)  # vertex 0 alone joins them: it is split
    assert len(apart.vertices) == 6 and apart.report["after"]["boundary_edges"] == 6
    for weld in (0.01, np.float32(0.01), 1):
        closed = meshbridge.repair(vertices, faces, weld=weld)
        assert closed.report["gaps"]["vertices_welded"] == 1
        assert len(closed.vertices) == 4 and closed.report["after"]["boundary_edges"] == 4
    assert meshbridge.repair(vertices, faces, weld="auto").report["gaps"]["tolerance"] < 0.001
    for bad in (-1, float("nan"), float("inf"), "far", True):
        with pytest.raises(ValueError, match="weld must be 'auto' or a distance >= 0"):
            meshbridge.repair(vertices, faces, weld=bad)


def test_fill_holes_closes_the_cube_and_marks_the_new_triangles():
    vertices = np.array([[c & 1, (c >> 1) & 1, (c >> 2) & 1] for c in range(8)], dtype=float)
    quads = np.array([[0, 2, 3, 1], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
    assert meshbridge.REPAIR_OPTIONS["fill_holes"] == 0
    plain = meshbridge.repair(vertices, quads)
    assert "holes" not in plain.report and plain.report["after"]["boundary_edges"] == 4
    for value in (True, 4, np.int64(32)):
        result = meshbridge.repair(vertices, quads, fill_holes=value)
        holes = result.report["holes"]
        assert holes == {"max_edges": 32 if value is True else int(value), "holes_filled": 1,
                         "faces_added": 2, "holes_left": 0, "patches_refused": 0}
        assert result.report["after"]["watertight"] and result.report["faces_out"] == 7
        # Mixed arities: a list of polygons; the quads first, as given, then two triangles.
        assert [len(f) for f in result.faces] == [4, 4, 4, 4, 4, 3, 3]
        np.testing.assert_array_equal(result.face_origin, [0, 1, 2, 3, 4, -1, -1])
        np.testing.assert_array_equal(result.corner_origin[20:], [-1] * 6)
    assert meshbridge.repair(vertices, quads, fill_holes=3).report["holes"]["holes_left"] == 1
    with pytest.raises(ValueError, match="fill_holes must be"):
        meshbridge.repair(vertices, quads, fill_holes=-1)


def test_check_self_intersections_counts():
    """check(self_intersections=True): the counts of `check --self-intersections`, opt-in."""
    # Two unit cubes, the second moved by (0.5, 0.5, 0.5): its three low faces cross the first
    # one's three high faces.
    corners = mesh_models.CUBE_CORNERS
    vertices = np.vstack([corners, corners + 0.5])
    faces = np.vstack([mesh_models.CUBE_TRIANGLES, mesh_models.CUBE_TRIANGLES + 8])
    assert "self_intersections" not in meshbridge.check(vertices, faces)
    report = meshbridge.check(vertices, faces, self_intersections=True)
    assert report["self_intersections"]["component_pairs"] == 1
    assert report["self_intersections"]["faces"] == 12  # both triangles of 6 squares
    assert "elements" not in report["self_intersections"]
    listed = meshbridge.check(vertices, faces, elements=True, self_intersections=True)
    pairs = listed["self_intersections"]["elements"]["face_pairs"]
    assert len(pairs) == report["self_intersections"]["face_pairs"]
    # Two cubes on one edge, before and after repair: touching, never crossing.
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    assert meshbridge.check(vertices, faces, self_intersections=True)["self_intersections"] == {
        "face_pairs": 0, "faces": 0, "component_pairs": 0, "degenerate_triangles": 0}
    result = meshbridge.repair(vertices, faces)
    after = meshbridge.check(result.vertices, result.faces, self_intersections=True)
    assert after["self_intersections"]["face_pairs"] == 0
    assert "self_intersections" not in result.report
    assert meshbridge.repair(vertices, faces, self_intersections=True).report[
        "self_intersections"] == after["self_intersections"]


def test_repair_self_intersections_are_the_cli_repairs(tmp_path):
    """repair(self_intersections=True): the result's crossing faces, as `repair
    --self-intersections --report` gives them (crossing cubes: repair keeps every face)."""
    import json
    import subprocess

    cli = os.environ.get("MESHBRIDGE_CLI", "")
    if not cli:
        pytest.skip("MESHBRIDGE_CLI not set (the CLI is not built)")
    corners = mesh_models.CUBE_CORNERS
    vertices = np.vstack([corners, corners + 0.5])
    faces = np.vstack([mesh_models.CUBE_TRIANGLES, mesh_models.CUBE_TRIANGLES + 8])
    path = tmp_path / "crossing.obj"
    mesh_models.write_obj(path, vertices, faces)
    printed = subprocess.run([cli, "repair", path, tmp_path / "out.obj", "--self-intersections",
                              "--report", "-"], capture_output=True, text=True, timeout=120)
    assert printed.returncode == 0, printed.stderr
    theirs = json.loads(printed.stdout)["self_intersections"]
    ours = meshbridge.repair(meshbridge.read(path), self_intersections=True).report
    assert ours["self_intersections"] == theirs
    assert theirs["face_pairs"] > 0 and theirs["component_pairs"] == 1


def test_nested_shells_option_turns_an_insert_into_a_cavity_on_request():
    # A cube of side 4 with a cube of side 2 inside, both wound outward.
    corners = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
    quads = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2],
                      [1, 3, 7, 5]])
    vertices = np.vstack([corners * 4, corners * 2 + 1])
    faces = np.vstack([quads, quads + 8])
    material = meshbridge.repair(vertices, faces)
    assert material.report["faces_flipped"] == 0
    assert material.report["ambiguous_nested_shells"] == 1
    cavity = meshbridge.repair(vertices, faces, nested_shells="cavity")
    assert cavity.report["faces_flipped"] == 6
    assert sorted(set(np.nonzero(np.any(cavity.faces != faces, axis=1))[0])) == [6, 7, 8, 9, 10, 11]
    with pytest.raises(ValueError, match="nested_shells must be 'material' or 'cavity'"):
        meshbridge.repair(vertices, faces, nested_shells="hollow")
    assert meshbridge.REPAIR_OPTIONS["nested_shells"] == "material"


def test_check_forecasts_what_repair_would_change():
    """check() says what repair would change, as the CLI's check: `repair.changes`, its counts and
    its line of text; the counts are the repair's own."""
    vertices, faces = mesh_models.two_cubes_sharing_an_edge()
    report = meshbridge.check(vertices, faces)
    would = report["repair"]
    assert would["changes"] is True and would["ran_repair"] is True
    assert would["text"] == "repair would: make 2 vertex copies (split fans)"
    assert (would["vertices_in"], would["vertices_out"], would["vertices_split"]) == (14, 16, 2)
    assert (would["faces_in"], would["faces_out"]) == (24, 24)
    assert would["sides_cut"] == would["sides_cut_for_orientation"] == would["faces_flipped"] == 0
    assert would["components_topology_changed"] == 0
    assert "orientation" not in report  # not watertight: repair itself ran
    assert report["gaps"]["vertices_welded"] == 0
    repaired = meshbridge.repair(vertices, faces).report
    assert {k: repaired[k] for k in would if k in repaired and k != "gaps"} == {
        k: v for k, v in would.items() if k in repaired}
    # An open box (a cube without its top): repair leaves it as it is.
    box = mesh_models.CUBE_TRIANGLES[[0, 1] + list(range(4, 12))]
    report = meshbridge.check(mesh_models.CUBE_CORNERS, box)
    assert report["boundary_edges"] == 4
    assert report["repair"]["changes"] is False
    assert report["repair"]["text"] == "repair would change nothing (4 boundary edges stay open)"
    assert report["repair"]["vertices_split"] == report["repair"]["sides_cut"] == 0
    # A closed cube written inside out: detection alone tells (orientation), nothing repaired.
    inside_out = mesh_models.CUBE_TRIANGLES[:, ::-1]
    report = meshbridge.check(mesh_models.CUBE_CORNERS, inside_out, nested_shells="cavity")
    assert report["orientation"] == {"faces_flipped": 12, "ambiguous_nested_shells": 0}
    assert report["repair"]["ran_repair"] is False
    assert report["repair"]["text"] == "repair would: reverse 12 faces"
    # forecast=False: detection only, as before.
    plain = meshbridge.check(vertices, faces, forecast=False)
    assert not {"gaps", "orientation", "repair"} & set(plain)
    with pytest.raises(ValueError, match="nested_shells must be"):
        meshbridge.check(vertices, faces, nested_shells="void")
    with pytest.raises(ValueError, match="weld must be"):
        meshbridge.check(vertices, faces, weld=-1)
