// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/formats.h"
#include "io/triangulate.h"

#include "meshbridge/errors.h"

#include <Model/COM/NMR_DLLInterfaces.h>

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

void write_3mf(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* /*attributes*/,
               const WriteOptions& /*options*/) {
  const Soup& soup = mesh.soup;
  const std::string& path = out.target();  // for error messages
  require_float_range(soup, path, "3MF");
  std::vector<NMR::MODELMESHVERTEX> vertices(soup.num_vertices());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    for (int a = 0; a < 3; ++a)
      vertices[v].m_fPosition[a] = static_cast<float>(soup.positions[v][a]);
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  Triangulation triangulation;
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

}  // namespace meshbridge::detail
