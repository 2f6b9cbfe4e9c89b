// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/formats.h"
#include "io/objects_3mf.h"
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
  const std::vector<Object3mf> objects =
      objects_3mf(soup,
                  output_face_objects(
                      soup, mesh.face_origin,
                      attributes != nullptr ? attributes->face_objects : std::vector<FaceObject>()),
                  path);
  Released model, writer;
  check(NMR::lib3mf_createmodel(&model.instance), path, "create a model");
  // The input's unit (a 3MF read in inches stays in inches); millimetres otherwise.
  check(NMR::lib3mf_model_setunit(model.instance,
                                  unit_3mf(attributes != nullptr ? attributes->length_unit : "")),
        path, "set the model's unit");
  if (attributes != nullptr) {
    for (const Metadata& entry : attributes->metadata) {
      check(NMR::lib3mf_model_addmetadatautf8(model.instance, entry.name.c_str(),
                                              entry.value.c_str()),
            path, ("add the metadata '" + entry.name + "'").c_str());
    }
  }
  std::vector<NMR::MODELMESHVERTEX> vertices;
  for (const Object3mf& o : objects) {
    vertices.resize(o.vertices.size());
    for (std::size_t v = 0; v < o.vertices.size(); ++v)
      for (int a = 0; a < 3; ++a)
        vertices[v].m_fPosition[a] = static_cast<float>(soup.positions[o.vertices[v]][a]);
    Released object, item;
    check(NMR::lib3mf_model_addmeshobject(model.instance, &object.instance), path,
          "add a mesh object");
    check(NMR::lib3mf_meshobject_setgeometry(
              object.instance, vertices.data(), static_cast<DWORD>(vertices.size()),
              const_cast<NMR::MODELMESHTRIANGLE*>(o.triangles.data()),
              static_cast<DWORD>(o.triangles.size())),
          path, "store the mesh");
    check(NMR::lib3mf_object_settype(object.instance, lib3mf_object_type(o.kind.type)), path,
          "set an object's type");
    // The specification allows no build item for an object of type "other".
    if (o.kind.in_build && o.kind.type != ObjectType::other) {
      check(
          NMR::lib3mf_model_addbuilditem(model.instance, object.instance, nullptr, &item.instance),
          path, "add the build item");
    }
  }
  check(NMR::lib3mf_model_querywriter(model.instance, "3mf", &writer.instance), path,
        "create a writer");
  check(NMR::lib3mf_writer_writetofileutf8(writer.instance, out.temporary_path().c_str()), path,
        "write the file");
}

ThreeMfRounding measure_3mf_rounding(const std::string& path, const Soup& soup,
                                     const std::vector<FaceObject>& face_objects) {
  ThreeMfRounding rounding;
  std::vector<Object3mf> objects;
  try {
    objects = objects_3mf(soup, face_objects, path);
  } catch (const WriteError&) {
    return rounding;  // not what write_3mf() wrote
  }
  Released model, reader, iterator;
  if (NMR::lib3mf_createmodel(&model.instance) != LIB3MF_OK ||
      NMR::lib3mf_model_queryreader(model.instance, "3mf", &reader.instance) != LIB3MF_OK ||
      NMR::lib3mf_reader_readfromfileutf8(reader.instance, path.c_str()) != LIB3MF_OK ||
      NMR::lib3mf_model_getmeshobjects(model.instance, &iterator.instance) != LIB3MF_OK) {
    return rounding;
  }
  const auto given = [&soup](Index v, int a) { return static_cast<float>(soup.positions[v][a]); };
  std::vector<bool> moved(soup.num_vertices(), false);
  std::vector<NMR::MODELMESHVERTEX> written;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  for (const Object3mf& o : objects) {
    BOOL more = false;
    Released object;
    if (NMR::lib3mf_resourceiterator_movenext(iterator.instance, &more) != LIB3MF_OK || !more ||
        NMR::lib3mf_resourceiterator_getcurrent(iterator.instance, &object.instance) != LIB3MF_OK) {
      return rounding;
    }
    DWORD vertex_count = 0, triangle_count = 0;
    if (NMR::lib3mf_meshobject_getvertexcount(object.instance, &vertex_count) != LIB3MF_OK ||
        NMR::lib3mf_meshobject_gettrianglecount(object.instance, &triangle_count) != LIB3MF_OK ||
        vertex_count != o.vertices.size() || triangle_count != o.triangles.size()) {
      return rounding;
    }
    written.resize(vertex_count);
    triangles.resize(triangle_count);
    if ((vertex_count > 0 &&
         NMR::lib3mf_meshobject_getvertices(object.instance, written.data(), vertex_count,
                                            nullptr) != LIB3MF_OK) ||
        (triangle_count > 0 &&
         NMR::lib3mf_meshobject_gettriangleindices(object.instance, triangles.data(),
                                                   triangle_count, nullptr) != LIB3MF_OK)) {
      return rounding;
    }
    for (DWORD v = 0; v < vertex_count; ++v) {
      for (int a = 0; a < 3; ++a) {
        const float difference = std::abs(written[v].m_fPosition[a] - given(o.vertices[v], a));
        if (difference != 0)
          moved[o.vertices[v]] = true;
        rounding.largest_move = std::max(rounding.largest_move, double(difference));
      }
    }
    const auto same = [&](DWORD u, DWORD v, bool as_written) {
      for (int a = 0; a < 3; ++a) {
        if ((as_written ? written[u].m_fPosition[a] : given(o.vertices[u], a)) !=
            (as_written ? written[v].m_fPosition[a] : given(o.vertices[v], a)))
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
  }
  rounding.moved = static_cast<std::size_t>(std::count(moved.begin(), moved.end(), true));
  rounding.measured = true;
  return rounding;
}

}  // namespace meshbridge::detail
