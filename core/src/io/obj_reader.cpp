// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/obj_reader.h"

#include "meshbridge/counted.h"
#include "meshbridge/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

namespace meshbridge::detail {

void ObjReader::locate_element_vertex_past(std::size_t vertices) {
  element_vertex_limit_ = &vertices;
  read();
  throw ReadError(file_.path() + ": an l or p corner past the last vertex not found again");
}

void ObjReader::locate(const ObjIndexOutOfRange& where) {
  locate_ = &where;
  read();
  throw ReadError(file_.path() + ": face " + std::to_string(where.face) + " not found again");
}

void ObjReader::read() {
  while (!in_.at_end()) {
    if (in_.position() - released_ > kReleaseEvery) {
      file_.release_between(released_, in_.position());
      released_ = in_.position();
    }
    const std::string_view keyword = in_.word();
    if (!keyword.empty() && keyword.front() == '#') {
      in_.skip_physical_line();  // a comment ending in '\' does not continue
      continue;
    }
    if (keyword == "v")
      vertex();
    else if (keyword == "vt")
      attribute_record(0);
    else if (keyword == "vn")
      attribute_record(1);
    else if (keyword == "f" || keyword == "fo")
      face();
    else if (keyword == "l")
      line_record();
    else if (keyword == "p")
      point_record();
    else if (keyword == "o" || keyword == "g" || keyword == "usemtl") {
      if (attributes_ != nullptr)
        attributes_->face_groups.push_back(
            FaceGroup{rest_of_line(keyword), static_cast<Index>(soup_.num_faces())});
    } else if (keyword == "mtllib") {
      if (attributes_ != nullptr)
        attributes_->material_libraries.push_back(rest_of_line(keyword));
    } else if (!keyword.empty() && !is_skipped_record(keyword)) {
      ++info_.unknown_records;
    }
    in_.next_line();  // anything else (mtllib, s, curves...): skipped
  }
  info_.declared_vertices = vertices();
  if (attributes_ != nullptr) {
    attributes_->vertex_color_channels = alpha_given_ ? kRgbaChannels : kRgbChannels;
    attributes_->texture_coordinates = texture_coordinates_;
    if (w_not_one_ > 0)
      add_not_kept(*attributes_, {"OBJ vertex w other than 1", w_not_one_, "vertex"});
    if (colors_clamped_ > 0) {
      add_not_kept(*attributes_, {"OBJ vertex colour values outside 0-1 (or 0-255) or not "
                                  "finite, clamped to the range",
                                  colors_clamped_, "vertex", true, true});
    }
    if (values_no_color_ > 0) {
      add_not_kept(*attributes_, {"OBJ numbers after a vertex that are no w or colour (5, or more "
                                  "than 7)",
                                  values_no_color_, "vertex", true});
    }
    if (attribute_records_bad_ > 0) {
      add_not_kept(*attributes_, {"OBJ vt or vn records with a value that is no number (kept as 0)",
                                  attribute_records_bad_, "line", true});
    }
    attributes_->normals = normals_;
    if (!attributes_->vertex_colors.empty())
      pad_missing_colors(attributes_->vertex_colors, attributes_->vertex_color_missing, vertices());
    // The corners after the last one with a vt or vn have none.
    for (std::vector<Index>* slots :
         {&attributes_->corners.corner_texture, &attributes_->corners.corner_normal}) {
      if (!slots->empty())
        slots->resize(soup_.num_corners(), kNoIndex);
    }
  }
}

void ObjReader::fail(const std::string& what) const {
  throw ReadError(file_.path() + ": line " + std::to_string(in_.line()) + ": " + what);
}

void ObjReader::vertex() {
  double values[7];
  int n = 0;
  while (n < 7 && !in_.at_line_end()) {
    if (!in_.number(values[n])) {
      const std::string_view bad = in_.word();
      fail("vertex " + std::to_string(vertices() + 1) + ": '" + clip(bad) +
           "' is not a number a double can hold (expected 'v x y z')");
    }
    ++n;
  }
  if (n < 3) {
    fail("vertex " + std::to_string(vertices() + 1) + " has " + std::to_string(n) +
         " coordinate(s), expected 3");
  }
  if (!std::isfinite(values[0]) || !std::isfinite(values[1]) || !std::isfinite(values[2])) {
    throw InvalidSoupError(file_.path() + ": line " + std::to_string(in_.line()) + ": vertex " +
                           std::to_string(vertices() + 1) +
                           " has a non-finite coordinate (nan or inf)");
  }
  const Point p(values[0], values[1], values[2]);
  if (weld_ != nullptr) {
    if (n == 3 && PositionTable::takes(p)) {
      weld_->add(p);  // no w, no colour: nothing more to note
      return;
    }
    weld_->put_back(soup_.positions);
    weld_ = nullptr;
  }
  soup_.positions.push_back(p);
  if (attributes_ == nullptr)
    return;
  // x y z r g b [a]: colours as floats in [0, 1], or 0..255 where they are whole numbers
  // and some is above 1 (as some exporters write them); in a file with such a colour, whole
  // numbers of 0 and 1 ("1 1 1") are 0..255 too (see ColourScale). A value with a fraction
  // is 0..1: "1.5" is clamped (and counted), never read as a byte. A vertex without a colour
  // has none.
  Rgba color;
  if (n >= 6) {
    const bool whole =
        std::all_of(values + 3, values + n, [](double v) { return v == std::floor(v); });
    const bool bytes = whole && *std::max_element(values + 3, values + n) > 1;
    if (bytes)
      color_scale_.bytes = true;
    else if (whole)  // 0s and 1s: the file's scale decides
      color_scale_.unit.emplace_back(static_cast<Index>(soup_.num_vertices() - 1), n == 7);
    const double top = bytes ? 255 : 1;
    colors_clamped_ +=
        std::any_of(values + 3, values + n, [top](double v) { return !(v >= 0 && v <= top); });
    color = Rgba{to_byte(values[3], bytes), to_byte(values[4], bytes), to_byte(values[5], bytes),
                 n == 7 ? to_byte(values[6], bytes) : std::uint8_t(255)};
  }
  push_color(attributes_->vertex_colors, attributes_->vertex_color_missing,
             soup_.num_vertices() - 1, n >= 6 ? &color : nullptr);
  alpha_given_ = alpha_given_ || n == 7;
  // Read past: a w other than 1 ("v x y z w"), and numbers that are neither w nor a colour.
  w_not_one_ += n == 4 && values[3] != 1;
  values_no_color_ += n == 5 || (n == 7 && !in_.at_line_end());
}

void ObjReader::attribute_record(int slot) {
  ++(slot == 0 ? texture_coordinates_ : normals_);
  if (attributes_ == nullptr)
    return;
  // vt u [v [w]] (v and w 0 when left out), vn x y z. Numbers after those are read past.
  std::array<double, 3> values{0, 0, 0};
  int n = 0;
  bool bad = false;
  while (n < 3 && !in_.at_line_end()) {
    if (!in_.number(values[n])) {
      bad = true;
      values = {0, 0, 0};
      break;
    }
    ++n;
  }
  CornerAttributes& corners = attributes_->corners;
  if (slot == 0) {
    bad = bad || n == 0;
    corners.texture_coordinates.push_back(values);
    corners.texture_components = std::max(corners.texture_components, bad ? 2 : n);
  } else {
    bad = bad || n < 3;
    corners.normals.push_back(bad ? std::array<double, 3>{0, 0, 0} : values);
  }
  attribute_records_bad_ += bad;
}

bool ObjReader::is_skipped_record(std::string_view keyword) {
  // The records of the OBJ format (Wavefront's specification, appendix B1) that carry nothing
  // MeshBridge keeps.
  static constexpr std::string_view kRecords[] = {
      "vp",       "s",        "mg",         "mtllib",    "usemap", "maplib", "lod",    "bevel",
      "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",  "stech",  "cstype", "deg",
      "bmat",     "step",     "curv",       "curv2",     "surf",   "parm",   "trim",   "hole",
      "scrv",     "sp",       "end",        "con",       "call",   "csh"};
  return std::find(std::begin(kRecords), std::end(kRecords), keyword) != std::end(kRecords);
}

std::uint8_t ObjReader::to_byte(double value, bool bytes) {
  const double scaled = bytes ? value : value * 255.0;
  const double clamped = std::isfinite(scaled) ? std::clamp(scaled, 0.0, 255.0) : 0.0;
  return static_cast<std::uint8_t>(std::lround(clamped));
}

std::string ObjReader::clip(std::string_view text) {
  std::string out(text.substr(0, 40));
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 32)
      c = '?';
  }
  return out;
}

