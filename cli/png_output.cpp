// SPDX-License-Identifier: GPL-3.0-or-later
#include "png_output.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <QBuffer>
#include <QByteArray>
#include <QImageWriter>
#include <QString>
#include <QtGlobal>

#include <iostream>
#include <string_view>

namespace meshbridge::cli {

namespace {

void filter_qt_message(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtCriticalMsg || type == QtFatalMsg)
    std::cerr << "meshbridge: Qt: " << message.toLocal8Bit().constData() << "\n";
}

}  // namespace

void write_png_atomically(const std::string& path, const QImage& image) {
  // Encoded in memory first: Qt's PNG writer leaks its row buffer when libpng fails on a full
  // disk, and our atomic writer names the OS reason for any failure to store the bytes.
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  QImageWriter writer(&buffer, QByteArrayLiteral("png"));
  if (!writer.write(image))
    throw WriteError(path + ": cannot encode the PNG (" + writer.errorString().toStdString() + ")");
  write_bytes_atomically(path,
                         std::string_view(png.constData(), static_cast<std::size_t>(png.size())));
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
