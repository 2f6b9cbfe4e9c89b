# SPDX-License-Identifier: GPL-3.0-or-later
"""MeshBridge: load, check and repair non-manifold polygon meshes without losing a face.

The same C++ core as the ``meshbridge`` command line and the MeshLab plugin, on numpy arrays.

Arrays
------
vertices
    ``(n, 3)`` array of coordinates, float64 or float32 (read in place, any strides; other
    real dtypes and nested lists are converted once).
faces
    ``(m, k)`` integer array (any integer dtype, k >= 3: triangles, quads, ...), or a sequence
    of index sequences for polygons of mixed arity. Indices are 0-based vertex rows.

Results come back as numpy arrays that own the repaired mesh (no copy): vertices ``(n', 3)``
float64; faces ``(m', k)`` int32 when every polygon has k corners, else a list of lists of
ints; provenance ``vertex_origin (n',)``, ``face_origin (m',)``, ``corner_origin (c',)``
int32, the input row each output element came from (-1: none). Index arrays are int64 instead
for meshes of 2^31 vertices or more.

Reports are dicts of the same JSON the command line writes (``meshbridge check --json``,
``meshbridge repair --report``): counts by default, element lists with ``elements=True``.

Errors: :class:`InvalidMeshError` (a ``ValueError``) names the face, corner or vertex at fault;
:class:`ReadError` and :class:`WriteError` (``OSError``) name the file.

The GIL is released while a file is read or written and while a mesh is checked or repaired,
so threads run those in parallel.
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Error, InvalidMeshError, ReadError, Soup, WriteError

__all__ = [
    "Error",
    "InvalidMeshError",
    "ReadError",
    "RepairResult",
    "Soup",
    "WriteError",
    "check",
    "read",
    "repair",
    "write",
    "REPAIR_OPTIONS",
]

__version__ = "0.1.0"

#: The options of :func:`repair` with their defaults (those of ``meshbridge repair``).
REPAIR_OPTIONS: Dict[str, Any] = {
    "pairing": "geometric",
    "orient": True,
    "cut_nonorientable": False,
    "stitch": True,
    "remove_duplicate_faces": False,
    "remove_degenerate_faces": False,
    "remove_zero_area_faces": False,
    "remove_isolated_vertices": False,
    "detect_before_after": True,
    "fill_holes": 0,
    "weld": "auto",
    "close_t_junctions": True,
    "nested_shells": "material",
}

Faces = Union[np.ndarray, Sequence[Sequence[int]]]


class RepairResult(tuple):
    """``(vertices, faces, report)`` of :func:`repair`, with the provenance as attributes.

    Unpacks as a 3-tuple: ``vertices, faces, report = meshbridge.repair(v, f)``.

    Attributes
    ----------
    vertices : ndarray, (n', 3) float64
    faces : ndarray (m', k) int32, or list of lists of int for mixed arities
    report : dict, the repair report (schema of ``meshbridge repair --report``)
    vertex_origin : ndarray, (n',) int32, input vertex of each output vertex
    face_origin : ndarray, (m',) int32, input face of each output face (order preserved;
        -1 for a triangle added by ``fill_holes``, which come last)
    corner_origin : ndarray, (c',) int32, input corner (position in the input's flattened
        faces) of each output corner, in output order (-1 for corners of added triangles)
    """

    vertex_origin: np.ndarray
    face_origin: np.ndarray
    corner_origin: np.ndarray

    def __new__(cls, vertices, faces, report, vertex_origin, face_origin, corner_origin):
        self = super().__new__(cls, (vertices, faces, report))
        self.vertex_origin = vertex_origin
        self.face_origin = face_origin
        self.corner_origin = corner_origin
        return self

    def __reduce__(self):
        return (RepairResult, (*self, self.vertex_origin, self.face_origin, self.corner_origin))

    @property
    def vertices(self) -> np.ndarray:
        return self[0]

    @property
    def faces(self) -> Faces:
        return self[1]

    @property
    def report(self) -> Dict[str, Any]:
        return self[2]


def _soup(vertices: Union[Soup, np.ndarray, Sequence], faces: Optional[Faces]) -> Soup:
    if isinstance(vertices, Soup):
        if faces is not None:
            raise TypeError("pass either a Soup or vertices and faces, not a Soup and faces")
        return vertices
    if isinstance(vertices, RepairResult):
        if faces is not None:
            raise TypeError("pass either a RepairResult or vertices and faces, not both")
        return Soup(vertices[0], vertices[1])
    if faces is None:
        raise TypeError("faces are missing: pass vertices and faces, or a Soup")
    return Soup(vertices, faces)


def read(path: Union[str, "os.PathLike[str]"]) -> Soup:
    """Reads a mesh file (OBJ, OFF, PLY, STL) as a soup: every vertex and polygon as the file has
    them, nothing refused or merged (STL is welded by exact position).

    Returns a :class:`Soup` with ``vertices`` (n, 3) float64, ``faces`` ((m, k) int32 or a list
    of lists), ``corner_vertices``/``face_begin`` (the polygons as flat arrays), ``path`` and
    ``read_info`` (what the file declared). Its arrays are read-only views.

    The polygons are the file's face records as they are: a pinched polygon (one that passes a
    vertex twice, ``f 1 2 3 1 4 5``) keeps its corners, and :func:`check` and :func:`repair` split
    it at the repeated vertex, the same way for every format; a record with fewer than 3 distinct
    corners stays a face (a 1- or 2-corner record repeats its last corner up to 3) that
    :func:`check` counts in ``faces_set_aside`` and :func:`repair` sets aside. Either is a
    :class:`UserWarning`, as the CLI warns, and ``soup.reading`` in words (also dangling edges,
    lone points and skipped lines).

    A Soup holds positions and polygons only. What else the file holds (colours, OBJ groups and
    materials, texture coordinates, normals, other PLY properties) is listed in
    ``soup.not_held`` and named in a :class:`UserWarning`, because :func:`write` cannot write it
    back; :func:`meshbridge.batch.run_batch` and the CLI carry colours and groups to the output,
    and OBJ texture coordinates and normals to an OBJ output.

    Raises :class:`ReadError` (missing, unreadable, empty or malformed file, a vertex index out
    of range, named by line where the format has lines) or :class:`InvalidMeshError` (a
    non-finite coordinate), naming the file.
    """
    soup = _core.read(_path(path))
    if soup.reading is not None:  # as the CLI warns: a split, set-aside or skipped record
        warnings.warn(f"{soup.path}: {soup.reading}", UserWarning, stacklevel=2)
    if soup.not_held:  # what write() cannot give back
        warnings.warn(
            f"{soup.path}: a Soup holds positions and polygons only; not held: "
            + "; ".join(soup.not_held)
            + " (meshbridge.batch and the CLI carry colours and groups to their output, and OBJ"
            + " texture coordinates and normals to an OBJ output)",
            UserWarning,
            stacklevel=2,
        )
    return soup


def write(
    path: Union[str, "os.PathLike[str]"],
    mesh: Any,
    faces: Optional[Faces] = None,
    *,
    separate: bool = True,
) -> Dict[str, Any]:
    """Writes a manifold mesh to OBJ, OFF, PLY, STL or 3MF (chosen by the extension).

    ``mesh`` is a :class:`Soup`, a :class:`RepairResult`, or vertices with ``faces``: positions
    and polygons only (no colours or groups: :func:`read` warns of what a file held besides, in
    ``soup.not_held``; :func:`meshbridge.batch.run_batch` carries a file's own). The file is written under a temporary name and renamed, so on error the previous file
    is untouched.
    STL and 3MF get triangles. STL stores no shared vertices, and every reader welds equal
    positions: for a :class:`RepairResult` written as STL with ``separate`` (default), the copies
    of each split vertex are first moved apart by the smallest distance a reader's weld by float32
    position keeps apart (as ``meshbridge repair`` does); ``separate=False`` keeps positions
    exact. When reading the written STL back re-creates singular edges or vertices, a
    :class:`UserWarning` says how many; write 3MF, PLY, OBJ or OFF to keep the repair exactly.
    Returns ``{"reread_singular_edges", "reread_singular_vertices", "copies_moved",
    "separation"}`` (STL only; zeros for the other formats): the file as an STL reader gets it
    back, and the copies moved with their distance in model units.

    Any soup is written as it is (a non-manifold one too: repair it first to write a manifold
    mesh). Raises :class:`InvalidMeshError` (an index out of range, a face of fewer than 3
    corners, a non-finite coordinate) or :class:`WriteError` (a coordinate beyond the 32-bit
    floats of STL and 3MF, a triangle that names a vertex twice for 3MF, no permission...),
    naming the file; nothing is written then.
    """
    target = _path(path)
    origins = mesh.vertex_origin if separate and isinstance(mesh, RepairResult) else None
    edges, vertices, moved, distance = _core.write(target, _soup(mesh, faces), origins)
    if edges or vertices:
        warnings.warn(
            f"{target}: STL has no shared vertices; reading it welds split vertex copies again "
            f"and re-creates {_counted(edges, 'singular edge')} and "
            f"{_counted(vertices, 'singular vertex')}. "
            "Write 3MF, PLY, OBJ or OFF to keep the repair.",
            UserWarning,
            stacklevel=2,
        )
    return {"reread_singular_edges": edges, "reread_singular_vertices": vertices,
            "copies_moved": moved, "separation": distance}


def check(
    vertices: Union[Soup, np.ndarray, Sequence],
    faces: Optional[Faces] = None,
    *,
    elements: bool = False,
    self_intersections: bool = False,
    forecast: bool = True,
    weld: Union[str, float] = "auto",
    nested_shells: str = "material",
) -> Dict[str, Any]:
    """Detects every defect without changing anything, and says what :func:`repair` would change.

    ``vertices`` (n, 3) and ``faces`` (m, k) or polygons, or a :class:`Soup` alone. Returns the
    report of ``meshbridge check --json`` as a dict: counts (singular edges and vertices,
    boundary edges and loops, components, ...) and, with ``elements=True``, the element lists.
    With ``self_intersections=True`` (off by default: it costs about twice the rest), also the
    ``self_intersections`` object of ``check --self-intersections``: crossing face pairs, faces
    in them, pairs of components that cross.

    With ``forecast=True`` (the default, as the CLI's check) also what ``repair`` with the
    default options and this ``weld`` and ``nested_shells`` (as ``check --weld``,
    ``--nested-shells``) would do: ``gaps`` (the gap closing), ``orientation`` (a watertight
    mesh only: faces it would reverse) and ``repair``: ``changes`` (bool: repair would change
    the mesh), ``ran_repair``, ``text`` (the CLI's line, e.g. ``"repair would: make 2 vertex
    copies (split fans)"``) and the counts of a repair report (``vertices_split``, ``sides_cut``,
    ``faces_flipped``, ...). On a mesh that is not watertight this runs the repair in memory
    (about a repair's time); ``forecast=False`` skips it.

    Raises :class:`InvalidMeshError` naming the offending face, corner or vertex, and
    ``ValueError`` for a bad ``weld`` or ``nested_shells``.
    """
    options = (
        _repair_options({"weld": weld, "nested_shells": nested_shells}) if forecast else None
    )
    return _core.check(_soup(vertices, faces), elements, self_intersections, options)


def repair(
    vertices: Union[Soup, np.ndarray, Sequence],
    faces: Optional[Faces] = None,
    *,
    elements: bool = False,
    self_intersections: bool = False,
    **options: Any,
) -> RepairResult:
    """Lossless manifold repair: every face kept, every output edge manifold.

    ``vertices`` (n, 3) and ``faces`` (m, k) or polygons, or a :class:`Soup` alone.
    Options (defaults as ``meshbridge repair``; see ``REPAIR_OPTIONS``): ``pairing``
    ('geometric' or 'combinatorial'), ``orient``, ``cut_nonorientable`` (also orient
    non-orientable components, Moebius strips: faces follow a breadth-first spanning tree and
    the edges that disagree with it are cut; off, the default: their faces keep their
    directions and each edge whose faces run the same way is cut; either cut is not
    necessarily the fewest; as ``--cut-nonorientable``), ``stitch``,
    ``remove_duplicate_faces``, ``remove_degenerate_faces``, ``remove_zero_area_faces``,
    ``remove_isolated_vertices``,
    ``detect_before_after`` (False skips the before/after detection: faster, fewer counts),
    ``fill_holes`` (after the repair, close holes of at most this many edges with new
    triangles; ``True`` = 32, ``0``/``False`` = off, the default; as ``--fill-holes``),
    ``weld`` (gap closing before pairing: vertices closer than this distance, in the mesh's
    length unit, become one; ``'auto'``, the default, derives it from the mesh's size and
    coordinates; ``0`` = off; as ``--weld``), ``close_t_junctions`` (also split a boundary side
    where another boundary vertex lies on it within that distance; default True),
    ``nested_shells`` ('material', the default, or 'cavity': what a closed shell inside another
    and wound the same way becomes; as ``--nested-shells``).
    Faces added by hole filling come last, with ``face_origin`` and ``corner_origin`` -1.
    With ``self_intersections=True`` (off by default, as ``repair --self-intersections``) the
    report also holds ``self_intersections``: the faces of the result that cross (as check's).

    Returns a :class:`RepairResult`: ``(vertices (n', 3) float64, faces (m', k) int32 or
    polygons, report dict)`` with ``vertex_origin (n',)``, ``face_origin (m',)`` and
    ``corner_origin`` as attributes.

    Raises :class:`InvalidMeshError` naming the offending face, corner or vertex, and
    ``TypeError`` for an unknown option.
    """
    soup = _soup(vertices, faces)
    native = _repair_options(options)
    v, f, report, vertex_origin, face_origin, corner_origin = _core.repair(
        soup, native, elements, self_intersections
    )
    return RepairResult(v, f, report, vertex_origin, face_origin, corner_origin)


def _repair_options(options: Dict[str, Any]) -> "_core.RepairOptions":
    native = _core.RepairOptions()
    for name, value in options.items():
        if name not in REPAIR_OPTIONS:
            raise TypeError(
                f"repair() got an unknown option {name!r}; options are: "
                + ", ".join(REPAIR_OPTIONS)
            )
        if name == "pairing":
            if isinstance(value, str) and value.lower() in ("geometric", "combinatorial"):
                value = getattr(_core.PairingPolicy, value.lower())
            elif not isinstance(value, _core.PairingPolicy):
                raise ValueError(f"pairing must be 'geometric' or 'combinatorial', got {value!r}")
        elif name == "nested_shells":
            if not isinstance(value, str) or value.lower() not in ("material", "cavity"):
                raise ValueError(f"nested_shells must be 'material' or 'cavity', got {value!r}")
            setattr(native, name, getattr(_core.AmbiguousNesting, value.lower()))
            continue
        elif name == "weld":
            if isinstance(value, str) and value.lower() == "auto":
                value = _core.AUTO_WELD_TOLERANCE
            elif (
                isinstance(value, (bool, np.bool_))
                or not isinstance(value, (int, float, np.integer, np.floating))
                or not np.isfinite(value)
                or value < 0
            ):
                raise ValueError(f"weld must be 'auto' or a distance >= 0, got {value!r}")
            setattr(native, name, float(value))
            continue
        elif name == "fill_holes":
            if isinstance(value, (bool, np.bool_)):
                value = _core.DEFAULT_FILL_HOLES_MAX_EDGES if value else 0
            elif not isinstance(value, (int, np.integer)) or value < 0:
                raise ValueError(
                    f"fill_holes must be True, False or a number of edges >= 0, got {value!r}"
                )
            setattr(native, name, int(value))
            continue
        elif not isinstance(value, (bool, np.bool_)):
            raise TypeError(f"repair() option {name} must be True or False, got {value!r}")
        setattr(native, name, value if name == "pairing" else bool(value))
    return native


def _counted(n: int, noun: str) -> str:
    """``n`` and ``noun`` in the right number: "1 singular edge", "2 singular vertices"."""
    if n == 1:
        return f"{n} {noun}"
    return f"{n} {noun[:-2]}ices" if noun.endswith("vertex") else f"{n} {noun}s"


def _path(path: Any) -> str:
    import os

    return os.fsdecode(os.fspath(path))
