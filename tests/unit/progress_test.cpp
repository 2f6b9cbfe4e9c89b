// SPDX-License-Identifier: GPL-3.0-or-later
// RepairOptions::progress: told every stage's start and end, in order, on the calling thread.
#include "meshbridge/progress.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace meshbridge {
namespace {

TEST(Progress, repair_tells_each_stage_start_and_end_in_order) {
  std::vector<std::string> calls;
  const std::thread::id caller = std::this_thread::get_id();
  RepairOptions options;
  options.progress = [&](Stage stage, double fraction) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    calls.push_back(std::string(to_string(stage)) + " " + std::to_string(int(fraction * 100)));
  };
  const RepairResult result = repair(models::two_cubes_sharing_edge(), options);
  EXPECT_EQ(result.report.faces_out, 24u);
  const std::vector<std::string> expected = {"group 0",  "group 100", "pair 0",
                                             "pair 100", "detect 0",  "detect 100"};
  EXPECT_EQ(calls, expected);
}

TEST(Progress, cleanup_options_keep_the_same_stages) {
  std::vector<Stage> stages;
  RepairOptions options;
  options.remove_duplicate_faces = true;
  options.progress = [&](Stage stage, double) { stages.push_back(stage); };
  repair(models::two_cubes_sharing_edge(), options);
  const std::vector<Stage> expected = {Stage::group, Stage::group,  Stage::pair,
                                       Stage::pair,  Stage::detect, Stage::detect};
  EXPECT_EQ(stages, expected);
}

TEST(Progress, stage_names) {
  EXPECT_STREQ(to_string(Stage::read), "read");
  EXPECT_STREQ(to_string(Stage::group), "group");
  EXPECT_STREQ(to_string(Stage::pair), "pair");
  EXPECT_STREQ(to_string(Stage::detect), "detect");
  EXPECT_STREQ(to_string(Stage::write), "write");
}

}  // namespace
}  // namespace meshbridge
