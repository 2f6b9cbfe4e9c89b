// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/formats.h"
#include "io/triangulate.h"
#include "io/units_3mf.h"

#include "meshbridge/errors.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

struct Released {
  NMR::PLib3MFBase* instance = nullptr;
  ~Released() {
    if (instance != nullptr)
      NMR::lib3mf_release(instance);
  }
};

void check(HRESULT result, const std::string& path, const char* what) {
  if (result != LIB3MF_OK)
    throw WriteError(path + ": lib3mf cannot " + what + " (error " + std::to_string(result) + ")");
}

}  // namespace

void write_3mf(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& /*options*/) {
  const Soup& soup = mesh.soup;
  const std::string& path = out.target();  // for error messages
  require_float_range(soup, path, "3MF");
  // lib3mf refuses a coordinate beyond NMR_MESH_MAXCOORDINATE (1e9, "1 billion mm").
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    for (int a = 0; a < 3; ++a) {
      if (std::abs(soup.positions[v][a]) > 1e9) {
        throw WriteError(path + ": vertex " + std::to_string(v) + " has the coordinate " +
                         std::to_string(soup.positions[v][a]) +
                         ", beyond the 1e9 (1 billion mm) that lib3mf writes to 3MF");
      }
    }
  }
  std::vector<NMR::MODELMESHVERTEX> vertices(soup.num_vertices());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    for (int a = 0; a < 3; ++a)
      vertices[v].m_fPosition[a] = static_cast<float>(soup.positions[v][a]);
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  Triangulation triangulation;
  avoid_existing_edges(soup, triangulation);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    triangulate_polygon(soup, f, triangulation);
    for (const auto& [a, b, c] : triangulation.triangles) {
      // lib3mf refuses a triangle that names a vertex twice ("cannot store the mesh").
      if (a == b || b == c || a == c) {
        throw WriteError(path + ": face " + std::to_string(f) +
                         " names a vertex twice (a degenerate triangle), which 3MF refuses: "
                         "repair sets such faces aside or splits them");
      }
      triangles.push_back({{a, b, c}});
    }
  }
  Released model, object, item, writer;
  check(NMR::lib3mf_createmodel(&model.instance), path, "create a model");
  // The input's unit (a 3MF read in inches stays in inches); millimetres otherwise.
  check(NMR::lib3mf_model_setunit(model.instance,
                                  unit_3mf(attributes != nullptr ? attributes->length_unit : "")),
        path, "set the model's unit");
  check(NMR::lib3mf_model_addmeshobject(model.instance, &object.instance), path,
        "add a mesh object");
  check(NMR::lib3mf_meshobject_setgeometry(object.instance, vertices.data(),
                                           static_cast<DWORD>(vertices.size()), triangles.data(),
                                           static_cast<DWORD>(triangles.size())),
        path, "store the mesh");
  check(NMR::lib3mf_model_addbuilditem(model.instance, object.instance, nullptr, &item.instance),
        path, "add the build item");
  check(NMR::lib3mf_model_querywriter(model.instance, "3mf", &writer.instance), path,
        "create a writer");
  check(NMR::lib3mf_writer_writetofileutf8(writer.instance, out.temporary_path().c_str()), path,
        "write the file");
}

ThreeMfRounding measure_3mf_rounding(const std::string& path, const Soup& soup) {
  ThreeMfRounding rounding;
  Released model, reader, objects, object;
  if (NMR::lib3mf_createmodel(&model.instance) != LIB3MF_OK ||
      NMR::lib3mf_model_queryreader(model.instance, "3mf", &reader.instance) != LIB3MF_OK ||
      NMR::lib3mf_reader_readfromfileutf8(reader.instance, path.c_str()) != LIB3MF_OK ||
      NMR::lib3mf_model_getmeshobjects(model.instance, &objects.instance) != LIB3MF_OK) {
    return rounding;
  }
  BOOL more = false;
  if (NMR::lib3mf_resourceiterator_movenext(objects.instance, &more) != LIB3MF_OK || !more ||
      NMR::lib3mf_resourceiterator_getcurrent(objects.instance, &object.instance) != LIB3MF_OK) {
    return rounding;
  }
  DWORD vertex_count = 0, triangle_count = 0;
  if (NMR::lib3mf_meshobject_getvertexcount(object.instance, &vertex_count) != LIB3MF_OK ||
      NMR::lib3mf_meshobject_gettrianglecount(object.instance, &triangle_count) != LIB3MF_OK ||
      vertex_count != soup.num_vertices()) {
    return rounding;
  }
  std::vector<NMR::MODELMESHVERTEX> written(vertex_count);
  std::vector<NMR::MODELMESHTRIANGLE> triangles(triangle_count);
  if ((vertex_count > 0 &&
       NMR::lib3mf_meshobject_getvertices(object.instance, written.data(), vertex_count, nullptr) !=
           LIB3MF_OK) ||
      (triangle_count > 0 &&
       NMR::lib3mf_meshobject_gettriangleindices(object.instance, triangles.data(), triangle_count,
                                                 nullptr) != LIB3MF_OK)) {
    return rounding;
  }
  const auto given = [&soup](DWORD v, int a) { return static_cast<float>(soup.positions[v][a]); };
  for (DWORD v = 0; v < vertex_count; ++v) {
    bool moved = false;
    for (int a = 0; a < 3; ++a) {
      const float difference = std::abs(written[v].m_fPosition[a] - given(v, a));
      moved = moved || difference != 0;
      rounding.largest_move = std::max(rounding.largest_move, double(difference));
    }
    rounding.moved += moved;
  }
  const auto same = [&](DWORD u, DWORD v, bool as_written) {
    for (int a = 0; a < 3; ++a) {
      if ((as_written ? written[u].m_fPosition[a] : given(u, a)) !=
          (as_written ? written[v].m_fPosition[a] : given(v, a)))
        return false;
    }
    return true;
  };
  for (const NMR::MODELMESHTRIANGLE& t : triangles) {
    const DWORD* i = t.m_nIndices;
    if (i[0] >= vertex_count || i[1] >= vertex_count || i[2] >= vertex_count)
      continue;
    const bool now = same(i[0], i[1], true) || same(i[1], i[2], true) || same(i[0], i[2], true);
    const bool before =
        same(i[0], i[1], false) || same(i[1], i[2], false) || same(i[0], i[2], false);
    rounding.collapsed += now && !before;
  }
  rounding.measured = true;
  return rounding;
}

}  // namespace meshbridge::detail
