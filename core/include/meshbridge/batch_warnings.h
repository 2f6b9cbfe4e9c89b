// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file batch_warnings.h
//! The warnings of one batch file, and which of them are harmless. `meshbridge batch` and the
//! Python batch both print lost data (texture coordinates, normals, groups, colours, a unit,
//! faces a reader split or set aside) one line per file, and each harmless kind (STL solid names,
//! 32-bit float rounding, PLY comments) once for the whole batch with the number of files.

#include "meshbridge/file_job.h"

#include <string>

namespace meshbridge {

//! The warning lines of a finished job, one per line ("\n"-terminated): what the reader changed
//! (FileJobResult::reading), then "output NAME: WHAT" for each thing the output format left out
//! (FileJobResult::written.left_out); "" when there is none.
std::string batch_warning_lines(const FileJobResult& result, const FileJob& job);

//! The harmless kind a warning line is of (a fixed text without the file's own numbers), or ""
//! when the line reports lost data or a change and must be printed for its file.
std::string harmless_warning_kind(const std::string& line);

}  // namespace meshbridge
