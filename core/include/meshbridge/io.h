// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file io.h
//! Files in and out: OBJ, OFF, PLY and STL, read by MeshBridge's own readers (one per format,
//! core/src/io/), each file once, from a memory map. Nothing a file declares is changed silently:
//! every face record is accounted for in ReadInfo.

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/soup.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace meshbridge {

//! What the file declared and what became of each record. Every face record of the file is in
//! exactly one of `faces_kept`, `faces_split` and `faces_set_aside`:
//! `declared_faces == faces_kept + faces_split + faces_set_aside` for every format.
struct ReadInfo {
  //! Vertex records (OBJ 'v'), header count (OFF, PLY) or 3 x triangles (STL, before welding).
  std::size_t declared_vertices = 0;
  //! Face records (OBJ 'f'), header count (OFF, PLY face/tristrip triangles), triangles (STL).
  std::size_t declared_faces = 0;
  //! Records read as simple polygons (consecutive repeated corners collapse, e.g. "f 1 2 2 3").
  std::size_t faces_kept = 0;
  //! Pinched polygons that revisit a vertex (e.g. "f 1 2 3 1 4 5"); repair splits them into
  //! simple loops, the same way for every format.
  std::size_t faces_split = 0;
  //! Of `faces_split`, keyhole polygons: an outline and holes joined by slits (the polygon runs
  //! a -> b and later b -> a), which repair cuts into triangles as one polygon with holes, the
  //! holes left open (DefectReport::keyhole_polygons_triangulated). The others are pinched.
  std::size_t keyhole_polygons = 0;
  //! Records with fewer than 3 distinct corners (e.g. an STL facet with one point three times,
  //! "f 1 2"). They are in the soup (a record with 1 or 2 corners repeats its last corner up to
  //! a triangle, so soup face f is record f) and in `faces` of every report, and repair sets
  //! them aside; only records with no corner at all (`faces_without_corners`) are not in the soup.
  std::size_t faces_set_aside = 0;
  //! Face records without a single corner ("f" alone, a PLY face with count 0): counted in
  //! `faces_set_aside` and `declared_faces`, absent from the soup.
  std::size_t faces_without_corners = 0;
  //! Two-point records that are no face: OBJ 'l' segments (a polyline of n points counts n - 1)
  //! and PLY `edge` elements. Not part of the soup.
  std::size_t dangling_edges = 0;
  //! OBJ 'p' points (each index of a record counts one). Not part of the soup.
  std::size_t lone_points = 0;
  //! PLY `tristrips`: triangles of a strip that repeat a vertex. Strips link their runs with such
  //! triangles (a b c c d ...); they are the encoding, not faces: not in the soup, not in
  //! `declared_faces`, and not a change (changed_anything() ignores them).
  std::size_t strip_joins = 0;
  //! Records that hold no face, edge or point: an OBJ `l` or `p` line without an index, a PLY
  //! `tristrips` run (a strip, or its part between -1 restarts) of 1 or 2 vertices, which makes
  //! no triangle. Not in the soup; counted so that they do not vanish without a word.
  std::size_t empty_records = 0;
  //! Bytes after the end of the mesh: after the last element a binary PLY header declares
  //! (padding, or items that a false count leaves out: faces among them would be lost), line
  //! ends or NULs after a binary OFF's last face, NUL and ^Z bytes after an ASCII STL (padding
  //! some programs write). Not read; counted so that
  //! they are not passed over without a word. (An ascii PLY with values after its last element
  //! is an error.)
  std::size_t trailing_bytes = 0;
  //! OBJ lines whose keyword is no OBJ record (e.g. "F 1 2 3", "vx 1 2"), skipped: counted so
  //! that a misspelt face is not lost without a word (the CLI warns). Records of the OBJ format
  //! MeshBridge has no use for (s, curves...) are not counted.
  std::size_t unknown_records = 0;
  //! OFF colours given as a single colour-map index (Geomview's colour map is a file of its own,
  //! not read): not kept, counted so that they are not lost without a word.
  std::size_t color_map_indices = 0;
  //! The file repeats each vertex per face (no vertex record is used by two corners, as many
  //! OBJ, PLY, OFF and 3MF exporters write triangles): its copies at one exact position were
  //! welded into one vertex, as STL corners are, before anything else; this many vertex records
  //! were merged away (0 for an indexed file, and for STL, whose corners always weld).
  std::size_t vertices_welded_by_position = 0;
  //! The coordinates were stored as 32-bit floats (STL, 3MF, PLY `float`): gap closing's
  //! automatic tolerance then respects float rounding (CloseGapsOptions::float_coordinates).
  bool float_coordinates = false;

  //! True if some record was not kept as one simple polygon.
  bool changed_anything() const {
    return faces_split + faces_set_aside + dangling_edges + lone_points + unknown_records +
               color_map_indices + empty_records + trailing_bytes >
           0;
  }
};

//! One line saying what became of the file's records, e.g. "10 face records: 8 kept, 1 split
//! (pinched), 1 set aside (< 3 distinct corners); 3 dangling edges, 1 lone point (not part of
//! the surface)"; a keyhole polygon is named as one ("1 keyhole polygon (an outline and holes
//! joined by slits: cut into triangles, the holes left open)"), not as pinched. Parts that are 0
//! are left out; a file read unchanged gives "N face records: all kept".
std::string describe_reading(const ReadInfo& info);

//! An 8-bit RGBA colour (alpha 255 when the file gives none).
struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba& x, const Rgba& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
  }
};

