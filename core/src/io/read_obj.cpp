// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ reader: the file read by ObjReader (obj_reader.h) in one part, or in parts side by side
// (obj_parts.h) for a large file; then what only the whole file tells (indices past its records).

#include "io/formats.h"
#include "io/huge_pages.h"
#include "io/obj_parts.h"
#include "io/obj_reader.h"
#include "io/obj_weld.h"
#include "meshbridge/errors.h"
#include "parallel_parts.h"

#include <algorithm>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

//! Reads the file in `n` parts side by side: part 0 into `soup`, the others into their own soups
//! appended in file order. False (outputs to be reset) if a part met an error or a negative
//! index that reaches before the file's first vertex: the one-thread read names it. Where the
//! file looks written per face vertex, each part welds its positions as it reads them; if every
//! part did, `weld` holds the file's vertices and `soup` no positions (PositionTable::finish).
bool read_in_parts(const MappedFile& file, unsigned n, Soup& soup, ReadInfo& info,
                   MeshAttributes* attributes, AttributeIndices& attribute_indices,
                   ColorScale& color_scale, PositionTable& weld, bool& welding) {
  std::vector<ObjPart> parts(n);
  for (unsigned k = 0; k < n; ++k) {
    parts[k].first = k == 0 ? after_byte_order_mark(file.data(), file.end()) : parts[k - 1].last;
    parts[k].last = k + 1 == n ? file.end()
                               : line_start_after(file.data() + part_begin(file.size(), n, k + 1),
                                                  file.data(), file.end());
    parts[k].last = std::max(parts[k].last, parts[k].first);
  }
  std::vector<char> failed(n, 0);  // one byte per part: written by the parts' threads
  run_parts(n, [&](unsigned k) {
    ObjPart& part = parts[k];
    part.counts = estimate_records(part.first, part.last);
  });
  RecordCounts total;
  for (const ObjPart& part : parts) {
    total.vertices += part.counts.vertices;
    total.faces += part.counts.faces;
    total.corners += part.counts.corners;
  }
  welding = PositionTable::pays_for(total);
  std::vector<PositionTable> tables(welding ? n : 0);
  std::vector<char> welded(n, 0);  // whether part k's reader welded all its vertices
  reserve_huge(soup, welding ? 0 : total.vertices, total.faces, total.corners);
  run_parts(n, [&](unsigned k) {
    ObjPart& part = parts[k];
    try {
      if (k == 0) {
        ObjReader reader(file, part.first, part.last, soup, info, attributes);
        if (welding) {
          tables[0].reserve(total.vertices);
          reader.weld_into(&tables[0]);
        }
        reader.read();
        welded[0] = reader.welding();
        part.attribute_indices = reader.attribute_indices();
        part.color_scale = reader.take_color_scale();
      } else {
        reserve_huge(part.soup, welding ? 0 : part.counts.vertices, part.counts.faces,
                     part.counts.corners);
        ObjReader reader(file, part.first, part.last, part.soup, part.info,
                         attributes != nullptr ? &part.attributes : nullptr, &part.relative);
        if (welding) {
          tables[k].reserve(part.counts.vertices);
          reader.weld_into(&tables[k]);
        }
        reader.read();
        welded[k] = reader.welding();
        part.attribute_indices = reader.attribute_indices();
        part.color_scale = reader.take_color_scale();
      }
    } catch (const ReadError&) {
      failed[k] = 1;
    }
  });
  // Welded while read only if every part was: else each part's positions are put back.
  welding = welding && std::all_of(welded.begin(), welded.end(), [](char w) { return w != 0; });
  for (unsigned k = 0; k < tables.size(); ++k) {
    if (welding && k > 0)
      tables[0].append(tables[k]);
    else if (!welding && welded[k])
      tables[k].put_back(k == 0 ? soup.positions : parts[k].soup.positions);
    if (k > 0)
      tables[k] = PositionTable();
  }
  if (welding)
    weld = std::move(tables[0]);
  // The vt/vn indices of the whole file: relative ones of a part from the records before it.
  std::int64_t before[2] = {0, 0};
  for (unsigned k = 0; k < n; ++k) {
    const AttributeIndices& part = parts[k].attribute_indices;
    attribute_indices.zero = attribute_indices.zero || part.zero;
    attribute_indices.highest_element_vertex =
        std::max(attribute_indices.highest_element_vertex, part.highest_element_vertex);
    for (int slot = 0; slot < 2; ++slot) {
      attribute_indices.highest[slot] =
          std::max(attribute_indices.highest[slot], part.highest[slot]);
      attribute_indices.lowest[slot] =
          std::min(attribute_indices.lowest[slot], before[slot] + part.lowest[slot]);
    }
    const MeshAttributes& counted =
        k == 0 && attributes != nullptr ? *attributes : parts[k].attributes;
    before[0] += static_cast<std::int64_t>(counted.texture_coordinates);
    before[1] += static_cast<std::int64_t>(counted.normals);
  }
  // The colour scale of the whole file, its vertices numbered in the file (before appending:
  // part 0 read into `soup` itself, and appending empties a part).
  std::size_t first_vertex = 0;
  for (unsigned k = 0; k < n; ++k) {
    const ColorScale& part = parts[k].color_scale;
    color_scale.bytes = color_scale.bytes || part.bytes;
    for (const auto& [v, alpha] : part.unit)
      color_scale.unit.emplace_back(static_cast<Index>(first_vertex + v), alpha);
    first_vertex += k == 0 ? soup.num_vertices() : parts[k].soup.num_vertices();
  }
  for (unsigned k = 0; k < n; ++k) {
    if (failed[k] || (k > 0 && !append_part(parts[k], soup, info, attributes)))
      return false;
  }
  return true;
}

}  // namespace

