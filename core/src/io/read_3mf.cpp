// SPDX-License-Identifier: GPL-3.0-or-later
// 3MF reading through lib3mf 1.8's v1 C API: what a slicer prints, the build items with their
// transforms (3MF Core Specification 1.2, section 3.4: build; 4.1: components). The meshes'
// vertices and triangles are read apart by pugixml where they can be (mesh_xml_3mf.h), and lib3mf
// reads the package with those lists emptied; where it refuses that, it reads the file itself.
#include "io/affine_3mf.h"
#include "io/formats.h"
#include "io/mesh_xml_3mf.h"
#include "io/units_3mf.h"

#include "meshbridge/errors.h"

#include <Common/NMR_ErrorConst.h>
#include <Model/COM/NMR_DLLInterfaces.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <utility>
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

// lib3mf's transform as an Affine (affine_3mf.h).
Affine affine(const NMR::MODELTRANSFORM& t) {
  Affine a{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      a[j][i] = t.m_fFields[j][i];
  return a;
}

// Reads models, their objects and their build into one soup.
//! Thrown by Reader when a mesh read apart cannot be matched to lib3mf's object (see add_mesh).
struct MeshesApartUnmatched {};

class Reader {
 public:
  using MeshesXml = std::map<std::uint32_t, MeshXml>;
  //! `meshes`: the meshes pugixml read, by object id (may be null: lib3mf read them all).
  Reader(const std::string& path, Soup& soup, MeshesXml* meshes)
      : path_(path), soup_(soup), meshes_(meshes) {}

  //! What the placed mesh objects carry that MeshBridge reads past (see add_mesh).
  struct Properties {
    std::size_t triangles = 0;  //!< triangles with a colour, material or texture coordinate
    std::size_t names = 0;      //!< mesh objects with a name
  };
  const Properties& properties() const { return properties_; }

  //! One per soup face (MeshAttributes::face_objects), or empty when every face is of a placed
  //! "model" object.
  std::vector<FaceObject> face_objects() const {
    std::vector<FaceObject> faces;
    if (!any_other_object_)
      return faces;
    faces.reserve(soup_.num_faces());
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      const std::size_t end = r + 1 < runs_.size() ? runs_[r + 1].first : soup_.num_faces();
      faces.resize(end, runs_[r].second);
    }
    return faces;
  }

  // Appends the triangles of mesh object `object`, its vertices mapped by `placement` (their
  // corner order reversed where it mirrors); `in_build` tells whether a build item placed it.
  // The mesh is the one pugixml read (`meshes`, by the object's id) or else lib3mf's.
  void add_mesh(NMR::PLib3MFModelObjectResource* object, const Affine& placement, bool transformed,
                bool in_build) {
    DWORD id = 0;
    check(NMR::lib3mf_resource_getresourceid(object, &id), path_, "get an object's id");
    const auto parsed = meshes_ != nullptr ? meshes_->find(id) : MeshesXml::iterator();
    const bool from_xml = meshes_ != nullptr && parsed != meshes_->end();
    const Point* points = nullptr;  // read apart
    const float* floats = nullptr;  // lib3mf's
    const std::uint32_t* corners = nullptr;
    std::size_t vertex_count = 0, triangle_count = 0;
    if (from_xml) {
      points = parsed->second.positions.data();
      corners = parsed->second.corners.data();
      vertex_count = id == moved_.positions ? moved_.vertex_count : parsed->second.positions.size();
      triangle_count =
          (id == moved_.corners ? moved_.corner_count : parsed->second.corners.size()) / 3;
    } else {
      read_lib3mf_mesh(object);
      floats = vertices_.empty() ? nullptr : vertices_[0].m_fPosition;
      corners = triangles_.empty() ? nullptr : triangles_[0].m_nIndices;
      vertex_count = vertices_.size();
      triangle_count = triangles_.size();
      // With meshes read apart, an empty mesh from lib3mf is most likely one pugixml read under
      // an id lib3mf gives otherwise (it numbers some files' objects its own way): the whole
      // file goes to lib3mf instead (found on a Cura printer bed whose mesh object precedes the
      // components object placing it).
      if (meshes_ != nullptr && vertex_count == 0)
        throw MeshesApartUnmatched();
    }
    DWORD type = NMR::MODELOBJECTTYPE_MODEL;
    check(NMR::lib3mf_object_gettype(object, &type), path_, "get an object's type");
    const FaceObject kind{object_type(type), in_build};
    any_other_object_ = any_other_object_ || !kind.is_printed_model();
    if (runs_.empty() || runs_.back().second != kind)
      runs_.emplace_back(soup_.num_faces(), kind);
    const bool reversed = transformed && mirrors(placement);
    const Index offset = static_cast<Index>(soup_.num_vertices());
    // The first mesh read apart, as it is: its positions and corners become the soup's (no copy
    // of 25 MB for 1M triangles); a later placement of the same mesh copies them from there.
    if (from_xml && offset == 0 && !transformed && moved_.positions == kNone) {
      soup_.positions.swap(parsed->second.positions);
      moved_.positions = id;
      moved_.vertex_count = soup_.num_vertices();
    } else {
      soup_.positions.reserve(offset + vertex_count);
      if (from_xml && id == moved_.positions)
        points = soup_.positions.data();  // after the reserve: it may have moved
      for (std::size_t v = 0; v < vertex_count; ++v) {
        const Point p =
            from_xml ? points[v] : Point(floats[3 * v], floats[3 * v + 1], floats[3 * v + 2]);
        soup_.add_vertex(transformed ? apply(placement, p) : p);
      }
    }
    for (std::size_t c = 0; !from_xml && c < 3 * triangle_count; ++c) {  // the scan checked its own
      if (corners[c] >= vertex_count) {
        throw ReadError(path_ + ": 3MF triangle " + std::to_string(soup_.num_faces() + c / 3) +
                        " uses vertex " + std::to_string(corners[c]) + " of an object with " +
                        std::to_string(vertex_count) + " vertices");
      }
    }
    const std::size_t first = soup_.num_corners();
    if (from_xml && first == 0 && offset == 0 && !reversed && moved_.corners == kNone) {
      soup_.corner_vertices.swap(parsed->second.corners);
      moved_.corners = id;
      moved_.corner_count = soup_.num_corners();
    } else {
      // Appended whole, not a triangle at a time (a tenth of a 1M-triangle 3MF's read).
      soup_.corner_vertices.resize(first + 3 * triangle_count);
      if (from_xml && id == moved_.corners)
        corners = soup_.corner_vertices.data();  // after the resize: it may have moved
      add_corners(corners, triangle_count, offset, reversed, first);
    }
    const std::size_t faces = soup_.num_faces();
    soup_.face_begin.resize(faces + 1 + triangle_count);
    for (std::size_t t = 1; t <= triangle_count; ++t)
      soup_.face_begin[faces + t] = static_cast<Index>(first + 3 * t);
    count_properties(object, triangle_count, from_xml);
  }

  // Writes the corners of `triangle_count` triangles from `corners` at corner `first` of the
  // soup, each vertex number `offset` on, their order reversed if `reversed`.
  void add_corners(const std::uint32_t* corners, std::size_t triangle_count, Index offset,
                   bool reversed, std::size_t first) {
    Index* out = soup_.corner_vertices.data() + first;
    for (std::size_t t = 0; t < triangle_count; ++t) {
      const std::uint32_t* i = corners + 3 * t;
      out[3 * t] = offset + i[0];
      out[3 * t + 1] = offset + i[reversed ? 2 : 1];
      out[3 * t + 2] = offset + i[reversed ? 1 : 2];
    }
  }

  // lib3mf's mesh of `object` into vertices_ and triangles_.
  void read_lib3mf_mesh(NMR::PLib3MFModelObjectResource* object) {
    DWORD vertex_count = 0, triangle_count = 0;
    check(NMR::lib3mf_meshobject_getvertexcount(object, &vertex_count), path_, "count vertices");
    check(NMR::lib3mf_meshobject_gettrianglecount(object, &triangle_count), path_,
          "count triangles");
    vertices_.resize(vertex_count);
    triangles_.resize(triangle_count);
    if (vertex_count > 0)
      check(NMR::lib3mf_meshobject_getvertices(object, vertices_.data(), vertex_count, nullptr),
            path_, "get vertices");
    if (triangle_count > 0)
      check(NMR::lib3mf_meshobject_gettriangleindices(object, triangles_.data(), triangle_count,
                                                      nullptr),
            path_, "get triangles");
  }

  // Counts the triangles of `object` that carry a property (a colour of an m:colorgroup, a base
  // material, texture coordinates; the object's own pid gives one to every triangle without
  // one) and whether the object has a name: read past, so named (NotKept).
  // A mesh pugixml read (`from_xml`) has no triangle properties (read_meshes_xml() leaves such
  // meshes to lib3mf).
  void count_properties(NMR::PLib3MFModelObjectResource* object, std::size_t triangle_count,
                        bool from_xml) {
    ULONG name_length = 0;
    if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &name_length) == LIB3MF_OK)
      properties_.names += name_length > 0;
    Released defaults, handler;
    NMR::eModelPropertyType property = NMR::MODELPROPERTYTYPE_NONE;
    bool object_default = false;
    if (NMR::lib3mf_object_createdefaultpropertyhandler(object, &defaults.instance) == LIB3MF_OK &&
        NMR::lib3mf_defaultpropertyhandler_getpropertytype(defaults.instance, &property) ==
            LIB3MF_OK) {
      object_default = property != NMR::MODELPROPERTYTYPE_NONE;
    }
    if (from_xml) {
      properties_.triangles += object_default ? triangle_count : 0;
      return;
    }
    if (NMR::lib3mf_meshobject_createpropertyhandler(object, &handler.instance) != LIB3MF_OK)
      return;
    for (DWORD t = 0; t < triangle_count; ++t) {
      property = NMR::MODELPROPERTYTYPE_NONE;
      NMR::lib3mf_propertyhandler_getpropertytype(handler.instance, t, &property);
      properties_.triangles += object_default || property != NMR::MODELPROPERTYTYPE_NONE;
    }
  }

  // Appends `object` (a mesh, or components placing other objects) under `placement`.
  void add_object(NMR::PLib3MFModelObjectResource* object, const Affine& placement,
                  bool transformed, int depth) {
    DWORD id = 0;
    check(NMR::lib3mf_resource_getresourceid(object, &id), path_, "get an object's id");
    if (depth > kMaxDepth) {
      throw ReadError(path_ + ": 3MF object " + std::to_string(id) +
                      " nests components more than " + std::to_string(kMaxDepth) + " levels deep");
    }
    BOOL is_mesh = false, is_components = false;
    check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), path_, "tell an object's kind");
    check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), path_,
          "tell an object's kind");
    if (is_mesh) {
      placed_.insert(id);
      add_mesh(object, placement, transformed, true);
      return;
    }
    if (!is_components)
      return;
    DWORD count = 0;
    check(NMR::lib3mf_componentsobject_getcomponentcount(object, &count), path_,
          "count an object's components");
    for (DWORD c = 0; c < count; ++c) {
      Released component, target;
      check(NMR::lib3mf_componentsobject_getcomponent(object, c, &component.instance), path_,
            "get a component");
      check(NMR::lib3mf_component_getobjectresource(component.instance, &target.instance), path_,
            "get a component's object");
      Affine inner = kIdentity;
      const bool has_transform =
          transform_of(component.instance, NMR::lib3mf_component_hastransform,
                       NMR::lib3mf_component_gettransform, "get a component's transform", inner);
      add_object(target.instance, compose(placement, inner), transformed || has_transform,
                 depth + 1);
    }
  }

  // Every build item in file order; returns how many there were.
  std::size_t add_build(NMR::PLib3MFModel* model) {
    Released items;
    check(NMR::lib3mf_model_getbuilditems(model, &items.instance), path_, "list the build items");
    std::size_t count = 0;
    for_each(
        items.instance, NMR::lib3mf_builditemiterator_movenext,
        NMR::lib3mf_builditemiterator_getcurrent, "get a build item", [&](NMR::PLib3MFBase* item) {
          Released object;
          check(NMR::lib3mf_builditem_getobjectresource(item, &object.instance), path_,
                "get a build item's object");
          Affine placement = kIdentity;
          const bool has_transform = transform_of(item, NMR::lib3mf_builditem_hasobjecttransform,
                                                  NMR::lib3mf_builditem_getobjecttransform,
                                                  "get a build item's transform", placement);
          add_object(object.instance, placement, has_transform, 0);
          ++count;
        });
    return count;
  }

  // Mesh objects that no build item reaches, as stored (nothing in a file is dropped).
  void add_unplaced(NMR::PLib3MFModel* model) {
    Released objects;
    check(NMR::lib3mf_model_getmeshobjects(model, &objects.instance), path_,
          "list the mesh objects");
    for_each(objects.instance, NMR::lib3mf_resourceiterator_movenext,
             NMR::lib3mf_resourceiterator_getcurrent, "get a mesh object",
             [&](NMR::PLib3MFBase* object) {
               DWORD id = 0;
               check(NMR::lib3mf_resource_getresourceid(object, &id), path_, "get an object's id");
               if (placed_.count(id) == 0) {
                 add_mesh(object, kIdentity, false, false);
               }
             });
  }

 private:
  // Calls visit(instance) for every instance a lib3mf iterator (build items or resources)
  // yields, releasing each after the visit.
  template <class Next, class Current, class Visit>
  void for_each(NMR::PLib3MFBase* iterator, Next next, Current current, const char* what,
                Visit visit) {
    BOOL more = false;
    check(next(iterator, &more), path_, "iterate");
    while (more) {
      Released instance;
      check(current(iterator, &instance.instance), path_, what);
      visit(instance.instance);
      check(next(iterator, &more), path_, "iterate");
    }
  }

  // The transform of a component or build item into `transform`, when it has one (else
  // `transform` is left as is); returns whether it has one.
  template <class Has, class Get>
  bool transform_of(NMR::PLib3MFBase* instance, Has has, Get get, const char* what,
                    Affine& transform) {
    BOOL present = false;
    check(has(instance, &present), path_, what);
    if (!present)
      return false;
    NMR::MODELTRANSFORM t;
    check(get(instance, &t), path_, what);
    transform = affine(t);
    return true;
  }

  // lib3mf's eModelObjectType as ObjectType ("other" for a number it does not list).
  static ObjectType object_type(DWORD type) {
    switch (type) {
      case NMR::MODELOBJECTTYPE_MODEL:
        return ObjectType::model;
      case NMR::MODELOBJECTTYPE_SUPPORT:
        return ObjectType::support;
      case NMR::MODELOBJECTTYPE_SOLIDSUPPORT:
        return ObjectType::solidsupport;
      case NMR::MODELOBJECTTYPE_SURFACE:
        return ObjectType::surface;
      default:
        return ObjectType::other;
    }
  }

  static constexpr int kMaxDepth = 64;
  const std::string& path_;
  Soup& soup_;
  MeshesXml* meshes_;
  static constexpr DWORD kNone = ~DWORD(0);
  // The meshes whose positions and whose corners went into the soup (add_mesh), and how many.
  struct Moved {
    DWORD positions = kNone, corners = kNone;
    std::size_t vertex_count = 0, corner_count = 0;
  } moved_;
  std::set<DWORD> placed_;  // mesh objects some build item reached
  std::vector<NMR::MODELMESHVERTEX> vertices_;
  std::vector<NMR::MODELMESHTRIANGLE> triangles_;
  Properties properties_;
  // The soup's faces by object kind: (first face, kind) where the kind changes.
  std::vector<std::pair<std::size_t, FaceObject>> runs_;
  bool any_other_object_ = false;
};

