// SPDX-License-Identifier: GPL-3.0-or-later
// The report schema (docs/report-schema.md): keys, counts by default, element lists on request,
// and valid JSON for any path bytes.
#include "meshbridge/report_json.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace meshbridge {
namespace {

using nlohmann::json;

TEST(ReportJson, check_has_counts_only_by_default) {
  const DefectReport r = detect_defects(models::two_cubes_sharing_edge());
  const json j = json::parse(check_report_json("two cubes.obj", r));
  EXPECT_EQ(j["schema_version"], kReportSchemaVersion);
  EXPECT_EQ(j["kind"], "check");
  EXPECT_EQ(j["file"], "two cubes.obj");
  EXPECT_EQ(j["faces"], 24);
  EXPECT_EQ(j["singular_edges"], 1);
  EXPECT_EQ(j["singular_edge_contenders"], 4);
  EXPECT_EQ(j["singular_vertices"], 2);
  EXPECT_EQ(j["boundary_edges"], 0);
  EXPECT_EQ(j["watertight"], false);
  EXPECT_EQ(j["has_defects"], true);
  EXPECT_FALSE(j.contains("elements"));
  EXPECT_FALSE(j.contains("read"));
  // One object on one line: JSON Lines.
  EXPECT_EQ(check_report_json("x", r).find('\n'), std::string::npos);
}

TEST(ReportJson, check_lists_elements_on_request) {
  const DefectReport r = detect_defects(models::two_cubes_sharing_edge());
  ReadInfo read;
  read.declared_faces = 24;
  read.faces_kept = 24;
  const json j = json::parse(check_report_json("c.obj", r, &read, {true, 2}));
  ASSERT_TRUE(j.contains("elements"));
  const json& e = j["elements"];
  ASSERT_EQ(e["singular_edges"].size(), 1u);
  EXPECT_EQ(e["singular_edges"][0]["contenders"], 4);
  EXPECT_EQ(e["singular_edges"][0]["vertices"].size(), 2u);
  EXPECT_EQ(e["singular_edge_vertices"].size(), 2u);
  EXPECT_TRUE(e["boundary_edges"].empty());
  EXPECT_EQ(j["read"]["declared_faces"], 24);
  EXPECT_EQ(j["read"]["faces_kept"], 24);
  EXPECT_EQ(j["read"]["lone_points"], 0);
}

TEST(ReportJson, repair_nests_before_and_after_with_the_check_keys) {
  const RepairResult r = repair(models::two_cubes_sharing_edge());
  const json j = json::parse(repair_report_json("in.obj", "out.ply", r.report));
  EXPECT_EQ(j["kind"], "repair");
  EXPECT_EQ(j["file"], "in.obj");
  EXPECT_EQ(j["output"], "out.ply");
  EXPECT_EQ(j["faces_in"], 24);
  EXPECT_EQ(j["faces_out"], 24);
  EXPECT_EQ(j["vertices_out"], 16);
  EXPECT_EQ(j["before"]["singular_edges"], 1);
  EXPECT_EQ(j["after"]["singular_edges"], 0);
  EXPECT_EQ(j["after"]["singular_vertices"], 0);
  EXPECT_EQ(j["after"]["components"], 2);
  EXPECT_EQ(j["after"]["watertight"], true);
  EXPECT_FALSE(j["before"].contains("elements"));
  EXPECT_FALSE(j.contains("components_before"));  // renamed: before.components
  const json with = json::parse(repair_report_json("in.obj", "", r.report, nullptr, {true, -1}));
  EXPECT_FALSE(with.contains("output"));
  EXPECT_EQ(with["before"]["elements"]["singular_edges"].size(), 1u);
  EXPECT_TRUE(with["after"]["elements"]["singular_edges"].empty());
}

TEST(ReportJson, paths_with_quotes_backslashes_and_control_characters_round_trip) {
  const DefectReport r = detect_defects(models::bowtie());
  const std::string path = "dir \"q\"\\back\\slash\ttab\nline/ü€.obj";
  const json j = json::parse(check_report_json(path, r));
  EXPECT_EQ(j["file"], path);
}

TEST(ReportJson, non_utf8_bytes_become_replacement_characters) {
  const DefectReport r = detect_defects(models::bowtie());
  // Latin-1 "café" and a lone continuation byte and a truncated sequence.
  const std::string path = std::string("caf\xE9/x\x80y\xE2\x82.obj");
  const std::string text = check_report_json(path, r);
  const json j = json::parse(text);  // strict UTF-8 parse
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(j["file"], "caf" + fffd + "/x" + fffd + "y" + fffd + ".obj");
  EXPECT_EQ(to_valid_utf8(path), j["file"].get<std::string>());
  EXPECT_EQ(to_valid_utf8("plain ü"), "plain ü");
}

TEST(ReportJson, batch_record_of_a_failure_has_reason_and_no_counts) {
  const json j = json::parse(batch_record_json("a.obj", "a.ply", "failed", "a.obj: bad", nullptr));
  EXPECT_EQ(j["kind"], "batch");
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["reason"], "a.obj: bad");
  EXPECT_FALSE(j.contains("faces_in"));
  const RepairResult r = repair(models::icosphere());
  const json ok = json::parse(batch_record_json("i.obj", "i.obj", "clean", "", &r.report));
  EXPECT_FALSE(ok.contains("reason"));
  EXPECT_EQ(ok["faces_out"], 80);
  EXPECT_EQ(ok["after"]["watertight"], true);
}

TEST(ReportJson, compare_has_the_same_figures_on_both_sides) {
  BuildFigures stock{38, 24, 6, 0, 30, 10}, bridged{16, 24, 0, 0, 0, 2};
  const json j = json::parse(compare_report_json("c.obj", 14, 24, stock, bridged));
  EXPECT_EQ(j["kind"], "compare");
  EXPECT_EQ(j["stock"]["vertices"], 38);
  EXPECT_EQ(j["bridged"]["components"], 2);
  EXPECT_EQ(j["faces"], 24);
}

}  // namespace
}  // namespace meshbridge
