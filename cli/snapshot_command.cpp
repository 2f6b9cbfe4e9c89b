// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"
#include "defect_snapshot.h"
#include "paths.h"
#include "progress.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <CLI/CLI.hpp>

#include <QByteArray>
#include <QFile>
#include <QGuiApplication>
#include <QImageWriter>
#include <QString>
#include <QtGlobal>

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>

namespace meshbridge::cli {

namespace {

bool ends_with_png(std::string path) {
  for (auto& ch : path)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".png") == 0;
}

//! Writes `image` as PNG under a hidden temporary name beside `path` and renames it into place,
//! so on any error the previous file at `path` is untouched and nothing half-written is left.
//! \throw WriteError naming the path and the reason
void write_png_atomically(const std::string& path, const QImage& image) {
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string temporary = dir + "." + name + ".tmp" + std::to_string(::getpid()) + ".png";
  QImageWriter writer(QFile::decodeName(temporary.c_str()), QByteArrayLiteral("png"));
  errno = 0;
  if (!writer.write(image)) {
    // Qt says "Unknown error" for a full disk; the OS reason, when there is one, says more.
    const std::string reason =
        errno != 0 ? std::strerror(errno) : writer.errorString().toStdString();
    std::remove(temporary.c_str());
    throw WriteError(path + ": cannot write the PNG (" + reason + ")");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw WriteError(path + ": cannot move the written file into place (" + reason + ")");
  }
}

//! While alive, Qt's debug output and warnings are dropped (offscreen they are chatter such as
//! "QStandardPaths: XDG_RUNTIME_DIR not set", and stderr is for our one-line messages); its
//! critical and fatal messages still reach stderr, prefixed "meshbridge: Qt: ".
class QtMessageFilter {
 public:
  QtMessageFilter() : previous_(qInstallMessageHandler(&QtMessageFilter::handle)) {}
  ~QtMessageFilter() { qInstallMessageHandler(previous_); }
  QtMessageFilter(const QtMessageFilter&) = delete;
  QtMessageFilter& operator=(const QtMessageFilter&) = delete;

 private:
  static void handle(QtMsgType type, const QMessageLogContext&, const QString& message) {
    if (type == QtCriticalMsg || type == QtFatalMsg)
      std::cerr << "meshbridge: Qt: " << message.toLocal8Bit().constData() << "\n";
  }
  QtMessageHandler previous_;
};

struct SnapshotArguments {
  std::string file, out;
  std::string view = "iso";
  SnapshotOptions options;
  bool progress = false;
};

int run_snapshot(const SnapshotArguments& arguments) {
  const std::string& path = arguments.file;
  const std::string& out = arguments.out;
  SnapshotOptions options = arguments.options;
  options.view = parse_snapshot_view(arguments.view);
  if (!ends_with_png(out))
    throw UsageError(out + ": the snapshot is written as PNG; name it .png");
  check_readable_file(path);
  check_writable_file(out);

  ProgressDisplay progress(path, progress_wanted(arguments.progress), progress_wanted(false),
                           snapshot_plan());
  progress.stage(Stage::read, 0);
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  progress.stage(Stage::detect, 0);
  const DefectReport report = detect_defects(soup);

  // Fonts need a QGuiApplication; the "offscreen" platform needs no display. A platform the
  // user chose through QT_QPA_PLATFORM is respected.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
  const QtMessageFilter filter;
  static int app_argc = 1;
  static char app_name[] = "meshbridge";
  static char* app_argv[] = {app_name, nullptr};
  const QGuiApplication application(app_argc, app_argv);

  progress.stage(Stage::write, 0);
  const DefectSnapshot snapshot = draw_defect_snapshot(soup, report, options);
  write_png_atomically(out, snapshot.image);
  progress.finish();
  warn_about_reader(path, info);
  if (options.legend && !snapshot.legend_drawn) {
    std::cerr << "meshbridge: warning: text does not render here (no font found); " << out
              << " has no legend\n";
  }
  std::cout << path << " -> " << out << " (" << options.size << "x" << options.size << ", view "
            << to_string(options.view) << "): " << report.singular_edges.size()
            << " singular edges, " << report.num_singular_vertices() << " singular vertices, "
            << report.boundary_edges.size() << " boundary edges; red pixels " << snapshot.red_pixels
            << ", green pixels " << snapshot.green_pixels << "\n";
  return report.has_defects() || info.faces_dropped_by_reader > 0 ? kDefectsFound : kOk;
}

}  // namespace

void add_snapshot_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<SnapshotArguments>();
  CLI::App* command = app.add_subcommand(
      "snapshot",
      "Draw FILE with its defects into a PNG (no display needed): the surface shaded grey,\n"
      "boundary edges green, singular edges and vertices red. Exit codes as check.");
  command->add_option("FILE", arguments->file, "mesh to draw (.obj, .off, .ply, .stl)")->required();
  command->add_option("OUT.png", arguments->out, "PNG to write; replaced atomically")->required();
  command->add_option("--size", arguments->options.size, "width and height in pixels")
      ->check(CLI::Range(SnapshotOptions::kMinSize, SnapshotOptions::kMaxSize));
  command
      ->add_option("--view", arguments->view,
                   "look from: iso (above a corner), x, y or z (along that axis)")
      ->transform(CLI::IsMember({"iso", "x", "y", "z"}, CLI::ignore_case));
  command->add_flag("--progress", arguments->progress,
                    "show the stage and a progress bar on stderr even when it is not a terminal "
                    "(on a terminal it shows anyway once the work takes over a second)");
  command->callback([arguments, &exit_code] { exit_code = run_snapshot(*arguments); });
}

}  // namespace meshbridge::cli
