// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file py_file_job.h
//! The core's per-file batch work (file_job.h) for meshbridge.batch: the same planning, the same
//! read -> repair -> write and the same JSON Lines record as `meshbridge batch`.

#include <pybind11/pybind11.h>

namespace meshbridge::python {

//! Adds FileJobOptions, plan_batch, run_file_job, skipped_record and failed_record to `m`.
void bind_file_job(pybind11::module_& m);

}  // namespace meshbridge::python
