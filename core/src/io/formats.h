// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The contract between the dispatcher (io.cpp) and the one reader and one writer per format.
//
// READERS  `void read_FMT(const MappedFile& file, Soup& soup, ReadInfo& info,
//                          MeshAttributes* attributes)`
//   - `file` is the whole file (size > 0); `soup` is empty; `info` is zeroed; `attributes` is
//     null when the caller does not want colours/groups (then do not collect them).
//   - Append every vertex and every face record in file order, exactly as the file has them:
//     repeated corners stay (the dispatcher classifies them, see account_faces); a record with
//     1 or 2 corners is appended as a triangle repeating its last corner (so soup face f is
//     record f); a record with 0 corners is not appended but counted in
//     `info.faces_without_corners`. Never drop, merge or reorder anything (STL welds corners by
//     exact position: that is its vertex identity). Convert coordinates to double unchanged.
//   - Fill `info.declared_vertices` / `info.declared_faces` (see io.h), `info.dangling_edges`
//     (OBJ l, PLY edge), `info.lone_points` (OBJ p). Leave faces_kept/split/set_aside to the
//     dispatcher. `attributes->vertex_colors`/`face_colors` must end up empty or exactly one per
//     soup vertex/face.
//   - Malformed input: throw ReadError whose message starts with `file.path() + ": "` and names
//     the line (text) or record (binary) and what was expected. Counts that lie (a header says
//     more than the file holds) are a ReadError, checked BEFORE reserving memory: reserve at
//     most what the remaining bytes can hold. Never read outside [file.data(), file.end()).
//   - Indices may be out of range or coordinates non-finite: store them as they are (index
//     kNoIndex for negative ones that do not resolve); the dispatcher's account_faces names them.
//     A reader that can name them better (ascii PLY: by line) throws itself.
//
// WRITERS  `void write_FMT(AtomicOutput& out, const IndexedMesh& mesh,
//                           const MeshAttributes* attributes, const WriteOptions& options)`
//   - Write the whole file through `out` (or to `out.temporary_path()`); the dispatcher has
//     already chosen the format and wraps the call in write_atomically (no renaming here).
//   - `attributes` (may be null) belong to the input soup: map them through
//     `mesh.vertex_origin` / `mesh.face_origin` (each may be empty: then identity) with
//     colour_of(), which gives an added face (origin kNoIndex) the default colour.
//   - Double precision where the format allows (text: std::to_chars shortest round trip).
//   - Throw WriteError naming `out.target()` if the mesh cannot be written (e.g. an index that
//     does not fit the format).

#include "io/atomic_write.h"
#include "io/mapped_file.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <string>
#include <string_view>

