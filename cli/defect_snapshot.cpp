// SPDX-License-Identifier: GPL-3.0-or-later
#include "defect_snapshot.h"

#include "meshbridge/validate.h"

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QLineF>
#include <QPainter>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

namespace meshbridge::cli {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kIsoAzimuthDegrees = 45;
constexpr double kIsoElevationDegrees = 30;

const QColor kBackground(255, 255, 255);
const QColor kEdgeColor(192, 192, 192);
const QColor kBoundaryColor(0, 160, 0);
const QColor kSingularColor(220, 0, 0);
const QColor kLegendColor(0, 0, 0);

//! Screen axes of an orthographic camera: `right` and `up` are orthonormal, and right x up points
//! from the model toward the camera.
struct ScreenAxes {
  Point right;
  Point up;
};

ScreenAxes screen_axes(SnapshotView view) {
  switch (view) {
    case SnapshotView::iso: {
      // Camera at azimuth a (from +x toward +y) and elevation e, +z up. The exact isometric
      // (e = 35.26 deg) puts a box's back corner behind its front one and hides three edges.
      const double a = kIsoAzimuthDegrees * kPi / 180, e = kIsoElevationDegrees * kPi / 180;
      return {Point(-std::sin(a), std::cos(a), 0),
              Point(-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e))};
    }
    case SnapshotView::x:
      return {Point(0, 1, 0), Point(0, 0, 1)};
    case SnapshotView::y:
      return {Point(-1, 0, 0), Point(0, 0, 1)};
    case SnapshotView::z:
      return {Point(1, 0, 0), Point(0, 1, 0)};
  }
  throw std::invalid_argument("unknown snapshot view");
}

//! Edges carrying at least one polygon side, each once (drawing one twice would darken its
//! antialiased rim).
std::vector<VertexPair> distinct_edges(const Soup& soup) {
  std::vector<VertexPair> edges;
  edges.reserve(soup.num_corners());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Index a = polygon[i];
      const Index b = polygon[(i + 1) % polygon.size()];
      if (a != b)
        edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const VertexPair& p, const VertexPair& q) {
    return p.v0 != q.v0 ? p.v0 < q.v0 : p.v1 < q.v1;
  });
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

//! Pixel positions of all soup vertices: used vertices fitted into `area`, centred; isolated
//! vertices are projected the same way but take no part in the fit.
std::vector<QPointF> project(const Soup& soup, SnapshotView view, const QRectF& area) {
  std::vector<bool> used(soup.num_vertices(), false);
  for (Index v : soup.corner_vertices)
    used[v] = true;
  // Halve before subtracting, then scale by the largest offset: no overflow even near DBL_MAX.
  Point low(std::numeric_limits<double>::max());
  Point high(std::numeric_limits<double>::lowest());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (used[v]) {
      low.minimize(soup.positions[v]);
      high.maximize(soup.positions[v]);
    }
  }
  const Point centre = low * 0.5 + high * 0.5;
  double extent = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (used[v])
      extent = std::max(extent, (soup.positions[v] * 0.5 - centre * 0.5).max_abs());
  }
  const double unit = extent > 0 ? 1 / extent : 1;

  const ScreenAxes axes = screen_axes(view);
  std::vector<QPointF> screen(soup.num_vertices());
  double min_x = std::numeric_limits<double>::max(), max_x = std::numeric_limits<double>::lowest();
  double min_y = min_x, max_y = max_x;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point p = (soup.positions[v] * 0.5 - centre * 0.5) * unit;  // every coordinate in [-1,1]
    screen[v] = QPointF(p.dot(axes.right), p.dot(axes.up));
    if (used[v]) {
      min_x = std::min(min_x, screen[v].x());
      max_x = std::max(max_x, screen[v].x());
      min_y = std::min(min_y, screen[v].y());
      max_y = std::max(max_y, screen[v].y());
    }
  }
  const double width = max_x - min_x;
  const double height = max_y - min_y;
  double scale = 1;
  if (width > 1e-12 || height > 1e-12) {
    scale = std::min(width > 1e-12 ? area.width() / width : std::numeric_limits<double>::max(),
                     height > 1e-12 ? area.height() / height : std::numeric_limits<double>::max());
  }
  const QPointF mid((min_x + max_x) / 2, (min_y + max_y) / 2);
  for (QPointF& s : screen) {
    // Image y grows downward.
    s = QPointF(area.center().x() + (s.x() - mid.x()) * scale,
                area.center().y() - (s.y() - mid.y()) * scale);
  }
  return screen;
}

//! True if `font` puts ink on an image: offscreen, without a font file, text draws nothing.
bool text_renders(const QFont& font) {
  QImage probe(64, 64, QImage::Format_ARGB32);
  probe.fill(kBackground);
  {
    QPainter painter(&probe);
    painter.setFont(font);
    painter.setPen(kLegendColor);
    painter.drawText(QRectF(0, 0, 64, 64), Qt::AlignCenter, QStringLiteral("0A"));
  }
  for (int y = 0; y < probe.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(probe.constScanLine(y));
    for (int x = 0; x < probe.width(); ++x) {
      if (row[x] != kBackground.rgb())
        return true;
    }
  }
  return false;
}

bool near(QRgb pixel, const QColor& color, int tolerance) {
  return std::abs(qRed(pixel) - color.red()) <= tolerance &&
         std::abs(qGreen(pixel) - color.green()) <= tolerance &&
         std::abs(qBlue(pixel) - color.blue()) <= tolerance;
}

