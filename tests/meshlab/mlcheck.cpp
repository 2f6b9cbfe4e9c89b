// SPDX-License-Identifier: GPL-3.0-or-later
//! \file mlcheck.cpp
//! Reads what meshlabserver wrote and prints checkable numbers, with the core as the reference.
//!
//!   mlcheck to-off IN OUT        IN (OBJ/OFF/PLY, read by the core's read_soup) -> OFF file.
//!                                Debian's meshlabserver 2020.09 aborts on every OBJ file
//!                                (import_obj.h:640 assertion, Debian bug #1054006), so the
//!                                tests feed it OFF.
//!   mlcheck report FILE          key=value lines: element counts, the core's detection and
//!                                self-intersections on the file's faces, selection counts (PLY
//!                                flags), defect-layer counts (edges by vertex colour: red
//!                                singular, green boundary; faces by face colour, violet for
//!                                self-intersecting faces).
//!   mlcheck make-attributed IN OUT.ply
//!                                IN (read by the core) -> ASCII PLY with a distinct colour and
//!                                quality per vertex and per face and a texture coordinate per
//!                                wedge, polygons fanned into triangles, for the attribute test.
//!   mlcheck same-attributes IN OUT
//!                                OUT (PLY) keeps IN's (PLY) faces in order with their colour and
//!                                quality, and each face's corners carry the same position, vertex
//!                                colour, vertex quality and wedge texture coordinate as before.
//!
//! MeshLab's outputs are parsed here (ASCII PLY with flags, OBJ with vertex colours and `l`
//! edges), since those are exactly what the core's readers leave out.

#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/soup.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using meshbridge::Index;

//! A mesh as a file has it, with the attributes MeshLab writes.
struct FileMesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::vector<Index>> faces;
  std::vector<std::array<Index, 2>> edges;
  std::vector<std::array<double, 4>> vertex_color;  //!< 0..1, empty if none
  std::vector<double> vertex_quality;
  std::vector<int> vertex_flags;
  std::vector<std::array<double, 4>> face_color;
  std::vector<double> face_quality;
  std::vector<int> face_flags;
  std::vector<std::vector<double>> face_texcoord;  //!< u0 v0 u1 v1 ... per face
};

std::string extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what);
}

// ---- ASCII PLY -------------------------------------------------------------------------------

struct PlyProperty {
  std::string name;
  bool is_list = false;
};
struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
  std::vector<std::vector<std::vector<double>>> rows;  //!< row -> property -> values
  int index_of(const std::string& n) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == n)
        return int(i);
    return -1;
  }
};

