// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file batch_log.h
//! The batch log: one JSON Lines record per finished file, which `meshbridge batch` and the
//! Python batch (Dask) both keep in OUTDIR (default name kBatchLogName). Each line is the file's
//! batch record (batch_record_json) with one more key, `"batch_log"`, holding what a rerun needs
//! to decide whether the file must be done again: the options it was repaired with and the
//! input's size and modification time. A rerun skips a file only when its last line says `clean`
//! or `repaired`, with the same options, from the same input, and the output is still there;
//! every other file is done again (a failed or skipped one is retried).

#include "meshbridge/file_job.h"

#include <map>
#include <string>
#include <vector>

namespace meshbridge {

//! The log's name inside OUTDIR.
inline constexpr const char* kBatchLogName = ".meshbridge-batch.jsonl";

//! Every option that changes an output file or its record, as one line of text
//! ("format=3mf weld=auto t_junctions=1 pairing=geometric ..."). Equal texts, equal outputs.
std::string batch_options_text(const FileJobOptions& options);

//! The input's size and modification time ("SIZE:MTIME_NS"); "" when the file cannot be read.
std::string batch_input_stamp(const std::string& path);

//! The log line of a finished job: `record` (one JSON object, no newline) with
//! `"batch_log":{"options":...,"input":...}` added as its last key (the input stamped now).
std::string batch_log_line(const std::string& record, const FileJob& job,
                           const FileJobOptions& options);

//! The batch record inside a log line (without its `"batch_log"` key); a line without that key
//! is returned as it is.
std::string record_of_log_line(const std::string& line);

//! The `"file"` of a log line; "" when the line is not a batch record.
std::string file_of_log_line(const std::string& line);

//! Whether a rerun may skip `job`: `line` (its last log line) says `clean` or `repaired`, with
//! the same batch_options_text and the same input stamp, and the output exists. Otherwise
//! false, with `why` (when given) saying what changed.
bool is_done_in_log(const std::string& line, const FileJob& job, const FileJobOptions& options,
                    std::string* why = nullptr);

//! The log's lines by file (the last line of each file wins). A missing file gives an empty
//! map; an incomplete last line (a run killed while writing it) is ignored.
//! \throw std::runtime_error naming the log and the line when a complete line is not a record
std::map<std::string, std::string> read_batch_log(const std::string& path);

//! Replaces the log at `path` with `lines` (one per line), atomically: a rerun starts from the
//! lines of the files it keeps, and appends one line per file it finishes.
//! \throw WriteError naming the log
void write_batch_log(const std::string& path, const std::vector<std::string>& lines);

}  // namespace meshbridge
