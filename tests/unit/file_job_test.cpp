// SPDX-License-Identifier: GPL-3.0-or-later
// Batch planning and one file's job: statuses, records, refusals, resume.
#include "meshbridge/file_job.h"
#include "meshbridge/io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kModels = MESHBRIDGE_MODELS_DIR;

class FileJobTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char dir_template[] = "/tmp/meshbridge_file_job_XXXXXX";
    ASSERT_NE(mkdtemp(dir_template), nullptr);
    root_ = dir_template;
    in_ = root_ / "in";
    fs::create_directories(in_ / "sub");
    fs::copy_file(kModels / "twocubes.obj", in_ / "twocubes.obj");
    fs::copy_file(kModels / "twocubes.off", in_ / "twocubes.off");
    fs::copy_file(kModels / "icosphere.obj", in_ / "sub" / "ico.obj");
    std::ofstream(in_ / "notes.txt") << "not a mesh\n";
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_, in_;
};

TEST_F(FileJobTest, plan_lists_meshes_sorted_with_outputs_below_outdir) {
  const BatchPlan plan = plan_batch(in_.string(), (root_ / "out").string(), {});
  ASSERT_EQ(plan.jobs.size(), 3u);
  EXPECT_EQ(plan.jobs[0].name, "sub/ico.obj");
  EXPECT_EQ(plan.jobs[1].name, "twocubes.obj");
  EXPECT_EQ(plan.jobs[2].name, "twocubes.off");
  EXPECT_EQ(plan.jobs[0].output, (root_ / "out" / "sub" / "ico.obj").string());
  EXPECT_TRUE(plan.unreadable.empty());
}

TEST_F(FileJobTest, plan_renames_outputs_that_would_meet_in_one_format) {
  FileJobOptions options;
  options.format = "PLY";
  const BatchPlan plan = plan_batch(in_.string(), (root_ / "out").string(), options);
  ASSERT_EQ(plan.jobs.size(), 3u);
  EXPECT_EQ(plan.jobs[1].output_name, "twocubes.ply");
  EXPECT_EQ(plan.jobs[2].output_name, "twocubes-off.ply");
}

// The renamed output must not be another file's own: a-off.off keeps a-off.ply, so a.off (which
// meets a.obj in a.ply) becomes a-off-2.ply; every output is distinct.
TEST_F(FileJobTest, renamed_outputs_never_take_another_files_output) {
  fs::copy_file(kModels / "twocubes.off", in_ / "twocubes-off.off");
  fs::copy_file(kModels / "twocubes.off", in_ / "twocubes-off-2.off");
  FileJobOptions options;
  options.format = "ply";
  const BatchPlan plan = plan_batch(in_.string(), (root_ / "out").string(), options);
  std::vector<std::string> outputs;
  for (const FileJob& job : plan.jobs)
    outputs.push_back(job.name + " -> " + job.output_name);
  EXPECT_EQ(outputs, (std::vector<std::string>{
                         "sub/ico.obj -> sub/ico.ply", "twocubes-off-2.off -> twocubes-off-2.ply",
                         "twocubes-off.off -> twocubes-off.ply", "twocubes.obj -> twocubes.ply",
                         "twocubes.off -> twocubes-off-3.ply"}));
}

// A file already in the output format keeps its own name, so that with --in-place its result
// replaces it and not another file's.
TEST_F(FileJobTest, a_file_in_the_output_format_keeps_its_own_name) {
  fs::copy_file(kModels / "twocubes.off", in_ / "twocubes.ply.off");
  std::ofstream(in_ / "twocubes.ply") << "not read by the plan\n";
  FileJobOptions options;
  options.format = "ply";
  const BatchPlan plan = plan_batch(in_.string(), in_.string(), options, /*in_place=*/true);
  std::vector<std::string> outputs;
  for (const FileJob& job : plan.jobs)
    outputs.push_back(job.name + " -> " + job.output_name);
  EXPECT_EQ(outputs, (std::vector<std::string>{
                         "sub/ico.obj -> sub/ico.ply", "twocubes.obj -> twocubes-obj.ply",
                         "twocubes.off -> twocubes-off.ply", "twocubes.ply -> twocubes.ply",
                         "twocubes.ply.off -> twocubes.ply.ply"}));
}