FileMesh read_ply(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    fail("cannot open " + path);
  std::string line;
  std::getline(in, line);
  if (line.rfind("ply", 0) != 0)
    fail(path + ": not a PLY file");
  std::vector<PlyElement> elements;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "format") {
      std::string fmt;
      ls >> fmt;
      if (fmt != "ascii")
        fail(path + ": binary PLY (save with meshlabserver -m ... sa)");
    } else if (word == "element") {
      PlyElement e;
      ls >> e.name >> e.count;
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty())
        fail(path + ": property before element");
      PlyProperty p;
      std::string type;
      ls >> type;
      if (type == "list") {
        std::string count_type, item_type;
        ls >> count_type >> item_type;
        p.is_list = true;
      }
      ls >> p.name;
      elements.back().properties.push_back(p);
    } else if (word == "end_header") {
      break;
    }
  }
  for (PlyElement& e : elements) {
    e.rows.resize(e.count);
    for (std::size_t r = 0; r < e.count; ++r) {
      auto& row = e.rows[r];
      row.resize(e.properties.size());
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        double v = 0;
        if (!(in >> v))
          fail(path + ": truncated " + e.name + " " + std::to_string(r));
        if (e.properties[p].is_list) {
          row[p].resize(std::size_t(v));
          for (double& x : row[p])
            if (!(in >> x))
              fail(path + ": truncated list in " + e.name);
        } else {
          row[p].push_back(v);
        }
      }
    }
  }

  FileMesh m;
  auto color = [](const std::vector<std::vector<double>>& row, int r, int g, int b, int a) {
    return std::array<double, 4>{row[r][0] / 255.0, row[g][0] / 255.0, row[b][0] / 255.0,
                                 a >= 0 ? row[a][0] / 255.0 : 1.0};
  };
  for (const PlyElement& e : elements) {
    if (e.name == "vertex") {
      const int x = e.index_of("x"), y = e.index_of("y"), z = e.index_of("z");
      const int fl = e.index_of("flags"), q = e.index_of("quality");
      const int r = e.index_of("red"), g = e.index_of("green"), b = e.index_of("blue"),
                a = e.index_of("alpha");
      if (x < 0 || y < 0 || z < 0)
        fail(path + ": vertex without x y z");
      for (const auto& row : e.rows) {
        m.positions.push_back({row[x][0], row[y][0], row[z][0]});
        if (fl >= 0)
          m.vertex_flags.push_back(int(row[fl][0]));
        if (q >= 0)
          m.vertex_quality.push_back(row[q][0]);
        if (r >= 0 && g >= 0 && b >= 0)
          m.vertex_color.push_back(color(row, r, g, b, a));
      }
    } else if (e.name == "face") {
      int vi = e.index_of("vertex_indices");
      if (vi < 0)
        vi = e.index_of("vertex_index");
      const int fl = e.index_of("flags"), q = e.index_of("quality"), t = e.index_of("texcoord");
      const int r = e.index_of("red"), g = e.index_of("green"), b = e.index_of("blue"),
                a = e.index_of("alpha");
      if (vi < 0)
        fail(path + ": face without vertex_indices");
      for (const auto& row : e.rows) {
        std::vector<Index> f;
        for (double v : row[vi])
          f.push_back(Index(v));
        m.faces.push_back(f);
        if (fl >= 0)
          m.face_flags.push_back(int(row[fl][0]));
        if (q >= 0)
          m.face_quality.push_back(row[q][0]);
        if (t >= 0)
          m.face_texcoord.push_back(row[t]);
        if (r >= 0 && g >= 0 && b >= 0)
          m.face_color.push_back(color(row, r, g, b, a));
      }
    } else if (e.name == "edge") {
      const int v1 = e.index_of("vertex1"), v2 = e.index_of("vertex2");
      if (v1 < 0 || v2 < 0)
        fail(path + ": edge without vertex1 vertex2");
      for (const auto& row : e.rows)
        m.edges.push_back({Index(row[v1][0]), Index(row[v2][0])});
    }
  }
  return m;
}

// ---- OBJ (as MeshLab writes it: `v x y z [r g b]`, `f a b c`, `l a b`) and OFF ---------------

Index obj_index(const std::string& token, std::size_t nv) {
  const long i = std::stol(token.substr(0, token.find('/')));
  return Index(i < 0 ? long(nv) + i : i - 1);
}

FileMesh read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    fail("cannot open " + path);
  FileMesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      std::array<double, 3> p{};
      ls >> p[0] >> p[1] >> p[2];
      m.positions.push_back(p);
      double r, g, b;
      if (ls >> r >> g >> b)
        m.vertex_color.push_back({r, g, b, 1.0});
    } else if (tag == "f" || tag == "l") {
      std::vector<Index> poly;
      std::string token;
      while (ls >> token)
        poly.push_back(obj_index(token, m.positions.size()));
      if (tag == "f") {
        m.faces.push_back(poly);
      } else {
        for (std::size_t i = 0; i + 1 < poly.size(); ++i)
          m.edges.push_back({poly[i], poly[i + 1]});
      }
    }
  }
  if (!m.vertex_color.empty() && m.vertex_color.size() != m.positions.size()) {
    fail(path + ": some vertices have a colour, some not");
  }
  return m;
}