Index ObjReader::corner(const char* what) {
  const std::string_view text = in_.word();
  const char* first = text.data();
  const char* last = first + text.size();
  std::int64_t index = 0;
  const char* end = parse_integer(first, last, index);
  if (end == nullptr) {
    const char* after_sign = first != last && (*first == '-' || *first == '+') ? first + 1 : first;
    const bool digits =
        after_sign != last && std::isdigit(static_cast<unsigned char>(*after_sign)) != 0;
    fail(std::string(what) + " corner '" + clip(text) + "' " +
         (digits ? std::string("is not an index MeshBridge can hold (beyond 64 bits)")
                 : std::string("has no vertex index") +
                       (first != last && *first == '/'
                            ? " before its texture coordinate or normal"
                            : " (expected 'v', 'v/vt', 'v//vn' or 'v/vt/vn')")));
  }
  // The texture coordinate and normal indices: their form checked here, their range noted
  // (attribute_index()), and of a face corner, with attributes, the records they name kept.
  bool names_no_record = false;
  for (int part = 0; end != last && part < 2; ++part) {
    if (*end != '/')
      break;
    ++end;
    std::int64_t attribute = 0;
    if (end != last && *end != '/') {
      end = parse_integer(end, last, attribute);
      if (end == nullptr)
        break;
      names_no_record = attribute_index(part, attribute) || names_no_record;
      if (in_face_ && attributes_ != nullptr) {
        std::vector<Index>& slots = slots_[part];
        slots.resize(corners_.size(), kNoIndex);
        slots.push_back(attribute_record_of(part, attribute, corners_.size()));
        any_slot_ = true;
      }
    }
  }
  attribute_index_faults_ += names_no_record;
  if (end != last)
    fail(std::string(what) + " corner '" + clip(text) +
         "' is not 'v', 'v/vt', 'v//vn' or 'v/vt/vn'");
  const std::int64_t count = static_cast<std::int64_t>(vertices());
  if (index == 0)
    fail(std::string(what) + " corner '" + clip(text) + "': OBJ indices start at 1 (or -1)");
  if (index > 0) {
    if (index > std::int64_t(kNoIndex))
      fail(std::string(what) + " corner '" + clip(text) + "': index beyond 32 bits");
    if (!in_face_) {  // l and p: counted, so checked here
      attribute_indices_.highest_element_vertex =
          std::max(attribute_indices_.highest_element_vertex, index);
      if (element_vertex_limit_ != nullptr && index > std::int64_t(*element_vertex_limit_)) {
        fail(std::string(what) + " corner '" + clip(text) + "' refers to vertex " +
             std::to_string(index) + ", but the file has " +
             counted(*element_vertex_limit_, "vertex"));
      }
    }
    return static_cast<Index>(index - 1);
  }
  if (relative_ != nullptr) {  // resolved when the parts before are read
    relative_->lowest = std::min(relative_->lowest, count + index);
    if (in_face_)  // l and p corners are counted, not kept
      relative_->corners.emplace_back(soup_.corner_vertices.size() + corners_.size(),
                                      count + index);
    return 0;
  }
  if (-index > count) {
    fail(std::string(what) + " corner '" + clip(text) + "' counts " + std::to_string(-index) +
         " vertices back, before the first vertex: only " + counted(std::size_t(count), "vertex") +
         " come before it");
  }
  return static_cast<Index>(count + index);
}

