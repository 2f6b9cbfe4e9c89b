// SPDX-License-Identifier: GPL-3.0-or-later
#include "png_output.h"

#include <QBuffer>
#include <QImageWriter>
#include <QString>
#include <QtGlobal>

#include <iostream>

namespace meshbridge::cli {

namespace {

void filter_qt_message(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtCriticalMsg || type == QtFatalMsg)
    std::cerr << "meshbridge: Qt: " << message.toLocal8Bit().constData() << "\n";
}

}  // namespace

QByteArray encode_png(const QImage& image) {
  // Encoded in memory: Qt's PNG writer leaks its row buffer when libpng fails on a full disk,
  // and the executable's atomic writer names the OS reason for any failure to store the bytes.
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  QImageWriter writer(&buffer, QByteArrayLiteral("png"));
  if (!writer.write(image))
    throw PngEncodeError("cannot encode the PNG (" + writer.errorString().toStdString() + ")");
  return png;
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