void check_vertex(const Soup& soup, Index v) {
  if (v >= soup.num_vertices()) {
    throw std::invalid_argument("draw_defect_snapshot: the report names vertex " +
                                std::to_string(v) + " but the soup has " +
                                std::to_string(soup.num_vertices()) + " vertices");
  }
}

}  // namespace

SnapshotView parse_snapshot_view(const std::string& text) {
  if (text == "iso")
    return SnapshotView::iso;
  if (text == "x")
    return SnapshotView::x;
  if (text == "y")
    return SnapshotView::y;
  if (text == "z")
    return SnapshotView::z;
  throw std::invalid_argument("view must be iso, x, y or z, got '" + text + "'");
}

const char* to_string(SnapshotView view) {
  switch (view) {
    case SnapshotView::iso:
      return "iso";
    case SnapshotView::x:
      return "x";
    case SnapshotView::y:
      return "y";
    case SnapshotView::z:
      return "z";
  }
  throw std::invalid_argument("unknown snapshot view");
}

DefectSnapshot draw_defect_snapshot(const Soup& soup, const DefectReport& report,
                                    const SnapshotOptions& options) {
  if (options.size < SnapshotOptions::kMinSize || options.size > SnapshotOptions::kMaxSize) {
    throw std::invalid_argument(
        "snapshot size must be " + std::to_string(SnapshotOptions::kMinSize) + " to " +
        std::to_string(SnapshotOptions::kMaxSize) + ", got " + std::to_string(options.size));
  }
  if (!(options.margin >= 0 && options.margin <= 0.45))
    throw std::invalid_argument("snapshot margin must be 0 to 0.45");
  validate_soup(soup);
  for (const SingularEdge& edge : report.singular_edges) {
    check_vertex(soup, edge.vertices.v0);
    check_vertex(soup, edge.vertices.v1);
  }
  for (const VertexPair& edge : report.boundary_edges) {
    check_vertex(soup, edge.v0);
    check_vertex(soup, edge.v1);
  }
  for (Index v : report.singular_edge_vertices)
    check_vertex(soup, v);
  for (Index v : report.pinch_vertices)
    check_vertex(soup, v);

  const double size = options.size;
  const double pen_scale = std::max(1.0, size / 800);
  const double border = size * options.margin;
  DefectSnapshot result;
  result.image = QImage(options.size, options.size, QImage::Format_ARGB32);
  if (result.image.isNull())
    throw std::bad_alloc();
  result.image.fill(kBackground);

  // The legend: one line at the top, shrunk until it fits the width.
  const QString legend =
      QStringLiteral("%1 singular edges, %2 singular vertices, %3 boundary edges")
          .arg(report.singular_edges.size())
          .arg(report.num_singular_vertices())
          .arg(report.boundary_edges.size());
  QFont font;
  double legend_height = 0;
  if (options.legend && QGuiApplication::instance() != nullptr) {
    double pixel_size = std::max(10.0, size / 40);
    font.setPixelSize(static_cast<int>(pixel_size));
    while (pixel_size > 6 && QFontMetricsF(font).horizontalAdvance(legend) > size - 2 * border) {
      pixel_size -= 1;
      font.setPixelSize(static_cast<int>(pixel_size));
    }
    if (text_renders(font)) {
      result.legend_drawn = true;
      legend_height = QFontMetricsF(font).height() + border / 2;
    }
  }
  const QRectF area(border, border + legend_height, size - 2 * border,
                    size - 2 * border - legend_height);
  const std::vector<QPointF> screen = project(soup, options.view, area);

  QPainter painter(&result.image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setRenderHint(QPainter::TextAntialiasing, true);
  const auto draw_edges = [&](const QColor& color, double width, const auto& pairs,
                              const auto& pair_of) {
    QVector<QLineF> lines;
    lines.reserve(static_cast<int>(pairs.size()));
    for (const auto& item : pairs) {
      const VertexPair pair = pair_of(item);
      lines.push_back(QLineF(screen[pair.v0], screen[pair.v1]));
    }
    painter.setPen(QPen(color, width * pen_scale, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawLines(lines);
  };
  const auto same = [](const VertexPair& pair) { return pair; };
  draw_edges(kEdgeColor, 1, distinct_edges(soup), same);
  draw_edges(kBoundaryColor, 2, report.boundary_edges, same);
  draw_edges(kSingularColor, 3, report.singular_edges,
             [](const SingularEdge& edge) { return edge.vertices; });

  painter.setPen(Qt::NoPen);
  painter.setBrush(kSingularColor);
  const double radius = 3.5 * pen_scale;
  for (const std::vector<Index>* list : {&report.singular_edge_vertices, &report.pinch_vertices}) {
    for (Index v : *list)
      painter.drawEllipse(screen[v], radius, radius);
  }

  if (result.legend_drawn) {
    painter.setFont(font);
    painter.setPen(kLegendColor);
    painter.drawText(QRectF(border, border / 2, size - 2 * border, legend_height),
                     Qt::AlignLeft | Qt::AlignTop, legend);
  }
  painter.end();

  for (int y = 0; y < result.image.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(result.image.constScanLine(y));
    for (int x = 0; x < result.image.width(); ++x) {
      result.red_pixels += near(row[x], kSingularColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
      result.green_pixels += near(row[x], kBoundaryColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
    }
  }
  return result;
}

}  // namespace meshbridge::cli