//! A run of faces under one OBJ `o`/`g`/`usemtl` name, from `first_face` to the next group.
struct FaceGroup {
  std::string name;  //!< "o NAME", "g NAME" or "usemtl NAME" as written (keyword included)
  Index first_face = 0;
};

//! Colour channels, as bits of MeshAttributes::vertex_color_channels / face_color_channels.
enum ColorChannel : std::uint8_t {
  kRedChannel = 1,
  kGreenChannel = 2,
  kBlueChannel = 4,
  kAlphaChannel = 8,
  kRgbChannels = 7,
  kRgbaChannels = 15
};

//! Something a file holds that MeshBridge reads past without keeping (normals, texture
//! coordinates, other PLY properties and elements, STL facet attributes...), e.g.
//! {"PLY vertex properties nx, ny, nz", 8, "vertex"}: no writer writes it, so every output
//! lacks it and describe_unwritten() names it.
struct NotKept {
  std::string what;       //!< what it is, with the format's own names
  std::size_t count = 0;  //!< on how many elements or records
  std::string noun;       //!< of what ("vertex", "face", "line", "item"), for counted()
  //! True when the file is at fault there, not merely holding what MeshBridge has no use for: an
  //! index naming no record, numbers that are no colour, a colour out of range, a stored normal
  //! against the winding. `meshbridge check` warns about these (it writes nothing, so it does
  //! not name the rest).
  bool fault = false;
  //! True when the values are kept, but clamped into their range (a colour channel of 300): the
  //! writers write the clamped values.
  bool clamped = false;
};

//! The type of a 3MF object (3MF Core Specification 1.2, section 4.1: object type).
enum class ObjectType : std::uint8_t { model, support, solidsupport, surface, other };

//! The specification's name of `type`: "model", "support", "solidsupport", "surface", "other".
const char* object_type_name(ObjectType type);

//! What a face was part of in a 3MF file: its object's type, and whether a build item placed it.
struct FaceObject {
  ObjectType type = ObjectType::model;
  //! False for a face of a mesh object that no build item reaches (a slicer does not print it).
  bool in_build = true;
  friend bool operator==(const FaceObject& x, const FaceObject& y) {
    return x.type == y.type && x.in_build == y.in_build;
  }
  friend bool operator!=(const FaceObject& x, const FaceObject& y) { return !(x == y); }
  //! True for a face of a placed "model" object: what a slicer prints as the model.
  bool is_printed_model() const { return type == ObjectType::model && in_build; }
};

//! The faces of 3MF objects that a slicer does not print as the model, by kind in order of
//! their first face, e.g. "4 faces of type support, 4 faces of an object in no build item, 2
//! faces of type other in no build item"; empty when there are none.
std::string describe_face_objects(const std::vector<FaceObject>& face_objects);

//! A 3MF model's metadata entry (3MF Core Specification 1.2, section 3.4.2: <metadata>).
struct Metadata {
  std::string name;
  std::string value;
  friend bool operator==(const Metadata& x, const Metadata& y) {
    return x.name == y.name && x.value == y.value;
  }
};

