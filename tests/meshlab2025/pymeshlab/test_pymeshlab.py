# SPDX-License-Identifier: GPL-3.0-or-later
"""The plugin through the real pymeshlab (PyMeshLab 2025.7.post1's bindings built against Debian
sid's MeshLab 2025.07 by scripts/build_pymeshlab.sh), inside the sid root: README's counts on
prisms24, MeshLab's own topology filters on the result, and the current mesh kept by Detect and
Repair. Environment (tests/meshlab2025/CMakeLists.txt): PYTHONPATH with pymeshlab and meshbridge,
MESHBRIDGE_PLUGIN, MESHBRIDGE_SOURCE_DIR."""

import os
from pathlib import Path

import pymeshlab
import pytest

SOURCE = Path(os.environ["MESHBRIDGE_SOURCE_DIR"])
MODELS = SOURCE / "resources" / "models"
PLUGIN = os.environ["MESHBRIDGE_PLUGIN"]
DETECT = "compute_singular_defects_bridged"
REPAIR = "meshing_repair_singular_defects_bridged"

pymeshlab.load_plugin(PLUGIN)


def test_the_real_module():
    assert pymeshlab.pmeshlab.__version__ == "2025.7.post1"
    assert pymeshlab.pmeshlab.__file__.endswith(".so")
    # Debian's IO and filter plugins (not decorate/edit/render) and ours.
    filters = pymeshlab.filter_list()
    assert DETECT in filters and REPAIR in filters
    assert "meshing_repair_non_manifold_edges" in filters and "get_topological_measures" in filters


def test_prisms24_counts_and_meshlab_agrees():
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MODELS / "prisms24.obj"))
    before = ms.apply_filter("get_topological_measures")
    assert before["non_two_manifold_edges"] > 0
    found = ms.apply_filter(DETECT)
    assert (found["singular_edges"], found["singular_vertices"]) == (79, 38)
    assert ms.mesh_number() == 2 and ms.current_mesh_id() == 0
    fixed = ms.apply_filter(REPAIR)
    assert (fixed["faces_in"], fixed["faces_out"], fixed["vertices_split"]) == (192, 192, 106)
    assert fixed["after.singular_edges"] == 0
    assert ms.mesh_number() == 1 and ms.current_mesh().face_number() == 192
    after = ms.apply_filter("get_topological_measures")
    assert after["non_two_manifold_edges"] == 0 and after["non_two_manifold_vertices"] == 0
    assert after["faces_number"] == 192


def test_arrays_are_float32():
    """A difference from the PyPI wheel (double): Debian's MeshLab is a float build."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MODELS / "twocubes.obj"))
    assert str(ms.current_mesh().vertex_matrix().dtype) == "float32"


@pytest.mark.parametrize("steps", ["detect", "detect-detect", "detect-repair"])
def test_current_mesh_kept_with_a_mesh_after_the_defect_layer(steps, tmp_path):
    """Detect and Repair delete the defect layer of an earlier Detect; another mesh after that
    layer must not become current (save_current_mesh() would save it)."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MODELS / "prisms24.obj"))  # id 0, 192 faces
    ms.apply_filter(DETECT)  # defect layer: id 1
    ms.load_new_mesh(str(MODELS / "twocubes.obj"))  # id 2, 24 faces, current
    ms.set_current_mesh(0)
    for step in steps.split("-")[1:]:
        ms.apply_filter(DETECT if step == "detect" else REPAIR)
        assert ms.current_mesh_id() == 0, step
    ms.save_current_mesh(str(tmp_path / "saved.obj"))
    back = pymeshlab.MeshSet()
    back.load_new_mesh(str(tmp_path / "saved.obj"))
    assert back.current_mesh().face_number() == 192
    assert ms.mesh_number() == (2 if steps == "detect-repair" else 3)


@pytest.mark.parametrize("name,faces_out,flat_polygons", [
    ("ur_ur20_forearm_collision.stl", 2494, 0), ("sumo_tram.obj", 37740, 4)])
def test_sides_split_at_their_midpoint_stay_manifold_in_meshlab(name, faces_out, flat_polygons):
    """Repair splits some edges at their midpoint; each triangle on one comes back as a polygon
    with three corners on a line, which the plugin fans into MeshLab's triangles. Fanned from an
    end of the split side it gave a zero-area triangle and the split edge again: MeshLab's own
    measure then found singular edges (4 and 131) and duplicate faces the filter did not report."""
    import meshbridge

    def check(m):
        return meshbridge.check(m.vertex_matrix().astype("float64"), m.face_matrix())

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(SOURCE / "tests" / "data" / "realworld2" / name))
    zero_area_in = check(ms.current_mesh())["zero_area_faces"]
    fixed = ms.apply_filter(REPAIR)
    assert fixed["faces_out"] == faces_out and fixed["after.singular_edges"] == 0
    after = ms.apply_filter("get_topological_measures")
    assert (after["non_two_manifold_edges"], after["non_two_manifold_vertices"]) == (0, 0)
    found = check(ms.current_mesh())
    assert (found["singular_edges"], found["singular_vertices"]) == (0, 0)
    # Zero-area triangles: the input's slivers (72 in sumo_tram as MeshLab loads it), plus one for
    # each repaired polygon whose corners all lie on a line (4 in sumo_tram with the core's
    # triangles_as_written; its own fan gave 8).
    assert found["duplicate_faces"] == 0
    assert found["zero_area_faces"] == zero_area_in + flat_polygons


@pytest.mark.parametrize("which,message", [
    ("DOUBLE", "has different floating point precision from the running MeshLab version."),
    ("VERSION", "has different version from the running MeshLab version.")])
def test_a_plugin_built_for_another_meshlab_is_refused(which, message):
    """What a user sees when the plugin was built for another pymeshlab (docs/meshlab.md): a
    plugin built for double precision, or for MeshLab 2023.12, against this float 2025.07."""
    plugin = os.environ[f"MESHBRIDGE_ABI_{which}"]
    with pytest.raises(pymeshlab.PyMeshLabException) as error:
        pymeshlab.load_plugin(plugin)
    assert str(error.value).strip() == f"{os.path.basename(plugin)} {message}"
    assert "abi_mismatch" not in pymeshlab.filter_list()
