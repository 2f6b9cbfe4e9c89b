// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ reader: v (x y z [w] [r g b [a]]), vt, vn, f/l/p with every index form (v, v/vt, v//vn,
// v/vt/vn, negative = relative), backslash line continuations, o/g/usemtl as face groups.
// mtllib and every other record are skipped (never opened).

#include "io/formats.h"
#include "io/huge_pages.h"
#include "io/obj_parts.h"
#include "io/text_scanner.h"
#include "meshbridge/counted.h"
#include "meshbridge/errors.h"
#include "parallel_parts.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

//! Reads the lines [first, last) of an OBJ file (all of it, or one part when `relative` is
//! given: then negative indices are recorded there, not resolved).
class ObjReader {
 public:
  ObjReader(const MappedFile& file, const char* first, const char* last, Soup& soup, ReadInfo& info,
            MeshAttributes* attributes, RelativeCorners* relative = nullptr)
      : file_(file),
        soup_(soup),
        info_(info),
        attributes_(attributes),
        relative_(relative),
        in_(first, last, true, true),
        released_(first) {}

  //! The vt/vn indices met by read().
  const AttributeIndices& attribute_indices() const { return attribute_indices_; }
  //! The colour scale this reader met (see ColourScale); moved out.
  ColourScale take_colour_scale() { return std::move(colour_scale_); }

  //! Reads the file counting the corners whose vt or vn index names a record past the file's
  //! `totals` (vt, vn) or, relative, before its first one.
  std::size_t count_attribute_index_faults(const std::size_t totals[2]) {
    totals_ = totals;
    read();
    return attribute_index_faults_;
  }

  //! Reads the file and throws the ReadError naming the first `l` or `p` corner whose vertex
  //! index is past `vertices` (the file's count).
  [[noreturn]] void locate_element_vertex_past(std::size_t vertices) {
    element_vertex_limit_ = &vertices;
    read();
    throw ReadError(file_.path() + ": an l or p corner past the last vertex not found again");
  }

  //! Reads until soup face `where.face` and throws the ReadError naming its line.
  [[noreturn]] void locate(const ObjIndexOutOfRange& where) {
    locate_ = &where;
    read();
    throw ReadError(file_.path() + ": face " + std::to_string(where.face) + " not found again");
  }

  void read() {
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
        ++texture_coordinates_;
      else if (keyword == "vn")
        ++normals_;
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
    info_.declared_vertices = soup_.num_vertices();
    if (attributes_ != nullptr) {
      attributes_->vertex_color_channels = alpha_given_ ? kRgbaChannels : kRgbChannels;
      attributes_->texture_coordinates = texture_coordinates_;
      if (w_not_one_ > 0)
        add_not_kept(*attributes_, {"OBJ vertex w other than 1", w_not_one_, "vertex"});
      if (colours_clamped_ > 0) {
        add_not_kept(*attributes_, {"OBJ vertex colour values outside 0-1 (or 0-255) or not "
                                    "finite, clamped to the range",
                                    colours_clamped_, "vertex", true, true});
      }
      if (values_no_colour_ > 0) {
        add_not_kept(*attributes_,
                     {"OBJ numbers after a vertex that are no w or colour (5, or more "
                      "than 7)",
                      values_no_colour_, "vertex", true});
      }
      attributes_->normals = normals_;
      if (!attributes_->vertex_colors.empty())
        pad_missing_colors(attributes_->vertex_colors, attributes_->vertex_color_missing,
                           soup_.num_vertices());
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_.path() + ": line " + std::to_string(in_.line()) + ": " + what);
  }