FileMesh read_off(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    fail("cannot open " + path);
  std::string header;
  in >> header;
  if (header.find("OFF") == std::string::npos)
    fail(path + ": not an OFF file");
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> nv >> nf >> ne;
  FileMesh m;
  m.positions.resize(nv);
  for (auto& p : m.positions)
    in >> p[0] >> p[1] >> p[2];
  std::string rest;
  std::getline(in, rest);
  for (std::size_t f = 0; f < nf; ++f) {
    std::string line;
    if (!std::getline(in, line))
      fail(path + ": truncated");
    std::istringstream ls(line);
    std::size_t n = 0;
    ls >> n;
    std::vector<Index> poly(n);
    for (Index& v : poly)
      ls >> v;
    m.faces.push_back(poly);
  }
  return m;
}

FileMesh read_file(const std::string& path) {
  const std::string ext = extension(path);
  if (ext == "ply")
    return read_ply(path);
  if (ext == "obj")
    return read_obj(path);
  if (ext == "off")
    return read_off(path);
  fail(path + ": unknown extension");
}

meshbridge::Soup to_soup(const FileMesh& m) {
  meshbridge::Soup s;
  for (const auto& p : m.positions)
    s.add_vertex(meshbridge::Point(p[0], p[1], p[2]));
  for (const auto& f : m.faces)
    s.add_polygon(f);
  return s;
}

// ---- commands --------------------------------------------------------------------------------

int to_off(const std::string& in_path, const std::string& out_path) {
  const meshbridge::Soup soup = meshbridge::read_soup(in_path);
  std::ofstream out(out_path);
  if (!out)
    fail("cannot write " + out_path);
  out << "OFF\n" << soup.num_vertices() << ' ' << soup.num_faces() << " 0\n";
  char buf[128];
  for (const auto& p : soup.positions) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out << buf;
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    out << soup.arity(f);
    for (Index v : soup.polygon(f))
      out << ' ' << v;
    out << '\n';
  }
  return out ? 0 : 1;
}

int make_attributed(const std::string& in_path, const std::string& out_path) {
  // Triangles only: MeshLab's PLY reader refuses polygons that carry wedge texture coordinates.
  const meshbridge::Soup polygons = meshbridge::read_soup(in_path);
  meshbridge::Soup soup;
  soup.positions = polygons.positions;
  for (std::size_t f = 0; f < polygons.num_faces(); ++f) {
    const meshbridge::PolygonView p = polygons.polygon(f);
    for (std::size_t k = 1; k + 1 < p.size(); ++k)
      soup.add_polygon({p[0], p[k], p[k + 1]});
  }
  std::ofstream out(out_path);
  if (!out)
    fail("cannot write " + out_path);
  out << "ply\nformat ascii 1.0\ncomment MeshBridge attribute test\n"
      << "element vertex " << soup.num_vertices() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
      << "property float quality\n"
      << "element face " << soup.num_faces() << "\n"
      << "property list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
      << "property float quality\nproperty list uchar float texcoord\nend_header\n";
  char buf[160];
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const auto& p = soup.positions[v];
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %zu %zu %zu 255 %zu.5\n", p[0], p[1], p[2],
                  (37 * v + 11) % 256, (91 * v + 23) % 256, (53 * v + 71) % 256, v);
    out << buf;
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    out << soup.arity(f);
    for (Index v : soup.polygon(f))
      out << ' ' << v;
    out << ' ' << (29 * f + 5) % 256 << ' ' << (67 * f + 13) % 256 << ' ' << (17 * f + 101) % 256
        << " 255 " << f << ".25 " << 2 * soup.arity(f);
    for (std::size_t k = 0; k < soup.arity(f); ++k) {
      out << ' ' << (double(f) + 0.125 * double(k)) / 1024.0 << ' ' << (double(k) + 0.5) / 8.0;
    }
    out << '\n';
  }
  return out ? 0 : 1;
}

