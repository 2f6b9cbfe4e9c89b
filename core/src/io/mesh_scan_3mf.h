// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A direct scan of a 3MF mesh's vertex and triangle lists (3MF Core Specification 1.2, section
// 4.1.1) as writers put them: <vertex x="1.5" y="-2" z="0"/> and <triangle v1="0" v2="1"
// v3="2"/>, separated by whitespace only. It reads what pugixml would read from such a list, to
// the bit, about three times as fast (no copy of the text, no tree), and gives up at the first
// byte outside that narrow form: a comment, an entity, another attribute, a space around '=',
// a number it does not take whole, a value that the pugixml route refuses. The caller then reads
// the same text with pugixml (mesh_xml_3mf.cpp), which decides.

#include "meshbridge/soup.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshbridge::detail {

//! Appends every vertex of the list text [begin, end) to `positions` (x, y, z each read as a
//! double and rounded to a float, as lib3mf does, held as doubles); false (and `positions` as it
//! was) where the text leaves that narrow form.
bool scan_vertices(const char* begin, const char* end, std::vector<Point>& positions);

//! Appends v1, v2, v3 of every triangle of the list text [begin, end) to `corners`, each below
//! `vertex_count` and no two the same; false (and `corners` as it was) where the text leaves that
//! narrow form or a triangle breaks those rules.
bool scan_triangles(const char* begin, const char* end, std::size_t vertex_count,
                    std::vector<std::uint32_t>& corners);

//! As scan_vertices(), for text that may go on past `end` (a chunk of a stream): appends every
//! vertex of [begin, end) up to the first element it does not read whole, and returns where that
//! element begins (`end` when it read them all). The element may be one `end` cuts off, the end
//! tag of the list, or one that leaves the narrow form; the caller tells them apart.
const char* scan_vertices_until(const char* begin, const char* end, std::vector<Point>& positions);

//! As scan_triangles(), for text that may go on past `end`, as scan_vertices_until() reads it.
const char* scan_triangles_until(const char* begin, const char* end, std::size_t vertex_count,
                                 std::vector<std::uint32_t>& corners);

}  // namespace meshbridge::detail