bool ObjReader::attribute_index(int slot, std::int64_t index) {
  const std::int64_t before =
      static_cast<std::int64_t>(slot == 0 ? texture_coordinates_ : normals_);
  if (totals_ != nullptr)
    return index == 0 || index > std::int64_t(totals_[slot]) || before + index < 0;
  AttributeIndices& r = attribute_indices_;
  if (index > 0)
    r.highest[slot] = std::max(r.highest[slot], index);
  else if (index < 0)
    r.lowest[slot] = std::min(r.lowest[slot], before + index);
  else
    r.zero = true;
  return false;
}

Index ObjReader::attribute_record_of(int slot, std::int64_t index, std::size_t corner) {
  if (index > 0)  // past the file's records: set to none when the file is read (read_obj)
    return index <= std::int64_t(kNoIndex) ? static_cast<Index>(index - 1) : kNoIndex;
  if (index == 0)
    return kNoIndex;
  const std::int64_t record =
      static_cast<std::int64_t>(slot == 0 ? texture_coordinates_ : normals_) + index;
  if (relative_ != nullptr) {  // resolved when the parts before are read
    relative_->attributes[slot].emplace_back(soup_.corner_vertices.size() + corner, record);
    return kNoIndex;
  }
  return record >= 0 ? static_cast<Index>(record) : kNoIndex;
}

