// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/obj_parts.h"

#include "io/formats.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace meshbridge::detail {

namespace {

// Counts 'v' and 'f' records (and the blanks of the 'f' lines, a bound on their corners) with
// memchr, to reserve the soup (see estimate_records).
RecordCounts count_records(const char* p, const char* end) {
  RecordCounts n;
  while (p < end) {
    const char* line_end = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (line_end == nullptr)
      line_end = end;
    if (line_end - p >= 2 && (p[1] == ' ' || p[1] == '\t')) {
      if (p[0] == 'v') {
        ++n.vertices;
      } else if (p[0] == 'f') {
        ++n.faces;
        n.corners += static_cast<std::size_t>(std::count(p + 1, line_end, ' '));
      }
    }
    if (line_end == end)
      break;
    p = line_end + 1;
  }
  return n;
}

// Appends the part's vt/vn records and its corners' records (its first corner `corner_base` of
// the file), resolving its relative indices from the records before it (`attributes`' counts).
void append_corner_attributes(ObjPart& part, std::size_t corner_base, MeshAttributes& attributes) {
  CornerAttributes& kept = attributes.corners;
  CornerAttributes& given = part.attributes.corners;
  const std::int64_t before[2] = {static_cast<std::int64_t>(attributes.texture_coordinates),
                                  static_cast<std::int64_t>(attributes.normals)};
  for (int slot = 0; slot < 2; ++slot) {
    std::vector<Index>& records = slot == 0 ? given.corner_texture : given.corner_normal;
    for (const auto& [corner, offset] : part.relative.attributes[slot]) {
      const std::int64_t record = before[slot] + offset;
      records[corner] = record >= 0 ? static_cast<Index>(record) : kNoIndex;
    }
    if (records.empty())
      continue;
    std::vector<Index>& out = slot == 0 ? kept.corner_texture : kept.corner_normal;
    out.resize(corner_base, kNoIndex);
    out.insert(out.end(), records.begin(), records.end());
  }
  kept.texture_coordinates.insert(kept.texture_coordinates.end(), given.texture_coordinates.begin(),
                                  given.texture_coordinates.end());
  kept.normals.insert(kept.normals.end(), given.normals.begin(), given.normals.end());
  kept.texture_components = std::max(kept.texture_components, given.texture_components);
}

}  // namespace

void rescale_unit_colors(const ColorScale& scale, MeshAttributes& attributes) {
  if (!scale.bytes)
    return;
  const auto as_byte = [](std::uint8_t& channel) {
    channel = static_cast<std::uint8_t>(std::lround(channel / 255.0));  // the value as written
  };
  for (const auto& [v, alpha] : scale.unit) {
    if (v >= attributes.vertex_colors.size())
      continue;
    Rgba& c = attributes.vertex_colors[v];
    as_byte(c.r);
    as_byte(c.g);
    as_byte(c.b);
    if (alpha)
      as_byte(c.a);
  }
}

void add_not_kept(MeshAttributes& attributes, const NotKept& n) {
  for (NotKept& known : attributes.not_kept) {
    if (known.what == n.what) {
      known.count += n.count;
      return;
    }
  }
  attributes.not_kept.push_back(n);
}

// The start of the line at or after `p` that does not continue the line before it (a line
// before it ending in a backslash, '\r' aside).
const char* line_start_after(const char* p, const char* first, const char* end) {
  while (p < end && p > first && p[-1] != '\n')
    ++p;
  for (;;) {
    const char* q = p - 1;  // the '\n' before p (or p is the start/end)
    if (p >= end || p <= first)
      return p;
    while (q > first && q[-1] == '\r')
      --q;
    if (q == first || q[-1] != '\\')
      return p;
    const char* next = static_cast<const char*>(std::memchr(p, '\n', end - p));
    p = next == nullptr ? end : next + 1;
  }
}