TEST_F(FileJobTest, plan_refuses_outdir_equal_to_or_inside_indir) {
  EXPECT_THROW(plan_batch(in_.string(), in_.string(), {}), std::invalid_argument);
  EXPECT_THROW(plan_batch(in_.string(), (in_ / "sub" / "out").string(), {}), std::invalid_argument);
  EXPECT_THROW(plan_batch(in_.string(), (in_ / "." / "x" / "..").string(), {}),
               std::invalid_argument);
  try {
    plan_batch(in_.string(), (in_ / "out").string(), {});
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("inside the input folder"), std::string::npos);
  }
  // A sibling whose name starts like INDIR is not inside it.
  EXPECT_NO_THROW(plan_batch(in_.string(), (root_ / "in2").string(), {}));
  const BatchPlan in_place = plan_batch(in_.string(), in_.string(), {}, true);
  ASSERT_EQ(in_place.jobs.size(), 3u);
  EXPECT_EQ(in_place.jobs[0].output, in_place.jobs[0].input);
  EXPECT_THROW(plan_batch((root_ / "missing").string(), (root_ / "out").string(), {}),
               std::invalid_argument);
  FileJobOptions bad;
  bad.format = "dxf";
  EXPECT_THROW(plan_batch(in_.string(), (root_ / "out").string(), bad), std::invalid_argument);
}

TEST_F(FileJobTest, run_reports_repaired_clean_and_failed) {
  const BatchPlan plan = plan_batch(in_.string(), (root_ / "out").string(), {});
  const FileJobResult ico = run_file_job(plan.jobs[0]);
  EXPECT_EQ(ico.status, FileStatus::clean);
  EXPECT_TRUE(fs::exists(plan.jobs[0].output));
  const json j = json::parse(ico.record);
  EXPECT_EQ(j["status"], "clean");
  EXPECT_EQ(j["file"], "sub/ico.obj");
  EXPECT_EQ(j["output"], "sub/ico.obj");
  EXPECT_EQ(j["faces_out"], 80);

  const FileJobResult cubes = run_file_job(plan.jobs[1]);
  EXPECT_EQ(cubes.status, FileStatus::repaired);
  EXPECT_EQ(cubes.report.vertices_out, 16u);
  EXPECT_EQ(json::parse(cubes.record)["before"]["singular_edges"], 1);
  EXPECT_EQ(read_soup(plan.jobs[1].output).num_vertices(), 16u);

  std::ofstream(in_ / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
  const FileJob broken{(in_ / "broken.obj").string(), (root_ / "out" / "broken.obj").string(),
                       "broken.obj", "broken.obj"};
  const FileJobResult failed = run_file_job(broken);
  EXPECT_EQ(failed.status, FileStatus::failed);
  EXPECT_NE(failed.reason.find("broken.obj"), std::string::npos);
  EXPECT_FALSE(fs::exists(broken.output));
  EXPECT_EQ(json::parse(failed.record)["reason"], failed.reason);
}

TEST_F(FileJobTest, clean_means_the_mesh_is_written_as_read) {
  // A tetrahedron with a vertex no face uses: not a defect, so clean as it is; removing the
  // vertex changes the mesh, so the file is "repaired", not "clean".
  std::ofstream(in_ / "lone.obj")
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const FileJob job{(in_ / "lone.obj").string(), (root_ / "out" / "lone.obj").string(), "lone.obj",
                    "lone.obj"};
  EXPECT_EQ(run_file_job(job).status, FileStatus::clean);
  EXPECT_EQ(read_soup(job.output).num_vertices(), 5u);
  FileJobOptions removing;
  removing.repair.remove_isolated_vertices = true;
  const FileJobResult removed = run_file_job(job, removing);
  EXPECT_EQ(removed.status, FileStatus::repaired);
  EXPECT_EQ(removed.report.isolated_vertices_removed, 1u);
  EXPECT_EQ(read_soup(job.output).num_vertices(), 4u);
}

TEST_F(FileJobTest, resume_skips_outputs_newer_than_their_input) {
  FileJobOptions options;
  options.resume = true;
  const BatchPlan plan = plan_batch(in_.string(), (root_ / "out").string(), options);
  EXPECT_EQ(run_file_job(plan.jobs[1], options).status, FileStatus::repaired);
  const FileJobResult again = run_file_job(plan.jobs[1], options);
  EXPECT_EQ(again.status, FileStatus::skipped);
  EXPECT_NE(again.reason.find("newer than the input"), std::string::npos);
  fs::last_write_time(plan.jobs[1].input,
                      fs::last_write_time(plan.jobs[1].output) + std::chrono::seconds(5));
  EXPECT_EQ(run_file_job(plan.jobs[1], options).status, FileStatus::repaired);
}

TEST_F(FileJobTest, an_output_folder_that_cannot_be_made_fails_naming_it) {
  std::ofstream(root_ / "file") << "x";
  const FileJob job{(in_ / "twocubes.obj").string(), (root_ / "file" / "a" / "t.obj").string(),
                    "twocubes.obj", "a/t.obj"};
  const FileJobResult result = run_file_job(job);
  EXPECT_EQ(result.status, FileStatus::failed);
  EXPECT_NE(result.reason.find("cannot create the folder"), std::string::npos) << result.reason;
  EXPECT_NE(result.reason.find((root_ / "file" / "a").string()), std::string::npos);
}

}  // namespace
}  // namespace meshbridge
