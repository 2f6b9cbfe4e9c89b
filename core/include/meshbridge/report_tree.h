// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file report_tree.h
//! The reports of report_json.h as a tree of values rather than text, for callers in the same
//! process that want the numbers (the Python module builds its dicts from it): the same keys in
//! the same order as the JSON text, with no text written and parsed back.

#include "meshbridge/report_json.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace meshbridge {

//! Receives a report tree depth first, SAX-style (as nlohmann-json's json_sax or RapidJSON's
//! Handler): an object is begin_object(), then key() and one value per member, then
//! end_object(); an array is begin_array(), its values, end_array(). Strings are valid UTF-8
//! (to_valid_utf8() applied, as in the text).
class ReportVisitor {
 public:
  virtual ~ReportVisitor() = default;
  virtual void begin_object() = 0;
  virtual void end_object() = 0;
  virtual void begin_array() = 0;
  virtual void end_array() = 0;
  virtual void key(std::string_view name) = 0;
  virtual void null_value() = 0;
  virtual void boolean(bool value) = 0;
  virtual void integer(std::int64_t value) = 0;            //!< a negative whole number
  virtual void unsigned_integer(std::uint64_t value) = 0;  //!< a count or index
  virtual void real(double value) = 0;
  virtual void string(std::string_view value) = 0;
};

//! One report as values. Made by check_report_tree() or repair_report_tree(); move-only.
class ReportTree {
 public:
  struct Values;  //!< the values (nlohmann::ordered_json inside the core, not in this header)
  explicit ReportTree(std::unique_ptr<Values> values);
  ReportTree(ReportTree&&) noexcept;
  ReportTree& operator=(ReportTree&&) noexcept;
  ~ReportTree();

  //! Walks the tree into `visitor`, depth first, members in the text's order.
  void visit(ReportVisitor& visitor) const;
  //! The JSON text, exactly as the *_report_json() functions write it (`indent` as
  //! ReportJsonOptions::indent: negative for one line).
  std::string text(int indent = -1) const;

 private:
  std::unique_ptr<Values> values_;
};

//! The tree of check_report_json() (same arguments, same preconditions; `options.indent` unused).
ReportTree check_report_tree(const std::string& file, const DefectReport& report,
                             const ReadInfo* read = nullptr, const ReportJsonOptions& options = {},
                             const CloseGapsReport* gaps = nullptr,
                             const SelfIntersectionReport* self_intersections = nullptr,
                             const OrientationPreview* orientation = nullptr,
                             const RepairPreview* preview = nullptr);

//! The tree of repair_report_json() (same arguments, same preconditions; `options.indent` unused).
ReportTree repair_report_tree(const std::string& file, const std::string& output,
                              const RepairReport& report, const ReadInfo* read = nullptr,
                              const ReportJsonOptions& options = {},
                              const DefectReport* reread = nullptr,
                              const WrittenOutput* written = nullptr,
                              const SelfIntersectionReport* self_intersections = nullptr);

}  // namespace meshbridge