//! OBJ texture coordinates (`vt`) and normals (`vn`), given per face corner ("f 1/4/2 ..."): the
//! OBJ reader keeps them, repair carries them through IndexedMesh::corner_origin
//! (carry_attributes(), write_mesh()), and the OBJ writer writes them back as `vt`, `vn` and
//! `v/vt/vn` corners. No other format holds them per corner: the other writers leave them out
//! and describe_unwritten() says so.
struct CornerAttributes {
  //! The `vt` records in file order: u, v, w (a number the record leaves out is 0).
  std::vector<std::array<double, 3>> texture_coordinates;
  //! The most numbers a `vt` record gave (1 to 3; 0 without records): the OBJ writer writes
  //! this many (at least u and v).
  int texture_components = 0;
  //! The `vn` records in file order (x, y, z as written, not normalised).
  std::vector<std::array<double, 3>> normals;
  //! Empty (no corner names a `vt`), or one per soup corner (Soup::corner_vertices): the 0-based
  //! `vt` record of the corner, or kNoIndex where it names none (no index, or one the file has
  //! no record for: counted in MeshAttributes::not_kept).
  std::vector<Index> corner_texture;
  //! The same for `vn`.
  std::vector<Index> corner_normal;

  //! True if no corner has a texture coordinate or normal and the file had no record of either.
  bool empty() const {
    return texture_coordinates.empty() && normals.empty() && corner_texture.empty() &&
           corner_normal.empty();
  }
};

//! What a file carries besides positions and polygons, where MeshBridge keeps it.
struct MeshAttributes {
  std::vector<Rgba> vertex_colors;  //!< empty, or one per soup vertex
  std::vector<Rgba> face_colors;    //!< empty, or one per soup face
  //! Elements the file gave no colour although others have one (an OBJ `v` line without one, an
  //! OFF face without one, a PLY strip triangle): one flag per element, or empty when every
  //! element has its colour. Such an element holds white in the colour vector; the OBJ and OFF
  //! writers leave its colour out, PLY (a colour on every element or none) writes the white.
  std::vector<bool> vertex_color_missing, face_color_missing;
  //! The channels the file gave (ColorChannel bits; rgb for OBJ and OFF, plus alpha if some
  //! colour had one; a PLY file's own properties). The PLY writer writes exactly these; OBJ and
  //! OFF always write red, green and blue (a channel the file lacked is 0) and alpha if given.
  std::uint8_t vertex_color_channels = kRgbaChannels, face_color_channels = kRgbaChannels;
  std::vector<FaceGroup> face_groups;  //!< OBJ groups in file order (empty elsewhere)
  //! OBJ `mtllib` lines as written (never opened); the OBJ writer writes them back, so that the
  //! `usemtl` groups still name materials of a library.
  std::vector<std::string> material_libraries;
  //! OBJ `vt` and `vn` records (counts; the records and the corners' indices are in `corners`).
  //! Corners whose vt or vn index names no record are a NotKept entry. The OBJ writer writes
  //! them; describe_unwritten() names them for the other formats.
  std::size_t texture_coordinates = 0, normals = 0;
  //! OBJ texture coordinates and normals per corner (filled by the OBJ reader only).
  CornerAttributes corners;
  //! Everything else the file holds that is read past, not kept (filled only when the reader is
  //! given attributes). See describe_unwritten().
  std::vector<NotKept> not_kept;
  bool double_precision = false;  //!< positions were stored as 64-bit floats (PLY double)
  //! The length unit the file gives its coordinates in (3MF's `unit`: "micron", "millimeter",
  //! "centimeter", "inch", "foot", "meter"); empty for the formats that have none. Coordinates
  //! are kept as written, in this unit: the 3MF writer writes it back, and describe_unwritten()
  //! names a unit other than millimetres that an output without units cannot hold.
  std::string length_unit;
  //! Empty, or one per soup face: the 3MF object each face was read from (its type, and whether
  //! a build item placed it); filled only when some face is not of a placed "model" object (a
  //! support, a surface, an object in no build item). The 3MF writer writes the faces of each
  //! kind as an object of its own, of that type (outside the build where they were);
  //! describe_unwritten() names what other formats make of them. An added face (origin
  //! kNoIndex: a filled hole) is of the object of the faces at its first corner.
  std::vector<FaceObject> face_objects;
  //! The 3MF model's <metadata> entries in file order (title, designer, an application's own
  //! names...); the 3MF writer writes them back, describe_unwritten() names them for others.
  std::vector<Metadata> metadata;

  //! True if element `i` has a colour of its own (a colour vector that is non-empty and no
  //! missing flag). `i` may be kNoIndex (an element repair added: no colour).
  static bool has_color(const std::vector<Rgba>& colors, const std::vector<bool>& missing,
                        Index i) {
    return i < colors.size() && (missing.empty() || !missing[i]);
  }
};