// The record counts of [first, last), to reserve the soup once. A small range is counted; a
// large one is counted in kSlices stretches spread evenly over it (about 2 MiB in all) and scaled
// to its size with a margin, so the file is read once, not twice. (A file whose lines differ
// much from one stretch to the next can still exceed the estimate: the arrays then grow.)
RecordCounts estimate_records(const char* first, const char* last) {
  constexpr std::size_t kCountBelow = std::size_t(8) << 20;
  constexpr std::size_t kSlices = 32, kSlice = std::size_t(64) << 10;
  const std::size_t size = static_cast<std::size_t>(last - first);
  if (size <= kCountBelow)
    return count_records(first, last);
  RecordCounts sampled;
  std::size_t sampled_bytes = 0;
  for (std::size_t k = 0; k < kSlices; ++k) {
    const char* a = line_start_after(first + size / kSlices * k, first, last);
    const char* b = line_start_after(a + std::min<std::size_t>(kSlice, last - a), first, last);
    const RecordCounts n = count_records(a, b);
    sampled.vertices += n.vertices;
    sampled.faces += n.faces;
    sampled.corners += n.corners;
    sampled_bytes += static_cast<std::size_t>(b - a);
  }
  const double scale = 1.2 * static_cast<double>(size) /
                       static_cast<double>(std::max<std::size_t>(sampled_bytes, 1));
  const auto scaled = [scale](std::size_t n) {
    return static_cast<std::size_t>(scale * static_cast<double>(n)) + 64;
  };
  return {scaled(sampled.vertices), scaled(sampled.faces), scaled(sampled.corners)};
}

bool append_part(ObjPart& part, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  // The vertices read before the part (not soup.num_vertices(): a welding read keeps them out of
  // the soup, see PositionTable).
  const std::int64_t vertices_before = static_cast<std::int64_t>(info.declared_vertices);
  if (vertices_before + part.relative.lowest < 0)
    return false;
  const Index corner_base = static_cast<Index>(soup.num_corners());
  const Index face_base = static_cast<Index>(soup.num_faces());
  for (const auto& [corner, offset] : part.relative.corners)
    part.soup.corner_vertices[corner] = static_cast<Index>(vertices_before + offset);
  if (attributes != nullptr) {
    auto& colors = attributes->vertex_colors;
    auto& missing = attributes->vertex_color_missing;
    const auto& part_colors = part.attributes.vertex_colors;
    const auto& part_missing = part.attributes.vertex_color_missing;
    const std::size_t vertices_after = soup.num_vertices() + part.soup.num_vertices();
    if (!colors.empty() || !part_colors.empty()) {
      pad_missing_colors(colors, missing, soup.num_vertices());
      if (!part_colors.empty()) {  // the part's colours cover all of its vertices
        if (!missing.empty() || !part_missing.empty()) {
          missing.resize(colors.size(), false);
          if (part_missing.empty())
            missing.resize(vertices_after, false);
          else
            missing.insert(missing.end(), part_missing.begin(), part_missing.end());
        }
        colors.insert(colors.end(), part_colors.begin(), part_colors.end());
      }
      pad_missing_colors(colors, missing, vertices_after);
    }
    attributes->vertex_color_channels |= part.attributes.vertex_color_channels;
    append_corner_attributes(part, soup.num_corners(), *attributes);
    attributes->texture_coordinates += part.attributes.texture_coordinates;
    attributes->normals += part.attributes.normals;
    for (std::string& library : part.attributes.material_libraries)
      attributes->material_libraries.push_back(std::move(library));
    for (const NotKept& n : part.attributes.not_kept)
      add_not_kept(*attributes, n);
    for (FaceGroup& group : part.attributes.face_groups) {
      group.first_face += face_base;
      attributes->face_groups.push_back(std::move(group));
    }
  }
  soup.positions.insert(soup.positions.end(), part.soup.positions.begin(),
                        part.soup.positions.end());
  if (soup.num_faces() == 0 && soup.num_corners() == 0) {
    // No face before the part (a file of all its v records first, in parts of about one MB):
    // its arrays are taken as they are, not copied.
    soup.corner_vertices = std::move(part.soup.corner_vertices);
    soup.face_begin = std::move(part.soup.face_begin);
  } else {
    soup.corner_vertices.insert(soup.corner_vertices.end(), part.soup.corner_vertices.begin(),
                                part.soup.corner_vertices.end());
    for (std::size_t f = 1; f < part.soup.face_begin.size(); ++f)
      soup.face_begin.push_back(corner_base + part.soup.face_begin[f]);
  }
  info.declared_vertices += part.info.declared_vertices;
  info.declared_faces += part.info.declared_faces;
  info.faces_without_corners += part.info.faces_without_corners;
  info.dangling_edges += part.info.dangling_edges;
  info.lone_points += part.info.lone_points;
  info.unknown_records += part.info.unknown_records;
  info.empty_records += part.info.empty_records;
  part = ObjPart();  // its memory goes back before the next part is appended
  return true;
}

}  // namespace meshbridge::detail
