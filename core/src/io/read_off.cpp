// SPDX-License-Identifier: GPL-3.0-or-later
// OFF reader: header [ST][C][N][n]OFF [BINARY] (nOFF with dimension 3), '#' comments wherever a
// word can start, vertex colours (COFF) and face colours kept, counts checked against the file.

#include "io/read_off.h"
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

std::string clip(std::string_view text) {
  std::string out(text.substr(0, 40));
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
      c = '?';
  }
  return out;
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
                                [unit](double value) { return off_color_clamped(value, unit); });
  color = Rgba{off_color_byte(values[0], unit), off_color_byte(values[1], unit),
               off_color_byte(values[2], unit),
               values.size() == 4 ? off_color_byte(values[3], unit) : std::uint8_t(255)};
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
    if (header.binary) {
      const OffBinaryNotes notes =
          read_off_binary(file_, in_.position(), header, soup_, info_, attributes_);
      binary_face_colors_ = notes.face_colors;
      vertex_colors_clamped_ = notes.vertex_colors_clamped;
      if (attributes_ != nullptr)
        note_not_kept(header, info_.declared_vertices);
    } else {
      read_ascii(header);
    }
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
    std::string_view word = in_.word();
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
    // "OFF8 6 12": the keyword and the vertex count without a blank between them, as in the
    // ModelNet data sets; read as the header it is.
    if (word.substr(i, 3) == "OFF" && word.size() > i + 3 &&
        std::all_of(word.begin() + i + 3, word.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; })) {
      in_.back_to(word.data() + i + 3);
      word = word.substr(0, i + 3);
    }
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
            ++vertex_values_no_color_;
        }
        if (want_colors) {
          push_color(attributes_->vertex_colors, attributes_->vertex_color_missing,
                     static_cast<std::size_t>(v), given ? &color : nullptr);
        }
      } else if (!h.colors && want_colors && !in_.at_line_end()) {
        // Plain OFF: values past x y z [normal] [s t] (a colour needs the C keyword).
        vertex_words_ += !numbers_to_line_end(rest, integral);
        if (rest.size() > (h.normals ? 3u : 0u) + (h.texcoords ? 2u : 0u))
          ++vertex_values_no_color_;
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
      add_off_face(corners, soup_, info_);
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
          ++face_values_no_color_;
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
    if (vertex_values_no_color_ > 0) {
      not_kept.push_back(
          {std::string("OFF values after a vertex that are no colour (") +
               (h.colors ? "not 1, 3 or 4 numbers" : "plain OFF: colours need COFF") + ")",
           vertex_values_no_color_, "vertex line", true});
    }
    if (face_values_no_color_ > 0) {
      not_kept.push_back(
          {"OFF values after a face's corners that are no colour (not 1, 3 or 4 "
           "numbers)",
           face_values_no_color_, "face line", true});
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
    if (binary_face_colors_ > 0) {
      not_kept.push_back(
          {"binary OFF face colours (Geomview's layout)", binary_face_colors_, "face"});
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

  const MappedFile& file_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  TextScanner in_;
  const char* released_ = file_.data();
  bool unit_colors_seen_ = false;  //!< some colour was written as floats (0..1)
  bool vertex_alpha_given_ = false, face_alpha_given_ = false;         //!< some colour had 4 values
  std::size_t vertex_values_no_color_ = 0, face_values_no_color_ = 0;  //!< see note_not_kept
  std::size_t binary_face_colors_ = 0;             //!< Geomview binary faces with a colour
  std::size_t vertex_words_ = 0, face_words_ = 0;  //!< lines with a word that is no number
  std::size_t vertex_colors_clamped_ = 0, face_colors_clamped_ = 0;  //!< see off_color_clamped()
  std::vector<std::pair<ColorOf, Index>> ambiguous_colors_;          //!< integer colours all <= 1
};

}  // namespace

void add_off_face(std::vector<Index>& corners, Soup& soup, ReadInfo& info) {
  if (corners.empty()) {
    ++info.faces_without_corners;
    return;
  }
  while (corners.size() < 3)
    corners.push_back(corners.back());
  soup.add_polygon(corners);
}

void read_off(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  OffReader(file, soup, info, attributes).read();
}

}  // namespace meshbridge::detail
