// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"
#include "commands.h"
#include "defect_snapshot.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"

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
  write_file_atomically(path, [&](const std::string& temporary) {
    QImageWriter writer(QFile::decodeName(temporary.c_str()), QByteArrayLiteral("png"));
    if (!writer.write(image)) {
      throw WriteError(path + ": cannot write the PNG (" + writer.errorString().toStdString() +
                       ")");
    }
  });
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

}  // namespace

int snapshot_command(const std::vector<std::string>& args) {
  const Arguments arguments(args, {}, {"size", "view"});
  arguments.expect_positionals(2, "meshbridge snapshot FILE OUT.png [--size N] [--view iso|x|y|z]");
  const std::string& path = arguments.positionals()[0];
  const std::string& out = arguments.positionals()[1];

  SnapshotOptions options;
  const double size = arguments.number("size", options.size);
  if (size != std::floor(size) || size < SnapshotOptions::kMinSize ||
      size > SnapshotOptions::kMaxSize) {
    throw UsageError("--size expects a whole number of pixels from " +
                     std::to_string(SnapshotOptions::kMinSize) + " to " +
                     std::to_string(SnapshotOptions::kMaxSize) + ", got '" +
                     arguments.value("size") + "'");
  }
  options.size = static_cast<int>(size);
  try {
    options.view = parse_snapshot_view(arguments.value("view", "iso"));
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--") + error.what());
  }
  if (!ends_with_png(out))
    throw UsageError(out + ": the snapshot is written as PNG; name it .png");

  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  warn_about_reader(path, info);
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

  const DefectSnapshot snapshot = draw_defect_snapshot(soup, report, options);
  write_png_atomically(out, snapshot.image);
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

}  // namespace meshbridge::cli