bool is_color(const std::array<double, 4>& c, double r, double g, double b) {
  return std::abs(c[0] - r) < 0.01 && std::abs(c[1] - g) < 0.01 && std::abs(c[2] - b) < 0.01;
}

int report(const std::string& path) {
  const FileMesh m = read_file(path);
  std::size_t triangles = 0;  // what MeshLab makes of the polygons (it triangulates on loading)
  for (const auto& f : m.faces)
    triangles += f.size() >= 3 ? f.size() - 2 : 0;
  std::cout << "vertices=" << m.positions.size() << "\nfaces=" << m.faces.size()
            << "\ntriangles=" << triangles << "\nedge_elements=" << m.edges.size() << '\n';
  if (!m.faces.empty()) {
    const meshbridge::DefectReport r = meshbridge::detect_defects(to_soup(m));
    std::cout << "singular_edges=" << r.singular_edges.size()
              << "\nsingular_vertices=" << r.num_singular_vertices()
              << "\npinch_vertices=" << r.pinch_vertices.size()
              << "\nboundary_edges=" << r.boundary_edges.size()
              << "\nboundary_loops=" << r.num_boundary_loops << "\ncomponents=" << r.num_components
              << "\ninconsistent_edges=" << r.inconsistent_edges.size()
              << "\nnonorientable_components=" << r.num_nonorientable_components
              << "\nwatertight=" << (r.watertight ? 1 : 0) << '\n';
    std::size_t contenders = 0;
    for (const auto& e : r.singular_edges)
      contenders += e.contenders;
    std::cout << "singular_edge_contenders=" << contenders << '\n';
    if (meshbridge::self_intersections_available()) {
      const meshbridge::SelfIntersectionReport s = meshbridge::find_self_intersections(to_soup(m));
      std::cout << "self_intersecting_face_pairs=" << s.face_pairs.size()
                << "\nself_intersecting_faces=" << s.faces.size()
                << "\ncrossing_component_pairs=" << s.component_pairs.size() << '\n';
    }
  }
  constexpr int kSelected = 0x20;  // vcg::BitFlags SELECTED
  if (!m.vertex_flags.empty()) {
    std::cout << "selected_vertices="
              << std::count_if(m.vertex_flags.begin(), m.vertex_flags.end(),
                               [](int f) { return (f & kSelected) != 0; })
              << '\n';
  }
  if (!m.face_flags.empty()) {
    std::cout << "selected_faces="
              << std::count_if(m.face_flags.begin(), m.face_flags.end(),
                               [](int f) { return (f & kSelected) != 0; })
              << '\n';
  }
  if (!m.face_color.empty()) {
    std::size_t red = 0, orange = 0, green = 0, magenta = 0, violet = 0;
    for (const auto& c : m.face_color) {
      red += is_color(c, 1, 0, 0) ? 1 : 0;
      orange += is_color(c, 1, 128.0 / 255, 0) ? 1 : 0;
      green += is_color(c, 0, 1, 0) ? 1 : 0;
      magenta += is_color(c, 1, 0, 1) ? 1 : 0;
      violet += is_color(c, 140.0 / 255, 0, 1) ? 1 : 0;  // self-intersecting faces
    }
    std::cout << "red_faces=" << red << "\norange_faces=" << orange << "\ngreen_faces=" << green
              << "\nmagenta_faces=" << magenta << "\nviolet_faces=" << violet << '\n';
  }
  if (!m.edges.empty() || m.faces.empty()) {
    std::size_t red = 0, green = 0, other = 0;
    std::vector<char> on_edge(m.positions.size(), 0);
    for (const auto& e : m.edges) {
      if (e[0] >= m.positions.size() || e[1] >= m.positions.size())
        fail(path + ": bad edge");
      on_edge[e[0]] = on_edge[e[1]] = 1;
      if (m.vertex_color.empty()) {
        ++other;
        continue;
      }
      const auto& a = m.vertex_color[e[0]];
      const auto& b = m.vertex_color[e[1]];
      if (is_color(a, 1, 0, 0) && is_color(b, 1, 0, 0)) {
        ++red;
      } else if (is_color(a, 0, 1, 0) && is_color(b, 0, 1, 0)) {
        ++green;
      } else {
        ++other;
      }
    }
    std::cout << "red_edges=" << red << "\ngreen_edges=" << green << "\nother_edges=" << other
              << "\nmarker_points=" << std::count(on_edge.begin(), on_edge.end(), 0) << '\n';
  }
  return 0;
}