void ObjReader::read_corners(const char* what) {
  corners_.clear();
  if (any_slot_) {
    slots_[0].clear();
    slots_[1].clear();
    any_slot_ = false;
  }
  while (!in_.at_line_end())
    corners_.push_back(corner(what));
}

void ObjReader::face() {
  in_face_ = true;
  read_corners("face");
  in_face_ = false;
  ++info_.declared_faces;
  if (corners_.empty()) {
    ++info_.faces_without_corners;
    return;
  }
  if (locate_ != nullptr && soup_.num_faces() == locate_->face) {
    const Index v = corners_[locate_->corner];
    fail("face corner " + std::to_string(locate_->corner + 1) + " refers to vertex " +
         std::to_string(std::uint64_t(v) + 1) + ", but the file has " +
         counted(locate_->vertices, "vertex"));
  }
  const std::size_t first = soup_.num_corners();
  const std::size_t given = corners_.size();
  while (corners_.size() < 3) {  // a record of 1 or 2 corners repeats its last one
    corners_.push_back(corners_.back());
    if (relative_ != nullptr && !relative_->corners.empty() &&
        relative_->corners.back().first == first + given - 1) {
      const std::int64_t offset = relative_->corners.back().second;
      relative_->corners.emplace_back(first + corners_.size() - 1, offset);
    }
  }
  soup_.add_polygon(corners_);
  if (any_slot_)
    keep_corner_attributes(first, given);
}

void ObjReader::keep_corner_attributes(std::size_t first, std::size_t given) {
  CornerAttributes& kept = attributes_->corners;
  for (int slot = 0; slot < 2; ++slot) {
    std::vector<Index>& slots = slots_[slot];
    if (slots.empty())
      continue;
    // A record of 1 or 2 corners repeats its last corner (and its vt/vn) up to a triangle.
    slots.resize(given, kNoIndex);
    while (slots.size() < corners_.size())
      slots.push_back(slots.back());
    if (relative_ != nullptr && given < corners_.size()) {
      auto& relative = relative_->attributes[slot];
      if (!relative.empty() && relative.back().first == first + given - 1) {
        const std::int64_t offset = relative.back().second;
        for (std::size_t c = given; c < corners_.size(); ++c)
          relative.emplace_back(first + c, offset);
      }
    }
    std::vector<Index>& out = slot == 0 ? kept.corner_texture : kept.corner_normal;
    if (out.capacity() == 0)  // once: as many as the soup's corners were reserved for
      out.reserve(soup_.corner_vertices.capacity());
    out.resize(first, kNoIndex);
    out.insert(out.end(), slots.begin(), slots.end());
  }
}

void ObjReader::line_record() {
  read_corners("line");
  if (corners_.empty())
    ++info_.empty_records;
  else if (corners_.size() >= 2)
    info_.dangling_edges += corners_.size() - 1;
  else
    info_.lone_points += corners_.size();
}

void ObjReader::point_record() {
  read_corners("point");
  info_.lone_points += corners_.size();
  if (corners_.empty())
    ++info_.empty_records;
}

std::string ObjReader::rest_of_line(std::string_view keyword) {
  in_.skip_blanks();
  const char* start = in_.position();
  in_.word();
  while (!in_.at_line_end())
    in_.word();
  std::string line(keyword);
  line += ' ';
  line.append(start, static_cast<std::size_t>(in_.position() - start));
  while (!line.empty() && TextScanner::is_blank_or_newline(line.back()))
    line.pop_back();
  return line;
}

}  // namespace meshbridge::detail