//! Reads the raw soup of a mesh file: every vertex and polygon as the file has them (repeated
//! corners included; repair splits or sets them aside), nothing refused or merged on the way in
//! except STL corners, which are welded by exact position. The format is chosen by extension
//! (.obj .off .ply .stl, any case); a file whose first bytes contradict it is refused.
//! \param info if given, filled with the counts above
//! \param attributes if given, filled with colours and groups where the file has them
//! \throw ReadError (missing, unreadable, empty, unknown extension, malformed: the message names
//!        the line or record and what was expected; counts that lie; a vertex index out of
//!        range; no polygons)
//! \throw InvalidSoupError (a non-finite coordinate)
Soup read_soup(const std::string& path, ReadInfo* info = nullptr,
               MeshAttributes* attributes = nullptr);

//! The attributes of a repaired mesh: per-vertex colours through `mesh.vertex_origin`, per-face
//! colours through `mesh.face_origin` (the copies of a split vertex and the pieces of a split
//! face carry their original's colour), OBJ groups moved to the first output face of each (a
//! group left with no face gives way to the next one that starts there); the missing-colour flags
//! mapped the same way; the 3MF objects of the faces (`face_objects`) through `mesh.face_origin`
//! too; the OBJ vt/vn of the corners through `mesh.corner_origin` (carry_corner_attributes in
//! core/src/io/formats.h: a corner repair inserted into a side is interpolated between its ends,
//! a corner of an added face has none); channels, `material_libraries`, the vt/vn counts,
//! `double_precision`, `length_unit` and `metadata` kept. An origin outside the input (kNoIndex: a
//! face added by hole filling) gets the default colour and is flagged as having none. The result
//! belongs to `mesh` itself, element by element: it is for callers that keep attributes per output
//! element. write_mesh() takes the input's attributes and maps them itself; handing it these
//! instead would map them twice. \pre `mesh.face_origin` is non-decreasing (repair keeps the face
//! order; added faces, marked kNoIndex, come last)
MeshAttributes carry_attributes(const MeshAttributes& input, const IndexedMesh& mesh);

//! What write_mesh() leaves out when it writes a mesh read with `attributes` to `path` (format
//! by extension), as far as the attributes tell: one phrase per kind, e.g. "24 texture
//! coordinates (vt) and 8 normals (vn) not written: PLY holds none per corner (write OBJ to keep
//! them)" (OBJ writes them), "face colours not
//! written: STL holds none", "3 vertices without a colour written white: PLY gives every vertex a
//! colour or none", "OBJ groups and materials not written (2 o/g/usemtl lines, 1 mtllib line):
//! PLY holds none", and each NotKept of the attributes. Empty when the output holds all
//! MeshBridge read. describe_written() adds what only the mesh tells (rounding to floats).
std::vector<std::string> describe_unwritten(const std::string& path,
                                            const MeshAttributes& attributes);

//! What a soup alone (positions and polygons: Soup, the Python module's Soup) does not hold of
//! a file read with `attributes`, one phrase per kind: "vertex colours (8 vertices)", "face
//! colours (6 faces)", "OBJ groups and materials (2 o/g/usemtl lines, 1 mtllib line)", "24 texture
//! coordinates (vt)", "8 normals (vn)", and each NotKept ("PLY vertex properties nx, ny, nz, on 8
//! vertices"). Empty when the file held nothing else.
std::vector<std::string> describe_not_held(const MeshAttributes& attributes);

//! What write_mesh() makes of a mesh beyond its polygons (describe_written()).
struct WrittenOutput {
  //! Triangles written, for formats that hold triangles only (STL, 3MF); 0 for the others.
  std::size_t triangles = 0;
  //! Polygons of more than 3 corners cut into triangles there (ear clipping in their plane, so
  //! a non-convex polygon stays covered by its own area; 0 for the other formats).
  std::size_t polygons_triangulated = 0;
  //! What the format left out of what was read, one phrase each (describe_unwritten()).
  std::vector<std::string> left_out;
  //! STL: copies of split vertices moved apart before writing (separate_copies_for_stl()), so
  //! that a reader's weld by position keeps the repair; 0 for the other formats or when off.
  std::size_t copies_moved = 0;
  double separation = 0;  //!< how far each of them moved (model units); 0 when none moved
};