// The model's <metadata> entries, in file order.
void read_metadata(NMR::PLib3MFModel* model, const std::string& path,
                   std::vector<Metadata>& metadata) {
  DWORD count = 0;
  check(NMR::lib3mf_model_getmetadatacount(model, &count), path, "count the metadata");
  const auto text = [&](auto get, DWORD index) {
    ULONG length = 0;
    check(get(model, index, nullptr, 0, &length), path, "get a metadata entry");
    std::string s(length + 1, '\0');
    check(get(model, index, s.data(), length + 1, &length), path, "get a metadata entry");
    s.resize(std::strlen(s.c_str()));
    return s;
  };
  for (DWORD m = 0; m < count; ++m) {
    metadata.push_back({text(NMR::lib3mf_model_getmetadatakeyutf8, m),
                        text(NMR::lib3mf_model_getmetadatavalueutf8, m)});
  }
}

// Reads the package into `model`: `package` if given (the meshes read apart), else the file.
HRESULT read_package(Released& model, const std::string& path, std::vector<unsigned char>& package,
                     DWORD& code, std::string& message) {
  Released reader;
  check(NMR::lib3mf_createmodel(&model.instance), path, "create a model");
  check(NMR::lib3mf_model_queryreader(model.instance, "3mf", &reader.instance), path,
        "create a reader");
  const HRESULT status =
      package.empty()
          ? NMR::lib3mf_reader_readfromfileutf8(reader.instance, path.c_str())
          : NMR::lib3mf_reader_readfrombuffer(reader.instance, package.data(), package.size());
  if (status != LIB3MF_OK) {
    LPCSTR what = nullptr;
    NMR::lib3mf_getlasterror(reader.instance, &code, &what);
    message = what != nullptr ? what : "";
  }
  return status;
}

}  // namespace

