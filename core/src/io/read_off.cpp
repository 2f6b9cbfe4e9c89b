// SPDX-License-Identifier: GPL-3.0-or-later
// OFF reader: header [ST][C][N][n]OFF [BINARY] (nOFF with dimension 3), '#' comments wherever a
// word can start, vertex colours (COFF) and face colours kept, counts checked against the file.

#include "io/formats.h"
#include "io/huge_pages.h"
#include "io/text_scanner.h"
#include "meshbridge/counted.h"
#include "meshbridge/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

struct OffHeader {
  bool texcoords = false, colors = false, normals = false, binary = false;
};

std::string clip(std::string_view text) {
  std::string out(text.substr(0, 40));
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
      c = '?';
  }
  return out;
}

std::uint8_t color_byte(double value, bool unit_range) {
  if (!std::isfinite(value))
    return 0;
  const double scaled = unit_range ? value * 255.0 : value;
  return static_cast<std::uint8_t>(std::lround(std::clamp(scaled, 0.0, 255.0)));
}

//! True if a colour channel lies outside 0..1 (`unit_range`) or 0..255, or is not finite:
//! color_byte() clamps it.
bool clamped(double value, bool unit_range) {
  return !(value >= 0 && value <= (unit_range ? 1.0 : 255.0));
}

// A colour from the numbers left on a vertex or face line: 3 or 4 values, integers 0..255 or
// floats 0..1 (a single value is a colour-map index, which MeshBridge counts but does not keep:
// Geomview's colour map is a file of its own).
bool to_color(const std::vector<double>& values, bool all_integers, Rgba& color,
              std::size_t& clamped_colors) {
  if (values.size() != 3 && values.size() != 4)
    return false;
  const bool unit = !all_integers;
  clamped_colors += std::any_of(values.begin(), values.end(),
                                [unit](double value) { return clamped(value, unit); });
  color =
      Rgba{color_byte(values[0], unit), color_byte(values[1], unit), color_byte(values[2], unit),
           values.size() == 4 ? color_byte(values[3], unit) : std::uint8_t(255)};
  return true;
}

class OffReader {
 public:
  OffReader(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes)
      : file_(file),
        soup_(soup),
        info_(info),
        attributes_(attributes),
        in_(after_byte_order_mark(file.data(), file.end()), file.end(), false, true) {}