//! One face corner with everything attached to it, for comparison as a multiset.
using Corner = std::vector<double>;

std::vector<Corner> corners_of(const FileMesh& m, std::size_t f) {
  std::vector<Corner> out;
  const auto& face = m.faces[f];
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Index v = face[k];
    Corner c(m.positions[v].begin(), m.positions[v].end());
    if (!m.vertex_color.empty())
      c.insert(c.end(), m.vertex_color[v].begin(), m.vertex_color[v].end());
    if (!m.vertex_quality.empty())
      c.push_back(m.vertex_quality[v]);
    if (!m.face_texcoord.empty() && m.face_texcoord[f].size() == 2 * face.size()) {
      c.push_back(m.face_texcoord[f][2 * k]);
      c.push_back(m.face_texcoord[f][2 * k + 1]);
    }
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool near(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > 1e-5 * (1 + std::abs(a[i])))
      return false;
  return true;
}

int same_attributes(const std::string& in_path, const std::string& out_path) {
  const FileMesh a = read_file(in_path);
  const FileMesh b = read_file(out_path);
  int errors = 0;
  auto complain = [&](const std::string& what) {
    if (++errors <= 10)
      std::cout << "mismatch: " << what << '\n';
  };
  if (a.faces.size() != b.faces.size()) {
    complain("face count " + std::to_string(a.faces.size()) + " -> " +
             std::to_string(b.faces.size()));
    return 1;
  }
  if (a.vertex_color.empty() != b.vertex_color.empty())
    complain("vertex colour presence");
  if (a.vertex_quality.empty() != b.vertex_quality.empty())
    complain("vertex quality presence");
  if (a.face_color.empty() != b.face_color.empty())
    complain("face colour presence");
  if (a.face_quality.empty() != b.face_quality.empty())
    complain("face quality presence");
  if (a.face_texcoord.empty() != b.face_texcoord.empty())
    complain("wedge texcoord presence");
  if (errors)
    return 1;
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    const std::string at = "face " + std::to_string(f);
    if (!a.face_color.empty() && !near({a.face_color[f].begin(), a.face_color[f].end()},
                                       {b.face_color[f].begin(), b.face_color[f].end()}))
      complain(at + " colour");
    if (!a.face_quality.empty() && !near({a.face_quality[f]}, {b.face_quality[f]}))
      complain(at + " quality");
    const auto ca = corners_of(a, f);
    const auto cb = corners_of(b, f);
    bool same = ca.size() == cb.size();
    for (std::size_t k = 0; same && k < ca.size(); ++k)
      same = near(ca[k], cb[k]);
    if (!same)
      complain(at + " corners (position/vertex colour/quality/texcoord)");
  }
  std::cout << "faces_compared=" << a.faces.size() << "\nmismatches=" << errors << '\n';
  return errors == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 3 && args[0] == "to-off")
      return to_off(args[1], args[2]);
    if (args.size() == 2 && args[0] == "report")
      return report(args[1]);
    if (args.size() == 3 && args[0] == "make-attributed")
      return make_attributed(args[1], args[2]);
    if (args.size() == 3 && args[0] == "same-attributes")
      return same_attributes(args[1], args[2]);
    std::cerr << "usage: mlcheck to-off IN OUT | report FILE | make-attributed IN OUT.ply |"
                 " same-attributes IN.ply OUT.ply\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mlcheck: " << e.what() << '\n';
    return 1;
  }
}