void read_3mf(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  const std::string& path = file.path();
  std::map<std::uint32_t, MeshXml> meshes;
  std::vector<unsigned char> package;
#ifdef MESHBRIDGE_WITH_3MF_MESH_XML
  const char* route = std::getenv("MESHBRIDGE_3MF_MESHES");
  if (route == nullptr || std::string(route) != "lib3mf")
    package = package_without_meshes(file.data(), file.size(), meshes);
#endif
  Released model;
  DWORD code = 0;
  std::string message;
  HRESULT status = read_package(model, path, package, code, message);
  if (status != LIB3MF_OK && !package.empty()) {
    // lib3mf refuses what is left: it reads the whole file, and names the fault.
    meshes.clear();
    package = std::vector<unsigned char>();
    NMR::lib3mf_release(model.instance);
    model.instance = nullptr;
    status = read_package(model, path, package, code, message);
  }
  package = std::vector<unsigned char>();
  if (status != LIB3MF_OK) {
    // lib3mf's own words ("Could not read ZIP file", "Could not create OPC Part": lib3mf 1.8
    // refuses a package whose relationships name a part the archive lacks).
    std::string why = !message.empty() ? message : "unknown error";
    if (why == "Could not create OPC Part")
      why += " (a relationship of the package names a part that is not in the archive?)";
    if (code == NMR_ERROR_INVALIDMODELCOORDINATEINDICES) {
      why +=
          " (a triangle names one vertex twice, or a vertex its object does not have: lib3mf "
          "1.8 refuses the whole file for it)";
    }
    throw ReadError(path + ": lib3mf cannot read the file as 3MF: " + why + " (error " +
                    std::to_string(status) + ", lib3mf code " + std::to_string(code) + ")");
  }
  std::optional<Reader> reader;
  try {
    reader.emplace(path, soup, meshes.empty() ? nullptr : &meshes);
    reader->add_build(model.instance);
    reader->add_unplaced(model.instance);
  } catch (const MeshesApartUnmatched&) {
    meshes.clear();
    soup = Soup();
    NMR::lib3mf_release(model.instance);
    model.instance = nullptr;
    status = read_package(model, path, package, code, message);
    if (status != LIB3MF_OK) {
      throw ReadError(path + ": lib3mf cannot read the file as 3MF: " +
                      (message.empty() ? std::string("unknown error") : message));
    }
    reader.emplace(path, soup, nullptr);
    reader->add_build(model.instance);
    reader->add_unplaced(model.instance);
  }
  Reader& read = *reader;
  info.declared_vertices = soup.num_vertices();
  info.declared_faces = soup.num_faces();
  if (attributes == nullptr)
    return;
  DWORD unit = NMR::MODELUNIT_MILLIMETER;
  check(NMR::lib3mf_model_getunit(model.instance, &unit), path, "get the model's unit");
  attributes->length_unit = unit_name_3mf(unit);
  if (read.properties().triangles > 0) {
    attributes->not_kept.push_back(
        {"3MF triangle colours, materials or texture coordinates (m:colorgroup, basematerials, "
         "texture2dgroup)",
         read.properties().triangles, "triangle"});
  }
  if (read.properties().names > 0)
    attributes->not_kept.push_back({"3MF object names", read.properties().names, "object"});
  // What a slicer would not print as part of the model (supports, surfaces, objects in no build
  // item): kept per face, written back as objects of their own (describe_unwritten() names what
  // other formats make of them).
  attributes->face_objects = read.face_objects();
  read_metadata(model.instance, path, attributes->metadata);
}

}  // namespace meshbridge::detail
