# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of the compiled module meshbridge._core (use the meshbridge package's functions)."""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Faces = Union[npt.NDArray[np.int32], List[List[int]]]

class Error(Exception): ...
class InvalidMeshError(Error, ValueError): ...
class ReadError(Error, OSError): ...
class WriteError(Error, OSError): ...

class PairingPolicy:
    geometric: PairingPolicy
    combinatorial: PairingPolicy
    name: str
    value: int
    def __init__(self, value: int) -> None: ...

class AmbiguousNesting:
    material: AmbiguousNesting
    cavity: AmbiguousNesting
    name: str
    value: int
    def __init__(self, value: int) -> None: ...

class RepairOptions:
    pairing: PairingPolicy
    orient: bool
    cut_nonorientable: bool
    stitch: bool
    remove_duplicate_faces: bool
    remove_degenerate_faces: bool
    remove_zero_area_faces: bool
    remove_isolated_vertices: bool
    detect_before_after: bool
    fill_holes: int  # FillHolesOptions::max_edges; 0 = off
    weld: float  # CloseGapsOptions::tolerance; AUTO_WELD_TOLERANCE = automatic, 0 = off
    close_t_junctions: bool  # CloseGapsOptions::close_t_junctions
    nested_shells: AmbiguousNesting
    def __init__(self) -> None: ...

DEFAULT_FILL_HOLES_MAX_EDGES: int
AUTO_WELD_TOLERANCE: float
HAS_HOLE_FILLING: bool

class Soup:
    """Positions and polygons exactly as given or read; arrays are read-only views."""

    def __init__(
        self,
        vertices: Union[npt.ArrayLike, Sequence[Sequence[float]]],
        faces: Union[npt.ArrayLike, Sequence[Sequence[int]]],
    ) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(n, 3) float64, read-only."""
    @property
    def faces(self) -> _Faces:
        """(m, k) int32 when every polygon has k corners, else a list of m lists of int."""
    @property
    def corner_vertices(self) -> npt.NDArray[np.int32]:
        """(c,) int32: the polygons' vertex indices back to back."""
    @property
    def face_begin(self) -> npt.NDArray[np.int32]:
        """(m + 1,) int32: polygon f is corner_vertices[face_begin[f]:face_begin[f + 1]]."""
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def path(self) -> Optional[str]:
        """The file it was read from, None when built from arrays."""
    @property
    def read_info(self) -> Optional[dict[str, Any]]:
        """What the file declared next to what was read; None when built from arrays."""
    @property
    def reading(self) -> Optional[str]:
        """What the reader did not keep as it was, in words; None when it kept every record."""
    @property
    def not_held(self) -> List[str]:
        """What the file holds besides positions and polygons (colours, groups, normals...), one
        phrase per kind; empty when nothing or built from arrays."""

def read(path: str) -> Soup: ...
def write(
    path: str, soup: Soup, vertex_origin: Optional[npt.ArrayLike] = None
) -> Tuple[int, int, int, float]: ...
def check(
    soup: Soup,
    elements: bool = False,
    self_intersections: bool = False,
    forecast: Optional[RepairOptions] = None,
) -> Dict[str, Any]: ...
def repair(
    soup: Soup, options: RepairOptions, elements: bool = False
) -> Tuple[
    npt.NDArray[np.float64],
    _Faces,
    Dict[str, Any],
    npt.NDArray[np.int32],
    npt.NDArray[np.int32],
    npt.NDArray[np.int32],
]: ...

class FileJobOptions:
    repair: RepairOptions
    format: str
    resume: bool
    elements: bool
    separate_stl_copies: bool
    print: bool
    print_keeps_weld: bool
    print_keeps_fill_holes: bool
    self_intersections: bool
    def __init__(self) -> None: ...

def plan_batch(
    in_dir: str, out_dir: str, options: FileJobOptions, in_place: bool = False
) -> Tuple[List[Tuple[str, str, str, str]], List[Tuple[str, str]]]:
    """(jobs as (input, output, name, output_name) sorted by name, unreadable as (name, reason))."""

def run_file_job(
    input: str, output: str, name: str, output_name: str, options: FileJobOptions
) -> Tuple[str, str, str, str]:
    """(status, reason, JSON Lines record, warning lines) of read -> repair -> write one file."""

def skipped_record(name: str, reason: str) -> str: ...
def failed_record(name: str, output_name: str, reason: str) -> str: ...
def batch_log_line(
    record: str, job: Tuple[str, str, str, str], options: FileJobOptions
) -> str:
    """The batch log's line of a finished job: its record with the options and input stamp."""

def record_of_log_line(line: str) -> str: ...
def batch_options_text(options: FileJobOptions) -> str: ...
def is_done_in_log(
    line: str, job: Tuple[str, str, str, str], options: FileJobOptions
) -> Tuple[bool, str]:
    """(True, "") when a rerun may skip the job, else (False, what changed)."""

def write_batch_log(path: str, lines: List[str]) -> None: ...
def harmless_warning_kind(line: str) -> str:
    """The harmless kind of a batch warning line, or "" when it reports lost data."""