void throw_obj_index_out_of_range(const MappedFile& file, const ObjIndexOutOfRange& where) {
  Soup soup;
  ReadInfo info;
  ObjReader(file, after_byte_order_mark(file.data(), file.end()), file.end(), soup, info, nullptr)
      .locate(where);
}

void read_obj(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  // Parts of less than 1 MiB cost more to start and append than they save.
  const unsigned n = static_cast<unsigned>(
      std::clamp<std::size_t>(file.size() / (std::size_t(1) << 20), 1, worker_threads()));
  bool read = false;
  AttributeIndices attribute_indices;
  ColorScale color_scale;
  PositionTable weld;  // the vertices, where the file is welded while read
  bool welding = false;
  if (n > 1) {
    read = read_in_parts(file, n, soup, info, attributes, attribute_indices, color_scale, weld,
                         welding);
    if (!read) {
      weld = PositionTable();
      welding = false;
      soup = Soup();
      info = ReadInfo();
      attribute_indices = AttributeIndices();
      color_scale = ColorScale();
      if (attributes != nullptr)
        *attributes = MeshAttributes();
    }
  }
  if (!read) {
    const RecordCounts counts = estimate_records(file.data(), file.end());
    welding = PositionTable::pays_for(counts);
    reserve_huge(soup, welding ? 0 : counts.vertices, counts.faces, counts.corners);
    ObjReader reader(file, after_byte_order_mark(file.data(), file.end()), file.end(), soup, info,
                     attributes);
    if (welding) {
      weld.reserve(counts.vertices);
      reader.weld_into(&weld);
    }
    reader.read();
    welding = reader.welding();
    attribute_indices = reader.attribute_indices();
    color_scale = reader.take_color_scale();
  }
  // An l or p corner past the last vertex: an error naming its line, as for faces.
  const std::size_t vertices = welding ? weld.vertices() : soup.num_vertices();
  if (attribute_indices.highest_element_vertex > std::int64_t(vertices)) {
    Soup again;
    ReadInfo ignored;
    ObjReader(file, after_byte_order_mark(file.data(), file.end()), file.end(), again, ignored,
              nullptr)
        .locate_element_vertex_past(vertices);
  }
  // A file welded while read: the weld done (as weld_repeated_vertices() would), or the positions
  // as read put back for it.
  if (welding)
    info.vertices_welded_by_position = weld.finish(soup);
  if (attributes == nullptr)
    return;
  rescale_unit_colors(color_scale, *attributes);
  // A vt or vn index the file has no record for: counted by reading the file once more (only
  // such a broken file pays for it), and named as a fault.
  const std::size_t totals[2] = {attributes->texture_coordinates, attributes->normals};
  bool faulty = attribute_indices.zero;
  for (int slot = 0; slot < 2; ++slot) {
    faulty = faulty || attribute_indices.lowest[slot] < 0 ||
             attribute_indices.highest[slot] > static_cast<std::int64_t>(totals[slot]);
  }
  if (faulty) {
    Soup again;
    ReadInfo ignored;
    const std::size_t corners = ObjReader(file, after_byte_order_mark(file.data(), file.end()),
                                          file.end(), again, ignored, nullptr)
                                    .count_attribute_index_faults(totals);
    add_not_kept(*attributes,
                 {"OBJ texture coordinate (vt) or normal (vn) indices the file has no record for",
                  corners, "corner", true});
    // Such a corner has no texture coordinate or normal (negative ones are none already).
    CornerAttributes& kept = attributes->corners;
    for (int slot = 0; slot < 2; ++slot) {
      for (Index& record : slot == 0 ? kept.corner_texture : kept.corner_normal) {
        if (record != kNoIndex && record >= totals[slot])
          record = kNoIndex;
      }
    }
  }
  // Corners after the last one with a vt or vn (in the last part read) have none.
  for (std::vector<Index>* records :
       {&attributes->corners.corner_texture, &attributes->corners.corner_normal}) {
    if (!records->empty())
      records->resize(soup.num_corners(), kNoIndex);
  }
}

}  // namespace meshbridge::detail
