// SPDX-License-Identifier: GPL-3.0-or-later
// Where an ascii PLY body stops matching its header, line by line: read only after the reader
// (which takes values as words, whatever the line breaks) has failed, to name the line.

#pragma once

#include "io/ply_header.h"

#include <optional>
#include <string>
#include <string_view>

namespace meshbridge::detail {

//! The first line of the ascii PLY body of `file` (header `header`) whose values do not match
//! the properties its element declares, as "line 12, vertex 2 of 3: 4 values where the header's
//! properties (x, y, z) take 3" (or: the line ends before a property, a list is shorter than its
//! count, a value is no number, a polygon corner no integer, or the file ends before an item).
//! Lines are counted from 1 at the start of the file; a body with one element item per line, as the
//! PLY format writes it, is assumed (blank lines skipped). An empty result when every line matches
//! (the fault is elsewhere: a count past the end).
std::optional<std::string> locate_ascii_ply_mismatch(std::string_view file,
                                                     const PlyHeader& header);

//! The line (counted from 1) of item `item` of element `element` (an index into
//! header.elements) in the ascii PLY body of `file`, one item per non-blank line as above; 0 if
//! the file ends before it.
std::size_t ascii_ply_item_line(std::string_view file, const PlyHeader& header, std::size_t element,
                                std::uint64_t item);

}  // namespace meshbridge::detail