  void read() {
    const OffHeader header = read_header();
    if (header.binary)
      read_binary(header);
    else
      read_ascii(header);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_.path() + ": " + what);
  }
  // Keeps at most a window of the map resident behind the cursor (see release_before).
  void release_behind() {
    if (in_.position() - released_ > (8 << 20)) {
      released_ = in_.position();
      file_.release_before(released_);
    }
  }
  std::string at_line() const {
    return in_.at_end() ? std::string(" (at the end of the file)")
                        : " (line " + std::to_string(in_.line()) + ")";
  }

  OffHeader read_header() {
    in_.skip_space_and_comments();
    OffHeader h;
    // The keyword is "recommended but optional, as many existing files lack this keyword"
    // (Geomview's OFF manual): a file that starts with its counts is plain OFF.
    const char* first = in_.position();
    const char* last = first;
    while (last != file_.end() && !TextScanner::is_blank_or_newline(*last) && *last != '#')
      ++last;
    const char* digits = first != last && (*first == '-' || *first == '+') ? first + 1 : first;
    if (digits != last && std::all_of(digits, last, [](char c) {
          return std::isdigit(static_cast<unsigned char>(c)) != 0;
        }))
      return h;  // "4OFF" is a keyword, "4" a count
    const std::string_view word = in_.word();
    std::size_t i = 0;
    if (word.substr(0, 2) == "ST")
      h.texcoords = true, i = 2;
    if (i < word.size() && word[i] == 'C')
      h.colors = true, ++i;
    if (i < word.size() && word[i] == 'N')
      h.normals = true, ++i;
    bool four = false, n_dimensional = false;
    if (i < word.size() && word[i] == '4')
      four = true, ++i;
    if (i < word.size() && word[i] == 'n')
      n_dimensional = true, ++i;
    if (word.substr(i) != "OFF") {
      fail("not an OFF file: it starts with '" + clip(word) +
           "', not a header such as OFF, COFF, NOFF, STOFF or nOFF" +
           other_format_hint(file_.view(), Format::off));
    }
    if (four) {
      fail("'" + clip(word) +
           "': 4-dimensional vertices (4OFF) cannot be read as a 3D mesh; only 3D OFF is read");
    }
    in_.skip_blanks();
    const char* at = in_.position();
    if (file_.end() - at >= 6 && std::memcmp(at, "BINARY", 6) == 0) {
      in_.advance(6);
      h.binary = true;
    }
    if (n_dimensional) {
      if (h.binary)
        fail("binary nOFF is not supported (only ASCII nOFF with dimension 3)");
      in_.skip_space_and_comments();
      std::int64_t dimension = 0;
      if (!in_.integer(dimension))
        fail("nOFF: no dimension after the header" + at_line());
      if (dimension != 3) {
        fail("nOFF of dimension " + std::to_string(dimension) +
             ": only 3-dimensional vertices can be read as a mesh");
      }
    }
    if (h.binary) {
      in_.next_line();  // binary data starts after the header line
    }
    return h;
  }

  // --- ASCII ----------------------------------------------------------------------------------

  std::int64_t count(const char* what) {
    in_.skip_space_and_comments();
    std::int64_t value = 0;
    if (!in_.integer(value)) {
      fail(std::string("no ") + what + " count after the OFF header" + at_line() +
           ": expected 'vertices faces edges'");
    }
    return value;
  }

  void read_ascii(const OffHeader& h) {
    const std::int64_t nv = count("vertex"), nf = count("face");
    if (!in_.at_line_end()) {
      std::int64_t edges = 0;  // often present, never used
      if (!in_.integer(edges))
        fail("the OFF edge count is not a number" + at_line());
    }
    if (nv < 0 || nf < 0) {
      fail("the OFF header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces: a count cannot be negative");
    }
    // The shortest vertex is "0 0 0\n" (6 bytes), the shortest face "0\n" (2 bytes).
    const std::size_t size = file_.size();
    if (std::uint64_t(nv) > size / 6 || std::uint64_t(nf) > size / 2 ||
        std::uint64_t(nv) * 6 + std::uint64_t(nf) * 2 > size) {
      fail("the OFF header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces, more than a file of " + std::to_string(size) +
           " bytes can hold (a false count)");
    }
    if (!in_.at_line_end()) {
      fail("more follows the counts" + at_line() + ": '" + clip(in_.word()) +
           "' (OFF gives the counts, each vertex and each face a line of its own; a file "
           "written on one line cannot be read)");
    }
    in_.next_line();
    info_.declared_vertices = static_cast<std::size_t>(nv);
    info_.declared_faces = static_cast<std::size_t>(nf);
    reserve_huge(soup_, static_cast<std::size_t>(nv), static_cast<std::size_t>(nf),
                 3 * static_cast<std::size_t>(nf));
    const bool want_colors = attributes_ != nullptr;
    if (want_colors && h.colors)
      attributes_->vertex_colors.reserve(static_cast<std::size_t>(nv));
    std::vector<double> rest;
    std::vector<char> integral;
    for (std::int64_t v = 0; v < nv; ++v) {
      release_behind();
      double xyz[3];
      for (double& x : xyz) {
        in_.skip_space_and_comments();
        if (!in_.number(x)) {
          fail("OFF vertex " + std::to_string(v + 1) + " of " + std::to_string(nv) +
               ": expected 3 numbers" +
               (in_.at_end() ? ", but the file ends (a truncated file or a false count)"
                             : at_line() + ", found '" + clip(in_.word()) +
                                   "', which is no number a double can hold"));
        }
      }
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        throw InvalidSoupError(file_.path() + ": OFF vertex " + std::to_string(v + 1) + " of " +
                               std::to_string(nv) + at_line() +
                               " has a non-finite coordinate (nan or inf)");
      }
      soup_.positions.push_back(Point(xyz[0], xyz[1], xyz[2]));
      if (h.colors && (want_colors || !in_.at_line_end())) {  // (colour-map indices are counted)
        vertex_words_ += !numbers_to_line_end(rest, integral);
        // Rest of the line: [nx ny nz] colour [s t].
        const std::size_t skip_front = h.normals ? 3 : 0, skip_back = h.texcoords ? 2 : 0;
        Rgba color;
        bool given = false;
        if (rest.size() >= skip_front + skip_back) {
          const std::size_t last = rest.size() - skip_back;
          const std::vector<double> values(rest.begin() + skip_front, rest.begin() + last);
          const bool integers = std::all_of(integral.begin() + skip_front, integral.begin() + last,
                                            [](char i) { return i; });
          given = to_color(values, integers, color, vertex_colors_clamped_);
          vertex_alpha_given_ = vertex_alpha_given_ || (given && values.size() == 4);
          if (given && want_colors)
            note_color(values, integers, ColorOf::vertex, static_cast<Index>(v));
          else if (values.size() == 1)
            ++info_.color_map_indices;
          else if (!values.empty())
            ++vertex_values_no_colour_;
        }
        if (want_colors) {
          push_color(attributes_->vertex_colors, attributes_->vertex_color_missing,
                     static_cast<std::size_t>(v), given ? &color : nullptr);
        }
      } else if (!h.colors && want_colors && !in_.at_line_end()) {
        // Plain OFF: values past x y z [normal] [s t] (a colour needs the C keyword).
        vertex_words_ += !numbers_to_line_end(rest, integral);
        if (rest.size() > (h.normals ? 3u : 0u) + (h.texcoords ? 2u : 0u))
          ++vertex_values_no_colour_;
      }
      in_.next_line();
    }
    std::vector<Index> corners;
    for (std::int64_t f = 0; f < nf; ++f) {
      release_behind();
      in_.skip_space_and_comments();
      std::int64_t n = 0;
      if (in_.at_end() || !in_.integer(n)) {
        fail("OFF face " + std::to_string(f + 1) + " of " + std::to_string(nf) + " is missing" +
             (in_.at_end() ? ": the file ends (a false count; or fewer vertex lines than the " +
                                 std::to_string(nv) + " declared, so that a face was read as one)"
                           : at_line() + ": no corner count there"));
      }
      if (n < 0)
        fail("OFF face " + std::to_string(f + 1) + " has a negative corner count " +
             std::to_string(n) + at_line());
      const std::size_t left = static_cast<std::size_t>(file_.end() - in_.position());
      if (std::uint64_t(n) > left / 2 + 1) {
        fail("OFF face " + std::to_string(f + 1) + " claims " + std::to_string(n) +
             " corners, more than the rest of the file holds" + at_line());
      }
      corners.clear();
      for (std::int64_t c = 0; c < n; ++c) {
        std::int64_t index = 0;
        if (in_.at_line_end() || !in_.integer(index)) {
          fail("OFF face " + std::to_string(f + 1) + ": corner " + std::to_string(c + 1) + " of " +
               std::to_string(n) + " is missing or not a vertex index" + at_line());
        }
        if (index < 0 || index >= nv) {
          fail("OFF face " + std::to_string(f + 1) + " refers to vertex index " +
               std::to_string(index) + at_line() + ", but the file has " +
               counted(static_cast<std::size_t>(nv), "vertex") + " (OFF counts from 0)");
        }
        corners.push_back(static_cast<Index>(index));
      }
      add_face(corners);
      if (!corners.empty() && (want_colors || !in_.at_line_end())) {
        face_words_ += !numbers_to_line_end(rest, integral);
        const bool integers =
            std::all_of(integral.begin(), integral.end(), [](char i) { return i; });
        Rgba color;
        const bool given = to_color(rest, integers, color, face_colors_clamped_);
        face_alpha_given_ = face_alpha_given_ || (given && rest.size() == 4);
        if (want_colors) {
          push_color(attributes_->face_colors, attributes_->face_color_missing,
                     soup_.num_faces() - 1, given ? &color : nullptr);
        }
        if (given && want_colors)
          note_color(rest, integers, ColorOf::face, static_cast<Index>(soup_.num_faces() - 1));
        else if (rest.size() == 1)
          ++info_.color_map_indices;
        else if (!rest.empty())
          ++face_values_no_colour_;
      }
      in_.next_line();
    }
    // A face count lower than the faces given would drop the rest without a word.
    in_.skip_space_and_comments();
    if (!in_.at_end()) {
      fail("OFF declares " + counted(static_cast<std::size_t>(nf), "face") +
           ", but more follows them" + at_line() + ": '" + clip(in_.word()) +
           "' (a false face count, or text after the mesh)");
    }
    if (want_colors) {
      note_not_kept(h, static_cast<std::size_t>(nv));
      attributes_->vertex_color_channels = vertex_alpha_given_ ? kRgbaChannels : kRgbChannels;
      attributes_->face_color_channels = face_alpha_given_ ? kRgbaChannels : kRgbChannels;
    }
    if (want_colors && !attributes_->face_colors.empty())
      pad_missing_colors(attributes_->face_colors, attributes_->face_color_missing,
                         soup_.num_faces());
    if (want_colors && unit_colors_seen_) {
      // Colours written as integers are 0..255, as floats 0..1; "1 1 1" could be either. In a
      // file that writes some colour as floats, it is read the same way (white, not near black).
      for (const auto& [of, i] : ambiguous_colors_) {
        Rgba& c = of == ColorOf::face ? attributes_->face_colors[i] : attributes_->vertex_colors[i];
        for (std::uint8_t* channel : {&c.r, &c.g, &c.b, &c.a})
          *channel = *channel <= 1 ? static_cast<std::uint8_t>(*channel * 255) : *channel;
      }
    }
  }

  // The numbers left on the current line, and for each whether it is written as an integer.
  // Stops at the first word that is no number and returns false then (the caller counts the
  // line: its words are read past, see note_not_kept).
  bool numbers_to_line_end(std::vector<double>& values, std::vector<char>& integral) {
    values.clear();
    integral.clear();
    while (!in_.at_line_end()) {
      const char* start = in_.position();
      double x = 0;
      if (!in_.number(x))
        return false;
      const std::string_view text(start, static_cast<std::size_t>(in_.position() - start));
      integral.push_back(text.find_first_of(".eEnN") == std::string_view::npos);
      values.push_back(x);
    }
    return true;
  }

  // What the file holds that is read past (with attributes only): normals, texture coordinates,
  // values after a vertex or face that are no colour.
  void note_not_kept(const OffHeader& h, std::size_t vertices) {
    auto& not_kept = attributes_->not_kept;
    if (h.normals && vertices > 0)
      not_kept.push_back({"OFF vertex normals (NOFF)", vertices, "vertex"});
    if (h.texcoords && vertices > 0)
      not_kept.push_back({"OFF texture coordinates (ST)", vertices, "vertex"});
    if (vertex_values_no_colour_ > 0) {
      not_kept.push_back(
          {std::string("OFF values after a vertex that are no colour (") +
               (h.colors ? "not 1, 3 or 4 numbers" : "plain OFF: colours need COFF") + ")",
           vertex_values_no_colour_, "vertex line", true});
    }
    if (face_values_no_colour_ > 0) {
      not_kept.push_back(
          {"OFF values after a face's corners that are no colour (not 1, 3 or 4 "
           "numbers)",
           face_values_no_colour_, "face line", true});
    }
    if (vertex_words_ > 0) {
      not_kept.push_back({"OFF words after a vertex's numbers that are no number (read past)",
                          vertex_words_, "vertex line", true});
    }
    if (face_words_ > 0) {
      not_kept.push_back({"OFF words after a face's numbers that are no number (read past)",
                          face_words_, "face line", true});
    }
    if (vertex_colors_clamped_ > 0) {
      not_kept.push_back(
          {"OFF vertex colour values outside 0-1 (or 0-255) or not finite, "
           "clamped to the range",
           vertex_colors_clamped_, "vertex", true, true});
    }
    if (face_colors_clamped_ > 0) {
      not_kept.push_back(
          {"OFF face colour values outside 0-1 (or 0-255) or not finite, "
           "clamped to the range",
           face_colors_clamped_, "face", true, true});
    }
    if (binary_face_colours_ > 0) {
      not_kept.push_back(
          {"binary OFF face colours (Geomview's layout)", binary_face_colours_, "face"});
    }
  }

  enum class ColorOf { vertex, face };
  // Remembers what the file's colours tell about their scale (see the end of read_ascii).
  void note_color(const std::vector<double>& values, bool integers, ColorOf of, Index i) {
    if (!integers)
      unit_colors_seen_ = true;
    else if (std::all_of(values.begin(), values.end(), [](double x) { return x <= 1; }))
      ambiguous_colors_.emplace_back(of, i);
  }

  void add_face(std::vector<Index>& corners) {
    if (corners.empty()) {
      ++info_.faces_without_corners;
      return;
    }
    while (corners.size() < 3)
      corners.push_back(corners.back());
    soup_.add_polygon(corners);
  }

  // --- binary (little-endian, as OpenMesh reads and writes it) --------------------------------

  // Binary OFF comes in two layouts: OpenMesh's (little-endian, as x86 writes it, and nothing
  // after a face's indices) and Geomview's specification (big-endian 32-bit words, each face
  // followed by a colour count and that many floats). The layout that accounts for every byte of
  // the file is read; when none does, OpenMesh's is read and names what is wrong.
  struct BinaryLayout {
    bool big_endian = false;
    bool color_counts = false;
  };
  static std::uint32_t load(const char* p, bool big_endian) {
    std::uint32_t w = 0;
    std::memcpy(&w, p, 4);
    return big_endian ? __builtin_bswap32(w) : w;
  }
  static std::uint64_t vertex_floats(const OffHeader& h) {
    return 3 + (h.normals ? 3 : 0) + (h.colors ? 3 : 0) + (h.texcoords ? 2 : 0);
  }
  // True if the body from `p` is exactly the counts, vertices and faces of `layout`.
  bool fits(const OffHeader& h, const char* p, BinaryLayout layout) const {
    const char* end = file_.end();
    if (end - p < 12)
      return false;
    const std::uint64_t nv = load(p, layout.big_endian), nf = load(p + 4, layout.big_endian);
    p += 12;
    if (nv * vertex_floats(h) * 4 > std::uint64_t(end - p))
      return false;
    p += nv * vertex_floats(h) * 4;
    for (std::uint64_t f = 0; f < nf; ++f) {
      if (end - p < 4)
        return false;
      const std::uint64_t n = load(p, layout.big_endian);
      if (n == 0 || (n + 1) * 4 > std::uint64_t(end - p))
        return false;
      p += (n + 1) * 4;
      if (layout.color_counts) {
        if (end - p < 4)
          return false;
        const std::uint64_t colors = load(p, layout.big_endian);
        if (colors > 4 || (colors + 1) * 4 > std::uint64_t(end - p))
          return false;
        p += (colors + 1) * 4;
      }
    }
    return p == end;
  }

  void read_binary(const OffHeader& h) {
    const char* p = in_.position();
    BinaryLayout layout;  // OpenMesh's, unless only another one fits the file
    for (const BinaryLayout candidate : {BinaryLayout{false, false}, BinaryLayout{true, true},
                                         BinaryLayout{false, true}, BinaryLayout{true, false}}) {
      if (fits(h, p, candidate)) {
        layout = candidate;
        break;
      }
    }
    const char* end = file_.end();
    const auto left = [&] { return static_cast<std::uint64_t>(end - p); };
    const auto word = [&] {
      const std::uint32_t w = load(p, layout.big_endian);
      p += 4;
      return w;
    };
    const auto real = [&] {
      const std::uint32_t w = word();
      float x = 0;
      std::memcpy(&x, &w, 4);
      return x;
    };
    if (left() < 12)
      fail("binary OFF ends before its vertex, face and edge counts");
    const std::uint32_t nv = word(), nf = word();
    word();
    const std::uint64_t floats = vertex_floats(h);
    if (std::uint64_t(nv) * floats * 4 > left()) {
      fail("binary OFF declares " + std::to_string(nv) + " vertices (" +
           std::to_string(std::uint64_t(nv) * floats * 4) + " bytes) but only " +
           std::to_string(left()) + " bytes follow its header (a truncated file or a false count)");
    }
    if (std::uint64_t(nf) * 4 > left() - std::uint64_t(nv) * floats * 4) {
      fail("binary OFF declares " + std::to_string(nf) + " faces but only " +
           std::to_string(left() - std::uint64_t(nv) * floats * 4) + " bytes follow its vertices");
    }
    info_.declared_vertices = nv;
    info_.declared_faces = nf;
    reserve_huge(soup_, nv, nf, 3 * std::size_t(nf));
    const bool colors = attributes_ != nullptr && h.colors;
    if (colors)
      attributes_->vertex_color_channels = kRgbChannels;  // 3 floats
    for (std::uint32_t v = 0; v < nv; ++v) {
      float values[11];
      for (std::uint64_t i = 0; i < floats; ++i)
        values[i] = real();
      soup_.positions.push_back(Point(values[0], values[1], values[2]));
      if (colors) {
        const float* c = values + 3 + (h.normals ? 3 : 0);
        vertex_colors_clamped_ += clamped(c[0], true) || clamped(c[1], true) || clamped(c[2], true);
        attributes_->vertex_colors.push_back(
            Rgba{color_byte(c[0], true), color_byte(c[1], true), color_byte(c[2], true), 255});
      }
    }
    std::vector<Index> corners;
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (left() < 4) {
        fail("binary OFF ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
      }
      const std::uint32_t n = word();
      if (std::uint64_t(n) * 4 > left()) {
        fail("binary OFF face " + std::to_string(f + 1) + " claims " + std::to_string(n) +
             " corners, more than the rest of the file holds");
      }
      corners.clear();
      for (std::uint32_t c = 0; c < n; ++c) {
        const std::int32_t index = static_cast<std::int32_t>(word());
        if (index < 0 || std::uint32_t(index) >= nv) {
          fail("binary OFF face " + std::to_string(f + 1) + " refers to vertex index " +
               std::to_string(index) + ", but the file has " + counted(nv, "vertex") +
               " (OFF counts from 0)");
        }
        corners.push_back(static_cast<Index>(index));
      }
      add_face(corners);
      if (layout.color_counts) {  // checked by fits(): a count of at most 4, then the floats
        const std::uint32_t colour_values = word();
        binary_face_colours_ += colour_values > 0 ? 1 : 0;
        p += 4 * std::uint64_t(colour_values);
      }
    }
    if (p != end) {
      fail("binary OFF: " + std::to_string(left()) +
           " bytes follow its last face (neither OpenMesh's layout nor Geomview's fits the file)");
    }
    if (attributes_ != nullptr)
      note_not_kept(h, nv);
  }

  const MappedFile& file_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  TextScanner in_;
  const char* released_ = file_.data();
  bool unit_colors_seen_ = false;  //!< some colour was written as floats (0..1)
  bool vertex_alpha_given_ = false, face_alpha_given_ = false;  //!< some colour had 4 values
  std::size_t vertex_values_no_colour_ = 0, face_values_no_colour_ = 0;  //!< see note_not_kept
  std::size_t binary_face_colours_ = 0;            //!< Geomview binary faces with a colour
  std::size_t vertex_words_ = 0, face_words_ = 0;  //!< lines with a word that is no number
  std::size_t vertex_colors_clamped_ = 0, face_colors_clamped_ = 0;  //!< see clamped()
  std::vector<std::pair<ColorOf, Index>> ambiguous_colors_;          //!< integer colours all <= 1
};

}  // namespace

void read_off(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  OffReader(file, soup, info, attributes).read();
}

}  // namespace meshbridge::detail
