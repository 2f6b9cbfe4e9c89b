// SPDX-License-Identifier: GPL-3.0-or-later
#include "png_output.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <QByteArray>
#include <QFile>
#include <QImageWriter>
#include <QString>
#include <QtGlobal>

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace meshbridge::cli {

namespace {

void filter_qt_message(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtCriticalMsg || type == QtFatalMsg)
    std::cerr << "meshbridge: Qt: " << message.toLocal8Bit().constData() << "\n";
}

}  // namespace

bool ends_with_png(std::string path) {
  for (auto& ch : path)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".png") == 0;
}

void write_png_atomically(const std::string& path, const QImage& image) {
  write_file_atomically(path, [&](const std::string& temporary) {
    QImageWriter writer(QFile::decodeName(temporary.c_str()), QByteArrayLiteral("png"));
    errno = 0;
    if (!writer.write(image)) {
      // Qt says "Unknown error" for a full disk; the OS reason, when there is one, says more.
      const std::string reason =
          errno != 0 ? std::strerror(errno) : writer.errorString().toStdString();
      throw WriteError(path + ": cannot write the PNG (" + reason + ")");
    }
  });
}

OffscreenQt::OffscreenQt() : previous_(qInstallMessageHandler(&filter_qt_message)) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
  static int argc = 1;
  static char name[] = "meshbridge";
  static char* argv[] = {name, nullptr};
  application_ = std::make_unique<QGuiApplication>(argc, argv);
}

OffscreenQt::~OffscreenQt() {
  application_.reset();
  qInstallMessageHandler(previous_);
}

}  // namespace meshbridge::cli