namespace meshbridge::detail {

//! The file formats, by extension (mesh_format()).
using Format = MeshFormat;
//! For a file (its whole bytes) that the reader of `format` cannot read or finds no polygon in:
//! what it looks like instead, as "; it begins with 'ply': a PLY file under another name?" (other
//! formats' first words, a zip archive's magic bytes, a binary STL's size, NUL bytes in text),
//! or empty.
std::string other_format_hint(std::string_view file, Format format);

void read_obj(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes);
//! A face corner of an OBJ soup whose vertex is past the file's last vertex (found after the
//! read: an OBJ face may name a vertex written after it).
struct ObjIndexOutOfRange {
  std::size_t face = 0;      //!< soup face (0-based)
  std::size_t corner = 0;    //!< corner of that face (0-based)
  std::size_t vertices = 0;  //!< vertices in the file
};
//! Reads `file` again up to that face and throws the ReadError naming its line ("line 6: face
//! corner 3 refers to vertex 9, but the file has 3 vertices").
[[noreturn]] void throw_obj_index_out_of_range(const MappedFile& file,
                                               const ObjIndexOutOfRange& where);
void read_off(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes);
void read_ply(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes);
void read_stl(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes);
//! 3MF through lib3mf 1.8 (the v1 C API; it reads `file.path()` itself): what a slicer prints.
//! Every build item in file order, its object's triangles placed by the item's transform
//! (components objects: each component's object under the component's transform, then the
//! item's, to any depth up to 64); an object placed twice is read twice. Then every mesh object
//! that no build item reaches, as stored, so that nothing in the file is dropped. Vertex indices
//! are offset per placement; positions are float32 from the file, transformed in double. A
//! placement that mirrors (the product of the transforms down to the mesh has a negative
//! determinant) reverses its triangles' corner order, as slicers do, so that a correct file is
//! read outward. With `attributes`: each face's 3MF object (type, in the build or not) where
//! some face is not of a placed "model" object, the unit and the model's metadata. No colours.
//! The meshes' vertex and triangle lists are read by pugixml where they can be
//! (package_without_meshes(); the same soup to the bit as lib3mf's, about 3x as fast), unless
//! MESHBRIDGE_3MF_MESHES=lib3mf.
void read_3mf(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes);

void write_obj(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options);
void write_off(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options);
void write_ply(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options);
void write_stl(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options);
//! For writers that store positions as 32-bit floats (STL, 3MF): throws WriteError naming
//! `path`, the first vertex (0-based, as validate_soup() names them) whose coordinate a float
//! cannot hold (beyond +-3.4e38, which a float would turn into infinity) and the formats that can.
//! Rounding within the range is not an error (describe_written() names it).
void require_float_range(const Soup& soup, const std::string& path, const char* format);

//! 3MF through lib3mf 1.8 into `out.temporary_path()`: one mesh object per 3MF object kind of
//! the faces (MeshAttributes::face_objects; one object when there are none: the model), each of
//! its type, in a build item of its own unless it was in none (or is of type "other"); polygons
//! cut into triangles (triangulate_polygon()), positions as float32 (3MF's precision); the
//! attributes' unit and metadata; no colours.
void write_3mf(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options);

//! How the positions of `soup` came back from the 3MF file `path` that write_3mf() wrote: lib3mf
//! 1.8 writes a coordinate as text with at most 6 decimals, computed in float (999.999f is
//! written 999.999040, 1e-7 as 0). Measured by reading the file again with lib3mf.
struct ThreeMfRounding {
  std::size_t moved = 0;      //!< vertices whose written position differs from their float one
  double largest_move = 0;    //!< the largest coordinate difference
  std::size_t collapsed = 0;  //!< triangles with two corners that now coincide (none before)
  bool measured = false;      //!< false if the file could not be read back (nothing measured)
};
//! See ThreeMfRounding. `face_objects` are the kinds write_3mf() wrote the faces of `soup` with
//! (output_face_objects(): one per face, or empty), which tell its objects' vertex order.
ThreeMfRounding measure_3mf_rounding(const std::string& path, const Soup& soup,
                                     const std::vector<FaceObject>& face_objects);

//! Checks `soup` as validate_soup() does and, in the same walk over the faces, classifies every
//! face as kept, split (pinched) or set aside (< 3 distinct corners) the way repair's WorkingSoup
//! does, adding the counts to `info` (faces_without_corners are added to faces_set_aside too).
//! Called by the dispatcher after every reader. \throw InvalidSoupError as validate_soup()
void account_faces(const Soup& soup, ReadInfo& info);

//! The 3MF object kind of every face of `soup` (`input` belongs to the input soup, one per input
//! face, mapped through `face_origin`, which may be empty: identity). A face repair added (origin
//! kNoIndex: a filled hole) takes the kind of the first face that has an input and shares its
//! first corner with it, else of the model: a patch in a support stays in the support. Empty
//! when `input` is, or when every face is of a placed "model" object.
std::vector<FaceObject> output_face_objects(const Soup& soup, const std::vector<Index>& face_origin,
                                            const std::vector<FaceObject>& input);

//! White, the colour of an element the file gave none (MeshAttributes::*_color_missing).
inline constexpr Rgba kNoColor{255, 255, 255, 255};

//! Gives elements [colors.size(), n) no colour of their own: white, flagged in `missing` (which
//! is extended with "given" flags for the elements before).
inline void pad_missing_colors(std::vector<Rgba>& colors, std::vector<bool>& missing,
                               std::size_t n) {
  if (colors.size() >= n)
    return;
  missing.resize(colors.size(), false);
  missing.resize(n, true);
  colors.resize(n, kNoColor);
}

//! Appends the colour of the next element: `given` or none (see pad_missing_colors). Nothing is
//! stored while no element has a colour.
inline void push_color(std::vector<Rgba>& colors, std::vector<bool>& missing, std::size_t element,
                       const Rgba* given) {
  if (given == nullptr) {
    if (!colors.empty())
      pad_missing_colors(colors, missing, element + 1);
    return;
  }
  pad_missing_colors(colors, missing, element);
  if (!missing.empty())
    missing.push_back(false);
  colors.push_back(*given);
}

//! True if input element `origin` has a colour of its own in `colours` (see
//! MeshAttributes::has_color); false for kNoIndex (an element repair added).
inline bool has_color(const std::vector<Rgba>& colors, const std::vector<bool>& missing,
                      Index origin) {
  return MeshAttributes::has_color(colors, missing, origin);
}

//! The vertex of the input soup behind output vertex `v` (identity when the map is empty).
inline Index input_vertex(const IndexedMesh& mesh, std::size_t v) {
  return mesh.vertex_origin.empty() ? static_cast<Index>(v) : mesh.vertex_origin[v];
}
//! The face of the input soup behind output face `f` (identity when the map is empty); kNoIndex
//! for a face repair added (a filled hole).
inline Index input_face(const IndexedMesh& mesh, std::size_t f) {
  return mesh.face_origin.empty() ? static_cast<Index>(f) : mesh.face_origin[f];
}
//! The OBJ texture coordinates and normals of the corners of `mesh`, from `input` (of the soup
//! `mesh` was repaired from) through `mesh.corner_origin` (identity when empty): each corner
//! takes its input corner's records; a corner repair inserted into a side (a midpoint split, a
//! closed T-junction: its origin repeats its neighbour's) gets records interpolated between the
//! side's two corners by its position along it (new records, appended after the input's); a
//! corner of a face hole filling added (origin kNoIndex) gets none. Every input record is kept.
CornerAttributes carry_corner_attributes(const CornerAttributes& input, const IndexedMesh& mesh);

//! The colour of the input element `origin` (from input_vertex / input_face), or the default
//! colour (opaque black) for an element with no input (kNoIndex: a face added by hole filling).
inline Rgba color_of(const std::vector<Rgba>& colors, Index origin) {
  return origin < colors.size() ? colors[origin] : Rgba{};
}

}  // namespace meshbridge::detail
