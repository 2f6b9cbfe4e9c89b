// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The meshes of a 3MF model part (3MF Core Specification 1.2, section 4.1.1: <mesh>, <vertices>,
// <triangles>) read apart (a direct scan, mesh_scan_3mf.h; pugixml where it gives up), and the
// model part without them, for lib3mf to read the rest (build, components, transforms, types,
// metadata, materials). A 3MF of 1M triangles reads in about an eighth of lib3mf 1.8's CPU time
// (meshbridge-parse-bench read-3mf, 1M torus, one thread: 0.107 s streamed with ISA-L, 0.15 s
// inflated whole, against 0.88 s; pugixml alone 0.25 s; bench/results.md sections 15 and 16).

#include "meshbridge/soup.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

//! The mesh of one 3MF object as the file has it.
struct MeshXml {
  //! Each vertex as lib3mf reads it (floats), as the soup holds it (doubles): the first mesh's
  //! become the soup's without a copy (read_3mf.cpp).
  std::vector<Point> positions;
  std::vector<std::uint32_t> corners;  //!< v1, v2, v3 of each triangle
};

//! The model part `text` read: into
//! `meshes` the mesh of every object (by its id) whose mesh holds nothing but vertices and
//! triangles with their coordinates and indices (attributes of other namespaces are read past),
//! and into `stripped` the model part with those meshes emptied. A mesh that is anything else
//! (triangle properties, a beam lattice, an attribute of the core namespace this reader does
//! not know) stays in `stripped` for lib3mf. Returns false when the file is not for this
//! reader, and lib3mf should read it all: not well-formed XML, a coordinate that is no number or
//! beyond lib3mf's +-1e9, a triangle that names a vertex twice or one its mesh lacks (lib3mf
//! refuses such a file and names the fault).
bool read_meshes_xml(std::string_view text, std::map<std::uint32_t, MeshXml>& meshes,
                     std::string& stripped);

//! What became of a mesh's lists: read, left in the part for lib3mf, or refused (lib3mf is to
//! read the whole file and name the fault).
enum class ListOutcome { read, left_for_lib3mf, refused };

//! Reads the mesh whose vertex list is cut `vertices` and triangle list cut `triangles` into
//! `mesh` (`prefixes`: the namespace prefixes declared around it).
using ReadMesh =
    std::function<ListOutcome(std::size_t vertices, std::size_t triangles,
                              const std::vector<std::string>& prefixes, MeshXml& mesh)>;

//! The structure of a model part: the part with the content of every list ("<vertices>...
//! </vertices>", "<triangles>...</triangles>") cut out, `landed[c]` the offset of the '<' of
//! list c's start tag in it. Parsed by pugixml in place (`structure` is changed); for every
//! object whose mesh holds one vertex list and one triangle list and nothing else,
//! read_mesh() is asked, and a mesh it read goes into `meshes`, its two lists marked in `taken`
//! (by cut). False when pugixml refuses the structure or read_mesh() refuses a mesh.
bool read_structure(std::string& structure, const std::vector<std::size_t>& landed,
                    const ReadMesh& read_mesh, std::map<std::uint32_t, MeshXml>& meshes,
                    std::vector<bool>& taken);

//! The 3MF package in `data` (`size` bytes) for lib3mf to read, with the meshes of its root
//! model part emptied, their vertices and triangles read into `meshes`: as the part is inflated
//! (read_meshes_streamed(), with ISA-L), else by read_meshes_xml() (the part inflated whole by
//! libdeflate; the same meshes); empty, and `meshes` too, when lib3mf is to read the file
//! itself: not a package this route reads (no root model part, a second model part, a model
//! part read_meshes_xml() refuses) or no mesh it could read. Set MESHBRIDGE_3MF_MESHES=lib3mf
//! to have lib3mf read every file whole (read_3mf() asks), =whole to inflate the part whole
//! (never streamed), =pugixml for pugixml alone on the part inflated whole (no scan).
std::vector<unsigned char> package_without_meshes(const void* data, std::size_t size,
                                                  std::map<std::uint32_t, MeshXml>& meshes);

}  // namespace meshbridge::detail
