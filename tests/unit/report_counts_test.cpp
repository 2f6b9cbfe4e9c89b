// SPDX-License-Identifier: GPL-3.0-or-later
// The flat counts of a report (report_counts.h) are the JSON report's numbers (report_json.h),
// key for key, in the same order, with the same values: the MeshLab plugin's result map and
// `check --json` / `repair --report` cannot drift apart.
#include "meshbridge/report_counts.h"

#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/report_json.h"
#include "meshbridge/self_intersections.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace meshbridge {
namespace {

using Json = nlohmann::ordered_json;

//! "key=value" per number of `j`, nested keys joined with dots; text, `elements` and the header
//! (schema_version) left out, as report_counts.h leaves them out.
void flatten(const Json& j, const std::string& prefix, std::ostringstream& out) {
  for (const auto& [key, value] : j.items()) {
    if (key == "elements" || key == "schema_version")
      continue;
    if (value.is_object()) {
      flatten(value, prefix + key + ".", out);
    } else if (value.is_boolean()) {
      out << prefix << key << "=" << (value.get<bool>() ? 1 : 0) << "\n";
    } else if (value.is_number_float()) {
      out << prefix << key << "=" << value.get<double>() << "\n";
    } else if (value.is_number()) {
      out << prefix << key << "=" << value.get<long long>() << "\n";
    }
  }
}

std::string json_numbers(const std::string& json) {
  std::ostringstream out;
  flatten(Json::parse(json), "", out);
  return out.str();
}

std::string counts_text(const ReportCounts& counts) {
  std::ostringstream out;
  for (const ReportCount& c : counts) {
    out << c.name << "=";
    if (c.kind == ReportCount::Kind::real) {
      out << c.real;
    } else {
      out << c.value;
    }
    out << "\n";
  }
  return out.str();
}

TEST(ReportCounts, check_counts_are_the_json_numbers_in_order) {
  const Soup soup = models::two_cubes_sharing_edge();
  const DefectReport report = detect_defects(soup);
  CloseGapsOptions options;
  options.tolerance = 0.01;
  const CloseGapsReport gaps = preview_close_gaps(soup, options);
  const SelfIntersectionReport crossings = find_self_intersections(soup);
  ReportCounts counts;
  append_counts(counts, report);
  append_counts(counts, gaps);
  append_counts(counts, crossings);
  EXPECT_EQ(counts_text(counts), json_numbers(check_report_json("c.obj", report, nullptr,
                                                                {true, -1}, &gaps, &crossings)));
  EXPECT_EQ(find_count(counts, "singular_edges")->value, 1);
  EXPECT_EQ(find_count(counts, "euler_characteristic")->kind, ReportCount::Kind::integer);
  EXPECT_EQ(find_count(counts, "watertight")->kind, ReportCount::Kind::flag);
  EXPECT_EQ(find_count(counts, "gaps.tolerance")->kind, ReportCount::Kind::real);
  EXPECT_EQ(find_count(counts, "gaps.tolerance")->real, 0.01);
  EXPECT_EQ(find_count(counts, "no_such_key"), nullptr);
}

TEST(ReportCounts, repair_counts_are_the_json_numbers_in_order) {
  RepairOptions options;
  options.fill_holes.max_edges = 8;  // so that the JSON has `holes` too
  const RepairResult result = repair(models::two_cubes_sharing_edge(), options);
  ReportCounts counts;
  append_counts(counts, result.report);
  EXPECT_EQ(counts_text(counts), json_numbers(repair_report_json("c.obj", "", result.report)));
  EXPECT_EQ(find_count(counts, "before.singular_edges")->value, 1);
  EXPECT_EQ(find_count(counts, "after.singular_edges")->value, 0);
  EXPECT_EQ(find_count(counts, "holes.max_edges")->value, 8);
}

TEST(ReportCounts, prefix_goes_before_every_key) {
  ReportCounts counts;
  append_counts(counts, detect_defects(models::bowtie()), "reread.");
  ASSERT_EQ(counts.size(), 22u);
  for (const ReportCount& c : counts)
    EXPECT_EQ(c.name.rfind("reread.", 0), 0u) << c.name;
}

}  // namespace
}  // namespace meshbridge
