// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/formats.h"

#include "meshbridge/errors.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <vector>

namespace meshbridge::detail {

namespace {

// Releases a lib3mf instance when it goes out of scope.
struct Released {
  NMR::PLib3MFBase* instance = nullptr;
  ~Released() {
    if (instance != nullptr)
      NMR::lib3mf_release(instance);
  }
};

void check(HRESULT result, const std::string& path, const char* what) {
  if (result != LIB3MF_OK)
    throw ReadError(path + ": lib3mf cannot " + what + " (error " + std::to_string(result) + ")");
}

}  // namespace

void read_3mf(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* /*attributes*/) {
  const std::string& path = file.path();
  Released model, reader, objects;
  check(NMR::lib3mf_createmodel(&model.instance), path, "create a model");
  check(NMR::lib3mf_model_queryreader(model.instance, "3mf", &reader.instance), path,
        "create a reader");
  check(NMR::lib3mf_reader_readfromfileutf8(reader.instance, path.c_str()), path,
        "read the file as 3MF");
  check(NMR::lib3mf_model_getmeshobjects(model.instance, &objects.instance), path,
        "list the mesh objects");
  BOOL more = false;
  check(NMR::lib3mf_resourceiterator_movenext(objects.instance, &more), path, "iterate");
  std::vector<NMR::MODELMESHVERTEX> vertices;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  while (more) {
    Released object;
    check(NMR::lib3mf_resourceiterator_getcurrent(objects.instance, &object.instance), path,
          "get a mesh object");
    DWORD vertex_count = 0, triangle_count = 0;
    check(NMR::lib3mf_meshobject_getvertexcount(object.instance, &vertex_count), path,
          "count vertices");
    check(NMR::lib3mf_meshobject_gettrianglecount(object.instance, &triangle_count), path,
          "count triangles");
    vertices.resize(vertex_count);
    triangles.resize(triangle_count);
    if (vertex_count > 0)
      check(NMR::lib3mf_meshobject_getvertices(object.instance, vertices.data(), vertex_count,
                                               nullptr),
            path, "get vertices");
    if (triangle_count > 0)
      check(NMR::lib3mf_meshobject_gettriangleindices(object.instance, triangles.data(),
                                                      triangle_count, nullptr),
            path, "get triangles");
    const Index offset = static_cast<Index>(soup.num_vertices());
    for (const auto& v : vertices)
      soup.add_vertex(Point(v.m_fPosition[0], v.m_fPosition[1], v.m_fPosition[2]));
    for (const auto& t : triangles) {
      for (DWORD i : t.m_nIndices) {
        if (i >= vertex_count) {
          throw ReadError(path + ": 3MF triangle " + std::to_string(soup.num_faces()) +
                          " uses vertex " + std::to_string(i) + " of an object with " +
                          std::to_string(vertex_count) + " vertices");
        }
      }
      soup.add_polygon(
          {offset + t.m_nIndices[0], offset + t.m_nIndices[1], offset + t.m_nIndices[2]});
    }
    check(NMR::lib3mf_resourceiterator_movenext(objects.instance, &more), path, "iterate");
  }
  info.declared_vertices = soup.num_vertices();
  info.declared_faces = soup.num_faces();
}

}  // namespace meshbridge::detail
