// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file io.h
//! Files in and out through OpenMesh's own readers and writers (OBJ, OFF, PLY, STL).

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/soup.h"

#include <string>

namespace meshbridge {

//! Reads the raw soup of a mesh file: every vertex and polygon as the file has them, captured by
//! a custom OpenMesh importer, so nothing is refused or duplicated on the way in. STL is welded
//! by exact position (OpenMesh's STL reader).
//! \throw ReadError (missing, unreadable, empty, unknown extension, malformed, no polygons)
//! \throw InvalidSoupError (index out of range, non-finite coordinate, polygon with < 3 corners)
Soup read_soup(const std::string& path);

//! True if `path` has an extension read_soup/write_mesh handle (.obj .off .ply .stl, any case).
bool is_supported_mesh_file(const std::string& path);

//! Writes `mesh` through OpenMesh's writer chosen by the extension, positions with 17 digits.
//! The file is written under a temporary name beside `path` and renamed on success, so on any
//! error the previous file at `path` is untouched. STL gets triangles (polygons are fanned).
//! \throw WriteError naming the path and the reason
void write_mesh(const std::string& path, const IndexedMesh& mesh);

}  // namespace meshbridge