//! What write_mesh(path, mesh with `soup`, &attributes) makes of it: the triangles and triangulated
//! polygons of a format that holds triangles only (.stl, .3mf); describe_unwritten(); there, the
//! vertices with a coordinate that is not exactly a 32-bit float ("positions of 12 vertices
//! rounded to 32-bit floats: STL holds no more"); and, when the input had vertex colours and
//! repair welded `vertices_welded` vertices (RepairReport::gaps), that their colours gave way.
WrittenOutput describe_written(const std::string& path, const Soup& soup,
                               const MeshAttributes& attributes, std::size_t vertices_welded = 0);
//! describe_written() of the mesh write_mesh(path, mesh, &attributes) wrote: the same; for an OBJ
//! output whose input corners had vt or vn, the faces hole filling added, written without ("2
//! faces added by hole filling written without texture coordinates (vt) and normals (vn): they
//! have no input corner to take them from"); and
//! where the faces are of several 3MF objects (MeshAttributes::face_objects, mapped through
//! `mesh.face_origin`), a 3MF output's rounding is measured object by object.
WrittenOutput describe_written(const std::string& path, const IndexedMesh& mesh,
                               const MeshAttributes& attributes, std::size_t vertices_welded = 0);

//! True if write_mesh and write_file_atomically write `path` in place rather than through a
//! temporary file renamed over it: a path under /dev/ (/dev/stdout, /dev/null) or an existing
//! file that is neither a regular file nor a folder (a device, a FIFO).
bool written_in_place(const std::string& path);
//! The file that writing `path` replaces: the file a symbolic link at `path` points to (the
//! link stays), else `path` itself.
std::string replaced_file(const std::string& path);

//! The mesh file formats, by extension.
enum class MeshFormat { unknown, obj, off, ply, stl, threemf };

//! The format of `path` by its extension (.obj .off .ply .stl .3mf, any case); unknown without
//! one or for any other. The one place a path's extension is read.
MeshFormat mesh_format(const std::string& path);

//! True if `path` has an extension read_soup/write_mesh handle (mesh_format() is not unknown).
bool is_supported_mesh_file(const std::string& path);

//! Writes a file the way write_mesh does (MeshBridge's one atomic-write helper): `fill` writes
//! the whole content to the temporary path it is given (a unique name beside `path`), which is
//! then renamed over `path`. If `fill` throws, the temporary file is removed, `path` is
//! untouched and the exception is passed on. A device or pipe `path` is written in place (`fill`
//! is given `path` itself). For callers that write through a library taking a file name (a PNG
//! through Qt, a report).
//! \throw WriteError naming `path` (no directory, no permission, rename failed)
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& fill);
//! write_file_atomically for content already in memory.
void write_bytes_atomically(const std::string& path, std::string_view bytes);

//! How write_mesh writes where a format has a choice.
struct WriteOptions {
  bool binary = true;  //!< PLY and STL: binary (default) or ASCII; OBJ and OFF are always text
  //! PLY: positions as `double` always (default false: `double` only if the attributes say
  //! the input had doubles or some coordinate is not exactly a float, so a write never rounds a
  //! position; `float` otherwise). Text formats always write the shortest exact text of each
  //! double; STL holds 32-bit floats only.
  bool double_precision = false;
};

//! Writes `mesh` by the format of the extension. Text formats write each coordinate as the
//! shortest decimal that reads back to the same double. STL and 3MF get triangles
//! (polygons cut by ear clipping in their plane: the triangles cover the polygon, not more).
//! Colours of `attributes` (of the soup `mesh` came from) are carried through `vertex_origin`
//! and `face_origin` where the format holds them (OFF faces, PLY vertices and faces); a face
//! with origin kNoIndex (added by hole filling) gets the default colour. OBJ also gets the
//! attributes' `vt`/`vn` records and each corner's through `corner_origin` (see
//! carry_attributes(); a face gets vt (vn) only when all its corners have one).
//! The file is written under a unique temporary name beside `path` and renamed on success, so
//! on any error the previous file at `path` is untouched and no temporary file stays. A `path`
//! that is a device or a pipe (/dev/stdout, a FIFO) is written in place, never replaced
//! (written_in_place()); through a symbolic link, the file it points to is replaced.
//! \throw InvalidSoupError naming the path and the face, corner or vertex when `mesh.soup` fails
//!        validate_soup() (nothing is written)
//! \throw WriteError naming the path and the reason
void write_mesh(const std::string& path, const IndexedMesh& mesh,
                const MeshAttributes* attributes = nullptr, const WriteOptions& options = {});

}  // namespace meshbridge
