// SPDX-License-Identifier: GPL-3.0-or-later
// The OBJ line reader (read_obj.cpp runs it over the whole file or over parts side by side):
// v (x y z [w] [r g b [a]]), vt, vn, f/l/p with every index form (v, v/vt, v//vn, v/vt/vn,
// negative = relative), backslash line continuations, o/g/usemtl as face groups. mtllib lines are
// kept as written (never opened); every other record is skipped.

#pragma once

#include "io/formats.h"
#include "io/mapped_file.h"
#include "io/obj_parts.h"
#include "io/obj_weld.h"
#include "io/text_scanner.h"
#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

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
  ColorScale take_color_scale() { return std::move(color_scale_); }

  //! Reads the file counting the corners whose vt or vn index names a record past the file's
  //! `totals` (vt, vn) or, relative, before its first one.
  std::size_t count_attribute_index_faults(const std::size_t totals[2]) {
    totals_ = totals;
    read();
    return attribute_index_faults_;
  }

  //! Reads the file and throws the ReadError naming the first `l` or `p` corner whose vertex
  //! index is past `vertices` (the file's count).
  [[noreturn]] void locate_element_vertex_past(std::size_t vertices);

  //! Reads until soup face `where.face` and throws the ReadError naming its line.
  [[noreturn]] void locate(const ObjIndexOutOfRange& where);

  //! Reads every line into the soup, the info and (if given) the attributes.
  void read();

  //! Puts the `v` records into `table` instead of the soup's positions (obj_weld.h), until one
  //! is not a plain "v x y z" the table takes: then the positions read so far are put back into
  //! the soup and the table emptied (welding() false).
  void weld_into(PositionTable* table) { weld_ = table; }
  //! Whether the `v` records all went into the table given to weld_into().
  bool welding() const { return weld_ != nullptr; }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  //! The `v` records read so far.
  std::size_t vertices() const {
    return weld_ != nullptr ? weld_->vertices() : soup_.num_vertices();
  }
  void vertex();
  //! A `vt` (slot 0) or `vn` (slot 1) record: counted, and with attributes kept.
  void attribute_record(int slot);
  //! The records of the OBJ format that carry nothing MeshBridge keeps: skipped without a count.
  static bool is_skipped_record(std::string_view keyword);
  //! A colour channel from 0..1, or from 0..255 when `bytes`.
  static std::uint8_t to_byte(double value, bool bytes);
  static std::string clip(std::string_view text);
  //! One corner "v", "v/vt", "v//vn" or "v/vt/vn": the vertex index, 0-based (kNoIndex if a
  //! relative index points before the first vertex; account_faces names out-of-range ones). Of a
  //! face corner, with attributes, its vt and vn records go into `slots_`.
  Index corner(const char* what);
  //! Notes vt (slot 0) or vn (slot 1) index `index` of a corner; true when counting faults
  //! (count_attribute_index_faults) and it names no record of the file.
  bool attribute_index(int slot, std::int64_t index);
  //! The record (0-based) that vt/vn index `index` of face corner `corner` (of the face being
  //! read) names, kNoIndex for none; in a part, a relative one is noted in `relative_`.
  Index attribute_record_of(int slot, std::int64_t index, std::size_t corner);
  void read_corners(const char* what);
  void face();
  //! Appends the vt/vn records of the face just added (its first soup corner `first`, `given`
  //! corners in the file).
  void keep_corner_attributes(std::size_t first, std::size_t given);
  void line_record();
  void point_record();
  //! "keyword rest of the line" as written (an o/g/usemtl group name, an mtllib file list).
  std::string rest_of_line(std::string_view keyword);

  const MappedFile& file_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  RelativeCorners* relative_;
  PositionTable* weld_ = nullptr;  // see weld_into()
  TextScanner in_;
  std::vector<Index> corners_;
  //! The vt (0) and vn (1) records of the face's corners being read: empty while no corner of
  //! the face gave one (`any_slot_`), then up to each corner that gave one (kNoIndex: none).
  std::vector<Index> slots_[2];
  bool any_slot_ = false;
  bool in_face_ = false;  // corners being read are a face's (l and p corners keep no vt/vn)
  std::size_t texture_coordinates_ = 0, normals_ = 0;
  std::size_t attribute_records_bad_ = 0;  // vt/vn records with a value that is no number
  AttributeIndices attribute_indices_;
  const std::size_t* totals_ = nullptr;  // vt and vn of the file: count_attribute_index_faults
  const std::size_t* element_vertex_limit_ = nullptr;  // see locate_element_vertex_past()
  std::size_t attribute_index_faults_ = 0;
  const ObjIndexOutOfRange* locate_ = nullptr;              // see locate()
  bool alpha_given_ = false;                                // some 'v' line has r g b a
  std::size_t w_not_one_ = 0, values_no_color_ = 0;         // see vertex()
  std::size_t colors_clamped_ = 0;                          // see vertex()
  ColorScale color_scale_;                                  // see vertex()
  static constexpr std::ptrdiff_t kReleaseEvery = 8 << 20;  // bytes of the map kept behind
  const char* released_;
};

}  // namespace meshbridge::detail
