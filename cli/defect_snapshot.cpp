// SPDX-License-Identifier: GPL-3.0-or-later
#include "defect_snapshot.h"
#include "meshbridge/counted.h"

#include "meshbridge/validate.h"

#include "zbuffer_canvas.h"

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
//! Self-intersecting faces: the violet of MeshLab's Detect (plugin/crossing_faces.h).
const QColor kCrossingColor(140, 0, 255);
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

//! Where the model lands in the image: model coordinates are halved, centred on `centre` and
//! scaled by `unit` into [-1, 1] (no overflow even near DBL_MAX), projected on the camera axes,
//! then `mid` goes to the centre of `area` and one unit becomes `scale` pixels.
struct Frame {
  ScreenAxes axes;
  Point forward;  //!< toward the camera: right x up
  Point centre;
  double unit = 1;
  double mid_x = 0, mid_y = 0;
  double scale = 1;
  QRectF area;

  Point normalized(const Point& p) const { return (p * 0.5 - centre * 0.5) * unit; }
  CanvasPoint to_canvas(const Point& p) const {
    const Point n = normalized(p);
    return {area.center().x() + ((n | axes.right) - mid_x) * scale,
            area.center().y() - ((n | axes.up) - mid_y) * scale, n | forward};
  }
};

//! Vertices the picture is fitted to: those of defects with `focus` (if any), else all used.
std::vector<char> fit_vertices(const Soup& soup, const DefectReport& report, SnapshotFocus focus) {
  std::vector<char> fit(soup.num_vertices(), 0);
  bool any = false;
  if (focus != SnapshotFocus::whole) {
    const auto mark = [&](Index v) {
      if (v < fit.size()) {
        fit[v] = 1;
        any = true;
      }
    };
    for (const SingularEdge& e : report.singular_edges)
      mark(e.vertices.v0), mark(e.vertices.v1);
    for (const VertexPair& e : report.boundary_edges)
      mark(e.v0), mark(e.v1);
    for (Index v : report.pinch_vertices)
      mark(v);
  }
  if (!any) {
    for (Index v : soup.corner_vertices)
      fit[v] = 1;
  }
  return fit;
}

Frame make_frame(const Soup& soup, const DefectReport& report, const SnapshotOptions& options,
                 const QRectF& area) {
  Frame frame;
  frame.axes = screen_axes(options.view);
  if (options.y_up) {
    // Drawn as if the model were turned by R: (x, y, z) -> (x, -z, y), +y to +z; projecting R p
    // on an axis a is projecting p on R^T a = (a.x, a.z, -a.y).
    for (Point* a : {&frame.axes.right, &frame.axes.up})
      *a = Point((*a)[0], (*a)[2], -(*a)[1]);
  }
  frame.forward = frame.axes.right % frame.axes.up;
  frame.area = area;
  std::vector<char> used(soup.num_vertices(), 0);
  for (Index v : soup.corner_vertices)
    used[v] = 1;
  Point low(std::numeric_limits<double>::max());
  Point high(std::numeric_limits<double>::lowest());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (used[v]) {
      low.minimize(soup.positions[v]);
      high.maximize(soup.positions[v]);
    }
  }
  frame.centre = low * 0.5 + high * 0.5;
  double extent = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (used[v])
      extent = std::max(extent, (soup.positions[v] * 0.5 - frame.centre * 0.5).max_abs());
  }
  frame.unit = extent > 0 ? 1 / extent : 1;

  // The projected box of the fitted vertices, and of the whole model (a zoom shows at least a
  // tenth of the model's width, so one short defect edge is not blown up to fill the picture).
  const auto box = [&](const std::vector<char>& which, double* out) {
    out[0] = out[2] = std::numeric_limits<double>::max();
    out[1] = out[3] = std::numeric_limits<double>::lowest();
    for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
      if (!which[v])
        continue;
      const Point n = frame.normalized(soup.positions[v]);
      const double x = n | frame.axes.right, y = n | frame.axes.up;
      out[0] = std::min(out[0], x), out[1] = std::max(out[1], x);
      out[2] = std::min(out[2], y), out[3] = std::max(out[3], y);
    }
  };
  double whole[4], fitted[4];
  box(used, whole);
  box(fit_vertices(soup, report, options.focus), fitted);
  const double across = std::max(whole[1] - whole[0], whole[3] - whole[2]);
  SnapshotFocus focus = options.focus;
  if (focus == SnapshotFocus::automatic) {  // defects when small, with the model around them
    const bool small = std::max(fitted[1] - fitted[0], fitted[3] - fitted[2]) < 0.25 * across;
    focus = small ? SnapshotFocus::defects : SnapshotFocus::whole;
    if (!small)
      std::copy(whole, whole + 4, fitted);
  }
  if (focus == SnapshotFocus::defects) {
    const double least = (options.focus == SnapshotFocus::automatic ? 0.4 : 0.1) * across;
    for (int axis = 0; axis < 4; axis += 2) {
      const double middle = (fitted[axis] + fitted[axis + 1]) / 2;
      const double half = std::max((fitted[axis + 1] - fitted[axis]) * 0.55, least / 2);
      fitted[axis] = middle - half, fitted[axis + 1] = middle + half;
    }
  }
  const double width = fitted[1] - fitted[0], height = fitted[3] - fitted[2];
  frame.scale = 1;
  if (width > 1e-12 || height > 1e-12) {
    frame.scale =
        std::min(width > 1e-12 ? area.width() / width : std::numeric_limits<double>::max(),
                 height > 1e-12 ? area.height() / height : std::numeric_limits<double>::max());
  }
  frame.mid_x = (fitted[0] + fitted[1]) / 2;
  frame.mid_y = (fitted[2] + fitted[3]) / 2;
  return frame;
}

