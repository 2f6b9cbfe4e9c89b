// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file io.h
//! Files in and out through OpenMesh's own readers and writers (OBJ, OFF, PLY, STL).

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <string>

namespace meshbridge {

//! What the file declared next to what OpenMesh's reader passed on.
struct ReadInfo {
  std::size_t declared_vertices = 0;  //!< 'v' records (OBJ) or header count (OFF, PLY); 0: unknown
  std::size_t declared_faces = 0;     //!< 'f' records (OBJ) or header count (OFF, PLY); 0: unknown
  std::size_t faces_dropped_by_reader = 0;  //!< declared faces the reader never passed on
  std::size_t faces_kept = 0;       //!< polygons in the soup as the file had them
  std::size_t faces_split = 0;      //!< pinched polygons split into simple ones
  std::size_t faces_set_aside = 0;  //!< face records with < 3 distinct corners, not in the soup
  std::size_t dangling_edges = 0;   //!< edge records (OBJ `l`, PLY `edge`), not in the soup
  std::size_t lone_points = 0;      //!< point records (OBJ `p`), not in the soup
};

//! Reads the raw soup of a mesh file: every vertex and polygon as the file has them, captured by
//! a custom OpenMesh importer, so nothing is refused or duplicated on the way in. STL is welded
//! by exact position (OpenMesh's STL reader).
//! \throw ReadError (missing, unreadable, empty, unknown extension, malformed, no polygons)
//! \throw InvalidSoupError (index out of range, non-finite coordinate, polygon with < 3 corners)
//! OpenMesh's OBJ reader skips face records with fewer than 3 distinct vertices without a word;
//! `info` (if given) counts them, so callers can say so. Fewer vertices than declared (e.g. an
//! unparseable coordinate such as "nan") is a ReadError, since every later index would shift.
Soup read_soup(const std::string& path, ReadInfo* info = nullptr);

//! True if `path` has an extension read_soup/write_mesh handle (.obj .off .ply .stl, any case).
bool is_supported_mesh_file(const std::string& path);

//! Writes `mesh` through OpenMesh's writer chosen by the extension, positions with 17 digits.
//! The file is written under a temporary name beside `path` and renamed on success, so on any
//! error the previous file at `path` is untouched. STL gets triangles (polygons are fanned).
//! \throw WriteError naming the path and the reason
void write_mesh(const std::string& path, const IndexedMesh& mesh);

}  // namespace meshbridge