  void vertex() {
    double values[7];
    int n = 0;
    while (n < 7 && !in_.at_line_end()) {
      if (!in_.number(values[n])) {
        const std::string_view bad = in_.word();
        fail("vertex " + std::to_string(soup_.num_vertices() + 1) + ": '" + clip(bad) +
             "' is not a number a double can hold (expected 'v x y z')");
      }
      ++n;
    }
    if (n < 3) {
      fail("vertex " + std::to_string(soup_.num_vertices() + 1) + " has " + std::to_string(n) +
           " coordinate(s), expected 3");
    }
    if (!std::isfinite(values[0]) || !std::isfinite(values[1]) || !std::isfinite(values[2])) {
      throw InvalidSoupError(file_.path() + ": line " + std::to_string(in_.line()) + ": vertex " +
                             std::to_string(soup_.num_vertices() + 1) +
                             " has a non-finite coordinate (nan or inf)");
    }
    soup_.positions.push_back(Point(values[0], values[1], values[2]));
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
        colour_scale_.bytes = true;
      else if (whole)  // 0s and 1s: the file's scale decides
        colour_scale_.unit.emplace_back(static_cast<Index>(soup_.num_vertices() - 1), n == 7);
      const double top = bytes ? 255 : 1;
      colours_clamped_ +=
          std::any_of(values + 3, values + n, [top](double v) { return !(v >= 0 && v <= top); });
      color = Rgba{to_byte(values[3], bytes), to_byte(values[4], bytes), to_byte(values[5], bytes),
                   n == 7 ? to_byte(values[6], bytes) : std::uint8_t(255)};
    }
    push_color(attributes_->vertex_colors, attributes_->vertex_color_missing,
               soup_.num_vertices() - 1, n >= 6 ? &color : nullptr);
    alpha_given_ = alpha_given_ || n == 7;
    // Read past: a w other than 1 ("v x y z w"), and numbers that are neither w nor a colour.
    w_not_one_ += n == 4 && values[3] != 1;
    values_no_colour_ += n == 5 || (n == 7 && !in_.at_line_end());
  }

  // The records of the OBJ format (Wavefront's specification, appendix B1) that carry nothing
  // MeshBridge keeps: skipped without a count.
  static bool is_skipped_record(std::string_view keyword) {
    static constexpr std::string_view kRecords[] = {
        "vp",       "s",        "mg",         "mtllib",    "usemap", "maplib", "lod",    "bevel",
        "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",  "stech",  "cstype", "deg",
        "bmat",     "step",     "curv",       "curv2",     "surf",   "parm",   "trim",   "hole",
        "scrv",     "sp",       "end",        "con",       "call",   "csh"};
    return std::find(std::begin(kRecords), std::end(kRecords), keyword) != std::end(kRecords);
  }

  //! A colour channel from 0..1, or from 0..255 when `bytes`.
  static std::uint8_t to_byte(double value, bool bytes) {
    const double scaled = bytes ? value : value * 255.0;
    const double clamped = std::isfinite(scaled) ? std::clamp(scaled, 0.0, 255.0) : 0.0;
    return static_cast<std::uint8_t>(std::lround(clamped));
  }

  static std::string clip(std::string_view text) {
    std::string out(text.substr(0, 40));
    for (char& c : out) {
      if (static_cast<unsigned char>(c) < 32)
        c = '?';
    }
    return out;
  }

  // One corner "v", "v/vt", "v//vn" or "v/vt/vn": the vertex index, 0-based (kNoIndex if a
  // relative index points before the first vertex; account_faces names out-of-range ones).
  Index corner(const char* what) {
    const std::string_view text = in_.word();
    const char* first = text.data();
    const char* last = first + text.size();
    std::int64_t index = 0;
    const char* end = parse_integer(first, last, index);
    if (end == nullptr) {
      const char* after_sign =
          first != last && (*first == '-' || *first == '+') ? first + 1 : first;
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
    // (attribute_index()).
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
      }
    }
    attribute_index_faults_ += names_no_record;
    if (end != last)
      fail(std::string(what) + " corner '" + clip(text) +
           "' is not 'v', 'v/vt', 'v//vn' or 'v/vt/vn'");
    const std::int64_t count = static_cast<std::int64_t>(soup_.num_vertices());
    if (index == 0)
      fail(std::string(what) + " corner '" + clip(text) + "': OBJ indices start at 1 (or -1)");
    if (index > 0) {
      if (index > std::int64_t(kNoIndex))
        fail(std::string(what) + " corner '" + clip(text) + "': index beyond 32 bits");
      if (std::string_view(what) != "face") {  // l and p: counted, so checked here
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
      if (std::string_view(what) == "face")  // l and p corners are counted, not kept
        relative_->corners.emplace_back(soup_.corner_vertices.size() + corners_.size(),
                                        count + index);
      return 0;
    }
    if (-index > count) {
      fail(std::string(what) + " corner '" + clip(text) + "' counts " + std::to_string(-index) +
           " vertices back, before the first vertex: only " +
           counted(std::size_t(count), "vertex") + " come before it");
    }
    return static_cast<Index>(count + index);
  }

  // Notes vt (slot 0) or vn (slot 1) index `index` of a corner; true when counting faults
  // (count_attribute_index_faults) and it names no record of the file.
  bool attribute_index(int slot, std::int64_t index) {
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

  void read_corners(const char* what) {
    corners_.clear();
    while (!in_.at_line_end())
      corners_.push_back(corner(what));
  }

  void face() {
    read_corners("face");
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
    while (corners_.size() < 3)
      corners_.push_back(corners_.back());
    soup_.add_polygon(corners_);
  }

  void line_record() {
    read_corners("line");
    if (corners_.empty())
      ++info_.empty_records;
    else if (corners_.size() >= 2)
      info_.dangling_edges += corners_.size() - 1;
    else
      info_.lone_points += corners_.size();
  }

  void point_record() {
    read_corners("point");
    info_.lone_points += corners_.size();
    if (corners_.empty())
      ++info_.empty_records;
  }

  // "keyword rest of the line" as written (an o/g/usemtl group name, an mtllib file list).
  std::string rest_of_line(std::string_view keyword) {
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

  const MappedFile& file_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  RelativeCorners* relative_;
  TextScanner in_;
  std::vector<Index> corners_;
  std::size_t texture_coordinates_ = 0, normals_ = 0;
  AttributeIndices attribute_indices_;
  const std::size_t* totals_ = nullptr;  // vt and vn of the file: count_attribute_index_faults
  const std::size_t* element_vertex_limit_ = nullptr;  // see locate_element_vertex_past()
  std::size_t attribute_index_faults_ = 0;
  const ObjIndexOutOfRange* locate_ = nullptr;              // see locate()
  bool alpha_given_ = false;                                // some 'v' line has r g b a
  std::size_t w_not_one_ = 0, values_no_colour_ = 0;        // see vertex()
  std::size_t colours_clamped_ = 0;                         // see vertex()
  ColourScale colour_scale_;                                // see vertex()
  static constexpr std::ptrdiff_t kReleaseEvery = 8 << 20;  // bytes of the map kept behind
  const char* released_;
};

//! Reads the file in `n` parts side by side: part 0 into `soup`, the others into their own soups
//! appended in file order. False (outputs to be reset) if a part met an error or a negative
//! index that reaches before the file's first vertex: the one-thread read names it.
bool read_in_parts(const MappedFile& file, unsigned n, Soup& soup, ReadInfo& info,
                   MeshAttributes* attributes, AttributeIndices& attribute_indices,
                   ColourScale& colour_scale) {
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
  reserve_huge(soup, total.vertices, total.faces, total.corners);
  run_parts(n, [&](unsigned k) {
    ObjPart& part = parts[k];
    try {
      if (k == 0) {
        ObjReader reader(file, part.first, part.last, soup, info, attributes);
        reader.read();
        part.attribute_indices = reader.attribute_indices();
        part.colour_scale = reader.take_colour_scale();
      } else {
        reserve_huge(part.soup, part.counts.vertices, part.counts.faces, part.counts.corners);
        ObjReader reader(file, part.first, part.last, part.soup, part.info,
                         attributes != nullptr ? &part.attributes : nullptr, &part.relative);
        reader.read();
        part.attribute_indices = reader.attribute_indices();
        part.colour_scale = reader.take_colour_scale();
      }
    } catch (const ReadError&) {
      failed[k] = 1;
    }
  });
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
    const ColourScale& part = parts[k].colour_scale;
    colour_scale.bytes = colour_scale.bytes || part.bytes;
    for (const auto& [v, alpha] : part.unit)
      colour_scale.unit.emplace_back(static_cast<Index>(first_vertex + v), alpha);
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
  ColourScale colour_scale;
  if (n > 1) {
    read = read_in_parts(file, n, soup, info, attributes, attribute_indices, colour_scale);
    if (!read) {
      soup = Soup();
      info = ReadInfo();
      attribute_indices = AttributeIndices();
      colour_scale = ColourScale();
      if (attributes != nullptr)
        *attributes = MeshAttributes();
    }
  }
  if (!read) {
    const RecordCounts counts = estimate_records(file.data(), file.end());
    reserve_huge(soup, counts.vertices, counts.faces, counts.corners);
    ObjReader reader(file, after_byte_order_mark(file.data(), file.end()), file.end(), soup, info,
                     attributes);
    reader.read();
    attribute_indices = reader.attribute_indices();
    colour_scale = reader.take_colour_scale();
  }
  // An l or p corner past the last vertex: an error naming its line, as for faces.
  if (attribute_indices.highest_element_vertex > std::int64_t(soup.num_vertices())) {
    Soup again;
    ReadInfo ignored;
    ObjReader(file, after_byte_order_mark(file.data(), file.end()), file.end(), again, ignored,
              nullptr)
        .locate_element_vertex_past(soup.num_vertices());
  }
  if (attributes == nullptr)
    return;
  rescale_unit_colours(colour_scale, *attributes);
  // A vt or vn index the file has no record for: counted by reading the file once more (only
  // such a broken file pays for it), and named as read past (MeshBridge keeps neither).
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
  }
}

}  // namespace meshbridge::detail
