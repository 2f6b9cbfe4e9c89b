// SPDX-License-Identifier: GPL-3.0-or-later
// `batch` outcome lines and its child processes (batch_entry.h).

#include "batch_entry.h"

#include "meshbridge/batch_warnings.h"
#include "meshbridge/report_json.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace meshbridge::cli {

void take_result(Entry& entry, const FileJobResult& result, const FileJob& job) {
  entry.status = result.status;
  entry.reason = result.reason;
  entry.warnings = batch_warning_lines(result, job);
  entry.record = result.record;
  const RepairReport& p = result.report;
  // An STL output counts as it will be re-read (split vertex copies weld again).
  const DefectReport& after = result.reread ? *result.reread : p.after;
  entry.row = {p.faces_in,  p.before.singular_edges.size(), p.before.num_singular_vertices(),
               p.faces_out, after.num_components,           after.watertight};
  if (result.crossings)
    entry.row.crossing_pairs = static_cast<long long>(result.crossings->face_pairs.size());
}

namespace {

// With --jobs > 1 every file is repaired in a child process of its own: a file that crashes its
// child or runs it out of memory fails alone instead of ending the run, and each child's memory
// goes back to the system when it ends.
// The child sends its result over a pipe: "status faces_in singular_edges singular_vertices
// faces_out components_after watertight crossing_pairs reason_length warnings_length\n", the
// reason, the warnings, then the record.

void write_all(int fd, const std::string& data) {
  for (std::size_t done = 0; done < data.size();) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return;
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void run_child(const FileJob& job, const FileJobOptions& options, int fd) {
  // The files are the parallel work: one thread per file unless the user chose otherwise.
  ::setenv("MESHBRIDGE_THREADS", "1", 0);
  Entry entry;
  try {
    take_result(entry, run_file_job(job, options), job);
  } catch (...) {  // run_file_job catches everything it can name; out of memory while copying
    ::_exit(3);
  }
  const TableRow& r = entry.row;
  std::ostringstream head;
  head << static_cast<int>(entry.status) << ' ' << r.faces_in << ' ' << r.singular_edges << ' '
       << r.singular_vertices << ' ' << r.faces_out << ' ' << r.components_after << ' '
       << (r.watertight_after ? 1 : 0) << ' ' << r.crossing_pairs << ' ' << entry.reason.size()
       << ' ' << entry.warnings.size() << '\n';
  write_all(fd, head.str() + entry.reason + entry.warnings + entry.record);
  ::close(fd);
  ::_exit(0);
}

//! Decodes what run_child sent; false if it is incomplete.
bool decode_child(const std::string& data, Entry& entry) {
  const auto newline = data.find('\n');
  if (newline == std::string::npos)
    return false;
  std::istringstream head(data.substr(0, newline));
  int status = 0, watertight = 0;
  std::size_t reason_size = 0, reading_size = 0;
  TableRow& r = entry.row;
  if (!(head >> status >> r.faces_in >> r.singular_edges >> r.singular_vertices >> r.faces_out >>
        r.components_after >> watertight >> r.crossing_pairs >> reason_size >> reading_size) ||
      status < 0 || status > 3 || data.size() < newline + 1 + reason_size + reading_size) {
    return false;
  }
  r.watertight_after = watertight != 0;
  entry.status = static_cast<FileStatus>(status);
  entry.reason = data.substr(newline + 1, reason_size);
  entry.warnings = data.substr(newline + 1 + reason_size, reading_size);
  entry.record = data.substr(newline + 1 + reason_size + reading_size);
  return !entry.record.empty();
}

//! The `failed` entry of a child that ended without a result.
void child_failed(Entry& entry, int wait_status) {
  std::string why = "the repair process ended without a result";
  if (WIFSIGNALED(wait_status)) {
    why = "the repair process was killed by signal " + std::to_string(WTERMSIG(wait_status)) +
          " (" + strsignal(WTERMSIG(wait_status)) + ")";
  } else if (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 3) {
    why = "out of memory";
  }
  entry.status = FileStatus::failed;
  entry.reason = entry.job->input + ": " + why;
  entry.row = {};
  entry.record =
      batch_record_json(entry.name, entry.job->output_name, "failed", entry.reason, nullptr);
}

}  // namespace

void run_in_child_processes(std::vector<Entry>& entries, const std::vector<char>& done,
                            const FileJobOptions& options, unsigned jobs,
                            const std::function<void(std::size_t)>& finished) {
  struct Child {
    pid_t pid;
    int fd;
    std::size_t index;
    std::string data;
  };
  std::vector<Child> running;
  std::size_t next = 0;
  std::signal(SIGPIPE, SIG_IGN);
  for (;;) {
    while (running.size() < jobs && next < entries.size()) {
      const std::size_t i = next++;
      if (done[i])
        continue;
      int fds[2];
      if (::pipe(fds) != 0)
        throw std::runtime_error(std::string("cannot start a repair process: ") + strerror(errno));
      std::cout.flush();
      std::cerr.flush();
      const pid_t pid = ::fork();
      if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("cannot start a repair process: ") + strerror(errno));
      }
      if (pid == 0) {
        ::close(fds[0]);
        for (const Child& c : running)
          ::close(c.fd);
        run_child(*entries[i].job, options, fds[1]);
      }
      ::close(fds[1]);
      running.push_back({pid, fds[0], i, {}});
    }
    if (running.empty())
      break;
    std::vector<pollfd> polls;
    for (const Child& c : running)
      polls.push_back({c.fd, POLLIN, 0});
    if (::poll(polls.data(), polls.size(), -1) < 0) {
      if (errno == EINTR)
        continue;
      throw std::runtime_error(std::string("waiting for the repair processes: ") + strerror(errno));
    }
    for (std::size_t k = polls.size(); k-- > 0;) {
      if (polls[k].revents == 0)
        continue;
      Child& c = running[k];
      char buffer[65536];
      const ssize_t n = ::read(c.fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR)
        continue;
      if (n > 0) {
        c.data.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      ::close(c.fd);
      int wait_status = 0;
      while (::waitpid(c.pid, &wait_status, 0) < 0 && errno == EINTR) {
      }
      Entry& entry = entries[c.index];
      const bool exited_cleanly = WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0;
      if (!exited_cleanly || !decode_child(c.data, entry))
        child_failed(entry, wait_status);
      const std::size_t index = c.index;
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
      finished(index);
    }
  }
}

}  // namespace meshbridge::cli
