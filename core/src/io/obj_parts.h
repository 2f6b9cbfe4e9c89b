// SPDX-License-Identifier: GPL-3.0-or-later
// An OBJ file read in parts side by side (read_obj.cpp): where a part may begin, how many
// records to reserve for, and how a part read on its own is appended to the parts before it.

#pragma once

#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshbridge::detail {

//! Where a part of the file (after the first) refers to vertices relative to its own start.
struct RelativeCorners {
  //! (soup corner, vertices read in the part before it + its negative index) of every face
  //! corner given as a negative index: its vertex is (vertices before the part) + that offset.
  std::vector<std::pair<std::size_t, std::int64_t>> corners;
  std::int64_t lowest = 0;  //!< lowest offset of any relative index (faces, l, p), or 0
  //! (soup corner, vt (0) / vn (1) records read in the part before it + its negative index) of
  //! every face corner whose vt / vn index is negative: its record is (records of the kind
  //! before the part) + that offset, none if that is below 0.
  std::vector<std::pair<std::size_t, std::int64_t>> attributes[2];
};

//! The texture coordinate (vt, slot 0) and normal (vn, slot 1) indices of the corners a reader
//! met, to tell whether some name a record the file does not have (which is then counted by
//! reading the file again: see count_attribute_index_faults).
struct AttributeIndices {
  std::int64_t highest[2] = {0, 0};  //!< highest positive index (1-based)
  //! Lowest (records of the kind read before, in this reader + negative index): below 0 where a
  //! relative index reaches before the reader's first record.
  std::int64_t lowest[2] = {0, 0};
  bool zero = false;  //!< some index is 0 (OBJ counts from 1, or from -1 back)
  //! Highest positive vertex index of an `l` or `p` corner (faces are checked by
  //! account_faces; these are counted, not kept, so they are checked here).
  std::int64_t highest_element_vertex = 0;
};

//! The scale of OBJ vertex colours written as whole numbers: a colour of whole numbers with one
//! above 1 is 0..255 (as some exporters write them), and in a file with such a colour, colours
//! of 0s and 1s are 0..255 too ("1 1 1" is near black, not white). A reader notes what it met;
//! rescale_unit_colours() applies the file's scale at the end.
struct ColorScale {
  bool bytes = false;  //!< some colour was whole numbers with one above 1
  //! The vertices (0-based, in the reader's soup) whose colour is 0s and 1s, read as 0..1, and
  //! whether it gave alpha.
  std::vector<std::pair<Index, bool>> unit;
};

//! In a file with some 0..255 colour (`scale.bytes`), reads the colours of 0s and 1s as 0..255
//! too: a channel of "1" is 1, not 255. Nothing otherwise.
void rescale_unit_colors(const ColorScale& scale, MeshAttributes& attributes);

//! How many `v` and `f` records, and face corners at most, a range of an OBJ file holds.
struct RecordCounts {
  std::size_t vertices = 0, faces = 0, corners = 0;
};

//! The start of the line at or after `p` that does not continue the line before it (a line
//! before it ending in a backslash, '\r' aside), within [first, end].
const char* line_start_after(const char* p, const char* first, const char* end);

//! The record counts of [first, last), to reserve the soup once: counted in a small range,
//! sampled and scaled (with a margin) in a large one, so that the file is read once.
RecordCounts estimate_records(const char* first, const char* last);

//! One part of the file read on its own thread (parts after the first).
struct ObjPart {
  const char* first = nullptr;
  const char* last = nullptr;
  RecordCounts counts;
  Soup soup;
  ReadInfo info;
  MeshAttributes attributes;
  RelativeCorners relative;
  AttributeIndices attribute_indices;
  ColorScale color_scale;
};

//! Adds `n` to the attributes' list, or its count to an entry about the same thing (parts).
void add_not_kept(MeshAttributes& attributes, const NotKept& n);

//! Appends part `part` (read after `soup`'s vertices and faces) to `soup`, `info`, `attributes`.
//! False if one of its negative indices points before the first vertex of the file.
bool append_part(ObjPart& part, Soup& soup, ReadInfo& info, MeshAttributes* attributes);

}  // namespace meshbridge::detail
