// SPDX-License-Identifier: GPL-3.0-or-later
#include "zbuffer_canvas.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace meshbridge::cli {

ZBufferCanvas::ZBufferCanvas(int width, int height, const QColor& background)
    : image_(width, height, QImage::Format_ARGB32),
      depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
             -std::numeric_limits<float>::infinity()),
      background_(background.rgb()),
      width_(width),
      height_(height) {
  if (image_.isNull())
    throw std::bad_alloc();
  image_.fill(background);
}

void ZBufferCanvas::fill_triangle(const CanvasPoint& a, const CanvasPoint& b, const CanvasPoint& c,
                                  QRgb color) {
  const int width = image_.width(), height = image_.height();
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
  const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
  const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
  if (x0 > x1 || y0 > y1)
    return;
  bool covered = false;
  if (std::abs(area) > 1e-12) {
    const double inverse = 1 / area;
    for (int y = y0; y <= y1; ++y) {
      QRgb* row = reinterpret_cast<QRgb*>(image_.scanLine(y));
      float* depth_row = depth_.data() + static_cast<std::size_t>(y) * width;
      float* far_row =
          farthest_.empty() ? nullptr : farthest_.data() + static_cast<std::size_t>(y) * width;
      const double py = y + 0.5;
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5;
        // Barycentric weights from the edge functions; the sign of `area` covers both windings.
        const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) * inverse;
        const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) * inverse;
        const double wc = 1 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0)
          continue;
        covered = true;
        const float depth = static_cast<float>(wa * a.depth + wb * b.depth + wc * c.depth);
        if (depth > depth_row[x]) {
          depth_row[x] = depth;
          row[x] = color;
        }
        if (far_row != nullptr && depth < far_row[x])
          far_row[x] = depth;
      }
    }
  }
  if (!covered) {
    const int x = static_cast<int>(std::floor((a.x + b.x + c.x) / 3));
    const int y = static_cast<int>(std::floor((a.y + b.y + c.y) / 3));
    if (x < 0 || y < 0 || x >= width || y >= height)
      return;
    const float depth = static_cast<float>((a.depth + b.depth + c.depth) / 3);
    float& stored = depth_[static_cast<std::size_t>(y) * width + x];
    if (depth > stored) {
      stored = depth;
      reinterpret_cast<QRgb*>(image_.scanLine(y))[x] = color;
    }
    if (!farthest_.empty()) {
      float& far = farthest_[static_cast<std::size_t>(y) * width + x];
      far = std::min(far, depth);
    }
  }
}

void ZBufferCanvas::keep_farthest() {
  farthest_.assign(depth_.size(), std::numeric_limits<float>::infinity());
}

ZBufferCanvas ZBufferCanvas::opposite(QRgb color) const {
  const int width = image_.width(), height = image_.height();
  ZBufferCanvas other(width, height, QColor::fromRgba(background_));
  for (int y = 0; y < height; ++y) {
    QRgb* row = reinterpret_cast<QRgb*>(other.image_.scanLine(y));
    const std::size_t start = static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      const float far =
          farthest_.empty() ? std::numeric_limits<float>::infinity() : farthest_[start + x];
      if (far < std::numeric_limits<float>::infinity()) {
        other.depth_[start + (width - 1 - x)] = -far;
        row[width - 1 - x] = color;
      }
    }
  }
  return other;
}

bool ZBufferCanvas::visible(double x, double y, double depth, double tolerance) const {
  const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
  const int width = width_, height = height_;  // QImage's accessors are calls through the PLT
  if (px < 0 || py < 0 || px >= width || py >= height)
    return false;
  // The farthest surface in the 3x3 pixels around: an edge on a crease or silhouette lies
  // between pixel centres, where either neighbouring face (or the background) owns a pixel.
  float farthest = std::numeric_limits<float>::infinity();
  for (int qy = std::max(0, py - 1); qy <= std::min(height - 1, py + 1); ++qy) {
    for (int qx = std::max(0, px - 1); qx <= std::min(width - 1, px + 1); ++qx)
      farthest = std::min(farthest, depth_[static_cast<std::size_t>(qy) * width + qx]);
  }
  return depth + tolerance >= farthest;
}

void ZBufferCanvas::stamp(double x, double y, double radius, QRgb color, double opacity) {
  const int x0 = std::max(0, static_cast<int>(std::floor(x - radius)));
  const int x1 = std::min(width_ - 1, static_cast<int>(std::floor(x + radius)));
  const int y0 = std::max(0, static_cast<int>(std::floor(y - radius)));
  const int y1 = std::min(height_ - 1, static_cast<int>(std::floor(y + radius)));
  const double limit = std::max(radius * radius, 0.25);
  for (int py = y0; py <= y1; ++py) {
    QRgb* row = reinterpret_cast<QRgb*>(image_.scanLine(py));
    for (int px = x0; px <= x1; ++px) {
      const double dx = px + 0.5 - x, dy = py + 0.5 - y;
      if (dx * dx + dy * dy > limit && !(x0 == x1 && y0 == y1))
        continue;
      if (opacity >= 1) {
        row[px] = color;
      } else {
        const auto mix = [opacity](int over, int under) {
          return static_cast<int>(std::lround(opacity * over + (1 - opacity) * under));
        };
        row[px] = qRgb(mix(qRed(color), qRed(row[px])), mix(qGreen(color), qGreen(row[px])),
                       mix(qBlue(color), qBlue(row[px])));
      }
    }
  }
}

void ZBufferCanvas::draw_line(const CanvasPoint& a, const CanvasPoint& b, double width,
                              QRgb visible_color, QRgb hidden_color, double tolerance,
                              double opacity) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 2)));  // every half pixel
  for (int i = 0; i <= steps; ++i) {
    const double t = double(i) / steps;
    const double x = a.x + (b.x - a.x) * t, y = a.y + (b.y - a.y) * t;
    const double depth = a.depth + (b.depth - a.depth) * t;
    if (visible(x, y, depth, tolerance)) {
      stamp(x, y, width / 2, visible_color, opacity);
    } else if (qAlpha(hidden_color) != 0) {
      const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
      if (px >= 0 && py >= 0 && px < width_ && py < height_)
        reinterpret_cast<QRgb*>(image_.scanLine(py))[px] = hidden_color;
    }
  }
}

void ZBufferCanvas::draw_dot(const CanvasPoint& centre, double radius, QRgb color,
                             double tolerance) {
  if (visible(centre.x, centre.y, centre.depth, tolerance))
    stamp(centre.x, centre.y, radius, color);
}

}  // namespace meshbridge::cli
