// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/batch_log.h"

#include "meshbridge/report_json.h"

#include "io/atomic_write.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace meshbridge {

namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kKey = ",\"batch_log\":";

std::string number_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

//! The line parsed, or a discarded value when it is not JSON.
Json parse(const std::string& line) {
  return Json::parse(line, nullptr, false);
}

}  // namespace

std::string batch_options_text(const FileJobOptions& options) {
  const RepairOptions& r = options.repair;
  std::string format = options.format;
  for (char& c : format)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::ostringstream text;
  text << "format=" << (format.empty() ? "same" : format) << " weld="
       << (r.close_gaps.tolerance == kAutoWeldTolerance ? std::string("auto")
                                                        : number_text(r.close_gaps.tolerance))
       << " t_junctions=" << r.close_gaps.close_t_junctions
       << " pairing=" << (r.pairing == PairingPolicy::combinatorial ? "combinatorial" : "geometric")
       << " orient=" << r.orient << " stitch=" << r.stitch
       << " cut_nonorientable=" << r.cut_nonorientable
       << " remove_duplicates=" << r.remove_duplicate_faces
       << " remove_degenerate=" << r.remove_degenerate_faces
       << " remove_zero_area=" << r.remove_zero_area_faces
       << " remove_isolated=" << r.remove_isolated_vertices
       << " detect_before_after=" << r.detect_before_after
       << " fill_holes=" << r.fill_holes.max_edges
       << " nested_shells=" << (r.nested_shells == AmbiguousNesting::cavity ? "cavity" : "material")
       << " elements=" << options.elements
       << " separate_stl_copies=" << options.separate_stl_copies;
  if (options.print) {  // (only when on: logs written before --print existed stay valid)
    text << " print=1 print_keeps_weld=" << options.print_keeps_weld
         << " print_keeps_fill_holes=" << options.print_keeps_fill_holes;
  }
  if (options.self_intersections)  // (only when on, as print)
    text << " self_intersections=1";
  return text.str();
}

std::string batch_input_stamp(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    return "";
  const long long ns = static_cast<long long>(info.st_mtim.tv_sec) * 1000000000LL +
                       static_cast<long long>(info.st_mtim.tv_nsec);
  return std::to_string(static_cast<long long>(info.st_size)) + ":" + std::to_string(ns);
}

std::string batch_log_line(const std::string& record, const FileJob& job,
                           const FileJobOptions& options) {
  if (record.empty() || record.back() != '}')
    throw std::invalid_argument("batch_log_line: the record is not one JSON object");
  const Json extra = {{"options", batch_options_text(options)},
                      {"input", batch_input_stamp(job.input)}};
  return record.substr(0, record.size() - 1) + kKey + extra.dump() + "}";
}

std::string record_of_log_line(const std::string& line) {
  const auto at = line.rfind(kKey);
  return at == std::string::npos ? line : line.substr(0, at) + "}";
}

std::string file_of_log_line(const std::string& line) {
  const Json json = parse(line);
  if (!json.is_object() || !json.contains("file") || !json["file"].is_string())
    return "";
  return json["file"].get<std::string>();
}

bool is_done_in_log(const std::string& line, const FileJob& job, const FileJobOptions& options,
                    std::string* why) {
  const auto no = [why](const std::string& reason) {
    if (why)
      *why = reason;
    return false;
  };
  const Json json = parse(line);
  if (!json.is_object() || !json.contains("status"))
    return no("not in the log");
  const std::string status = json["status"].is_string() ? json["status"].get<std::string>() : "";
  if (status != "clean" && status != "repaired")
    return no("its last run ended " + status);
  if (!json.contains("batch_log") || !json["batch_log"].is_object())
    return no("the log does not say how it was made");
  const Json& log = json["batch_log"];
  if (log.value("options", "") != batch_options_text(options))
    return no("the options changed");
  if (log.value("input", "") != batch_input_stamp(job.input))
    return no("the input changed");
  if (json.value("output", "") != to_valid_utf8(job.output_name))
    return no("the output's name changed");
  std::error_code error;
  if (!std::filesystem::exists(job.output, error))
    return no("the output is missing");
  return true;
}

std::map<std::string, std::string> read_batch_log(const std::string& path) {
  std::map<std::string, std::string> lines;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return lines;
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t end = data.rfind('\n') == std::string::npos ? 0 : data.rfind('\n') + 1;
  std::size_t number = 0;
  for (std::size_t at = 0; at < end;) {
    const std::size_t next = data.find('\n', at);
    const std::string line = data.substr(at, next - at);
    at = next + 1;
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    const std::string file = file_of_log_line(line);
    if (file.empty())
      throw std::runtime_error(path + ", line " + std::to_string(number) + ": not a batch record");
    lines[file] = line;
  }
  return lines;
}

void write_batch_log(const std::string& path, const std::vector<std::string>& lines) {
  detail::write_atomically(path, [&lines](detail::AtomicOutput& out) {
    for (const std::string& line : lines) {
      out.write(line);
      out.write("\n");
    }
  });
}

}  // namespace meshbridge