//! Light grey for a face whose unit normal makes `cosine` with the light (both sides lit).
QRgb shade(double cosine) {
  const int grey = static_cast<int>(std::lround(95 + 140 * std::min(1.0, std::abs(cosine))));
  return qRgb(grey, grey, grey);
}

//! Violet for a self-intersecting face, shaded like shade() but never darker than 0.55 of it.
QRgb shade_crossing(double cosine) {
  const double k = 0.55 + 0.45 * std::min(1.0, std::abs(cosine));
  return qRgb(static_cast<int>(std::lround(kCrossingColor.red() * k)), 0,
              static_cast<int>(std::lround(kCrossingColor.blue() * k)));
}

//! The median on-screen length of some edges (0 for none): how dense the defects are drawn.
template <class Edges, class PairOf>
double median_length(const std::vector<CanvasPoint>& canvas, const Edges& edges, PairOf pair_of) {
  std::vector<double> lengths;
  const std::size_t step = std::max<std::size_t>(1, edges.size() / 4096);  // a sample suffices
  for (std::size_t i = 0; i < edges.size(); i += step) {
    const VertexPair p = pair_of(edges[i]);
    lengths.push_back(std::hypot(canvas[p.v0].x - canvas[p.v1].x, canvas[p.v0].y - canvas[p.v1].y));
  }
  if (lengths.empty())
    return 0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
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

bool is_violet(unsigned red, unsigned green, unsigned blue) {
  return blue >= 100 && green <= 50 && 10 * red >= 3 * blue && 10 * red <= 8 * blue &&
         red >= green + 40;
}

DefectSnapshot draw_defect_snapshot(const Soup& soup, const DefectReport& report,
                                    const SnapshotOptions& options, const Soup* frame_soup,
                                    const DefectReport* frame_report,
                                    const SelfIntersectionReport* crossings) {
  if (frame_soup != nullptr && frame_report == nullptr)
    throw std::invalid_argument("draw_defect_snapshot: frame_soup without frame_report");
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
  std::vector<char> crossing(crossings ? soup.num_faces() : 0, 0);
  if (crossings != nullptr) {
    for (Index f : crossings->faces) {
      if (f >= soup.num_faces()) {
        throw std::invalid_argument("draw_defect_snapshot: the self-intersections name face " +
                                    std::to_string(f) + " but the soup has " +
                                    std::to_string(soup.num_faces()) + " faces");
      }
      crossing[f] = 1;
    }
  }

  const double size = options.size;
  const double pen_scale = std::max(1.0, size / 800);
  const double border = size * options.margin;
  DefectSnapshot result;

  // The legend: one line at the top, shrunk until it fits the width.
  const QString counts = QString::fromStdString(
      counted(report.singular_edges.size(), "singular edge") + ", " +
      counted(report.num_singular_vertices(), "singular vertex") + ", " +
      counted(report.boundary_edges.size(), "boundary edge") +
      (crossings ? ", " + counted(crossings->faces.size(), "self-intersecting face") : ""));
  const QString legend = options.title.empty()
                             ? counts
                             : QString::fromLocal8Bit(options.title.c_str()) + ": " + counts;
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
  const Frame frame = frame_soup ? make_frame(*frame_soup, *frame_report, options, area)
                                 : make_frame(soup, report, options, area);
  std::vector<CanvasPoint> canvas_points(soup.num_vertices());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    canvas_points[v] = frame.to_canvas(soup.positions[v]);

  ZBufferCanvas canvas(options.size, options.size, kBackground);
  // The light comes from the upper left, in front: fixed to the camera, so every view is lit.
  Point light = frame.axes.right * -0.4 + frame.axes.up * 0.6 + frame.forward * 0.7;
  light.normalize();
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    Point normal(0, 0, 0);  // Newell's normal: fine for any simple polygon
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point p = frame.normalized(soup.positions[polygon[i]]);
      const Point q = frame.normalized(soup.positions[polygon[(i + 1) % polygon.size()]]);
      normal += Point((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                      (p[0] - q[0]) * (p[1] + q[1]));
    }
    const double length = normal.norm();
    const double cosine = length > 0 ? (normal | light) / length : 0;
    const QRgb color = crossing.empty() || !crossing[f] ? shade(cosine) : shade_crossing(cosine);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      canvas.fill_triangle(canvas_points[polygon[0]], canvas_points[polygon[i]],
                           canvas_points[polygon[i + 1]], color);
    }
  }

  // Depth tolerance: three pixels' worth, so edges on the surface are not lost to rounding.
  const double tolerance = 3 / std::max(frame.scale, 1e-300);
  const auto same = [](const VertexPair& pair) { return pair; };
  const auto vertices_of = [](const SingularEdge& edge) { return edge.vertices; };
  // Many defect edges (kFewestDense or more) shorter than kDenseLength pixels on screen (median)
  // are too dense to draw one by one: they tint the surface instead (not counted as defect
  // pixels), their hidden parts and vertex dots are left out, so the shape stays visible. Fewer
  // are drawn at full width with their dots however short they look (an edge seen end on).
  constexpr double kDenseLength = 6;
  constexpr std::size_t kFewestDense = 100;
  constexpr std::size_t kMostHiddenDrawn = 20000;
  const auto draw_edges = [&](const auto& edges, const auto& pair_of, double width, QRgb color,
                              QRgb hidden) {
    const double median = median_length(canvas_points, edges, pair_of);
    const bool few = edges.size() < kFewestDense;
    const bool dense = !few && median < kDenseLength;
    // Thinner where many edges are short on screen: a grid of defects stays a grid.
    const double shown =
        few ? width * pen_scale : std::max(1.0, std::min(width * pen_scale, median / 4));
    if (dense || edges.size() > kMostHiddenDrawn)
      hidden = qRgba(0, 0, 0, 0);
    for (const auto& edge : edges) {
      const VertexPair pair = pair_of(edge);
      canvas.draw_line(canvas_points[pair.v0], canvas_points[pair.v1], shown, color, hidden,
                       tolerance, dense ? 0.45 : 1.0);
    }
    return dense ? 0.0 : shown;
  };
  draw_edges(report.boundary_edges, same, 2, kBoundaryColor.rgb(), qRgb(170, 225, 170));
  const double red_width =
      draw_edges(report.singular_edges, vertices_of, 3, kSingularColor.rgb(), qRgb(245, 170, 170));
  if (red_width > 0 || report.singular_edges.empty()) {
    const double radius = std::max(red_width / 2 + 0.5, std::min(3.5 * pen_scale, red_width * 1.2));
    for (Index v : report.singular_edge_vertices)
      canvas.draw_dot(canvas_points[v], radius, kSingularColor.rgb(), tolerance);
  }
  for (Index v : report.pinch_vertices)  // no edge shows these: always full size
    canvas.draw_dot(canvas_points[v], 3.5 * pen_scale, kSingularColor.rgb(), tolerance);
  result.image = std::move(canvas.image());

  if (result.legend_drawn) {
    QPainter painter(&result.image);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    painter.setFont(font);
    painter.setPen(kLegendColor);
    painter.drawText(QRectF(border, border / 2, size - 2 * border, legend_height),
                     Qt::AlignLeft | Qt::AlignTop, legend);
  }

  for (int y = 0; y < result.image.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(result.image.constScanLine(y));
    for (int x = 0; x < result.image.width(); ++x) {
      result.red_pixels += near(row[x], kSingularColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
      result.green_pixels += near(row[x], kBoundaryColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
      result.violet_pixels += is_violet(qRed(row[x]), qGreen(row[x]), qBlue(row[x])) ? 1 : 0;
    }
  }
  return result;
}

DefectSnapshot side_by_side(const DefectSnapshot& left, const DefectSnapshot& right) {
  constexpr int kRule = 2;
  DefectSnapshot both;
  both.image = QImage(left.image.width() + kRule + right.image.width(),
                      std::max(left.image.height(), right.image.height()), QImage::Format_ARGB32);
  if (both.image.isNull())
    throw std::bad_alloc();
  both.image.fill(kBackground);
  QPainter painter(&both.image);
  painter.drawImage(0, 0, left.image);
  painter.fillRect(left.image.width(), 0, kRule, both.image.height(), kEdgeColor);
  painter.drawImage(left.image.width() + kRule, 0, right.image);
  painter.end();
  both.legend_drawn = left.legend_drawn && right.legend_drawn;
  both.red_pixels = left.red_pixels + right.red_pixels;
  both.green_pixels = left.green_pixels + right.green_pixels;
  both.violet_pixels = left.violet_pixels + right.violet_pixels;
  return both;
}

}  // namespace meshbridge::cli
