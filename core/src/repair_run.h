// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file repair_run.h
//! One run of meshbridge::repair() on a valid soup, as the algorithm's steps over the state
//! they share (Shovhelia & Sokolova 2020, DESIGN sections 4 and 8a). Private to the core.

#include "meshbridge/repair.h"

#include "pipeline/grouping.h"
#include "pipeline/run_pipeline.h"
#include "working_soup.h"

#include <future>
#include <memory>
#include <optional>

namespace meshbridge::detail {

//! What repair() already made of the input before deciding to run the steps (the clean-input
//! shortcut makes it), handed on so that nothing is made twice. Empty: the run makes it all.
struct KnownInput {
  const WorkingSoup* simple = nullptr;  //!< the input made simple (outlives the run); null: make it
  std::optional<DefectReport> before;   //!< its detection; empty: detect when needed
  //! its detection still being made beside the run (detect_alongside(), reading `*simple`);
  //! not valid: none. Taken after pairing.
  std::future<DefectReport> before_later;
  GroupedSides grouped;  //!< its grouping; no contenders: group again
};

//! What the no-new-defects rule compares (DESIGN 8a): the input's open edges (one side), its
//! singular edges with an odd number of sides (each may leave one side open), and the output's
//! open edges and non-orientable components.
//! Which detections a run makes, when RepairOptions::detect_before_after (or a removal option)
//! asks for them.
enum class Detections {
  before_and_after,  //!< report.before and report.after (repair())
  before_only,       //!< report.before; report.after and its counts left empty (check's forecast)
};

struct DefectBalance {
  std::size_t open_edges_in = 0;
  std::size_t odd_singular_edges_in = 0;
  std::size_t open_edges_out = 0;
  std::size_t nonorientable_out = 0;
};

//! Everything repair() does on a valid soup, in this order (run()): group the input's sides,
//! close gaps, detect the input, group the closed soup, clean up, pair/orient/emit, compose
//! origins, remove isolated vertices, fill holes, detect the output. Whether gap closing stays is
//! decided by the caller (repair_guarded() in repair.cpp) from the balance().
class RepairRun {
 public:
  //! `input` and `options` must outlive the run; `input` is valid (validate_soup()).
  RepairRun(const Soup& input, const RepairOptions& options, KnownInput&& known,
            Detections detections = Detections::before_and_after);
  RepairRun(const RepairRun&) = delete;
  RepairRun& operator=(const RepairRun&) = delete;

  //! Runs every step once; the result's origins map to `input`.
  RepairResult run();
  //! The counts the no-new-defects rule reads; complete after run().
  const DefectBalance& balance() const { return balance_; }

 private:
  void group_input();
  void close_gaps();
  void detect_input();
  void group_closed_soup();
  void clean_up();
  void pair_orient_emit();
  void compose_origins();
  void fill_holes();
  void count();
  void detect_output();
  void tell(Stage stage, double fraction) const;

  const Soup& input_;
  const RepairOptions& options_;
  KnownInput known_;
  const bool filtering_;  //!< a removal option is on
  const bool detecting_;  //!< report.before/after are made
  const Detections detections_;
  bool before_later_ = false;

  std::optional<WorkingSoup> own_simple_;  //!< the input made simple, when not known
  const WorkingSoup* input_simple_ = nullptr;
  GroupedSides grouped_;  //!< the sides the pipeline will pair
  ClosedGaps gaps_;
  bool gaps_closed_ = false;
  std::unique_ptr<WorkingSoup> closed_simple_;  //!< the closed soup made simple
  const WorkingSoup* simple_ = nullptr;         //!< input_simple_ or closed_simple_
  //! Cleanup and keyholes: the simple polygons kept (a keyhole polygon's triangles in place of
  //! its loops), with face and corner origins in the input; made only when one of them applies.
  Soup filtered_;
  std::vector<Index> filtered_face_origin_, filtered_corner_origin_;
  std::unique_ptr<WorkingSoup> filtered_working_;
  //! Keyhole polygons that cleanup removed (their loops counted as removed), and the faces
  //! their triangles would have added beyond their loops.
  std::size_t keyholes_removed_ = 0, keyhole_faces_not_added_ = 0;
  const WorkingSoup* working_ = nullptr;  //!< what the pipeline reads
  PipelineResult pipeline_;
  RepairResult result_;
  DefectBalance balance_;
};

//! repair() of a valid soup held to the no-new-defects rule for gap closing (DESIGN 8a): a run
//! with gap closing, and when what it closed does not pay, a second run without it (repair.cpp).
//! `known` is what the caller already made of `input`.
RepairResult repair_guarded(const Soup& input, const RepairOptions& options, KnownInput&& known,
                            Detections detections = Detections::before_and_after);

}  // namespace meshbridge::detail
