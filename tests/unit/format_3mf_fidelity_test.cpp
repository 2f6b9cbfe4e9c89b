// SPDX-License-Identifier: GPL-3.0-or-later
// What a 3MF holds beyond its triangles is kept or named, not dropped without a word: the
// model's unit and metadata and its objects' types (kept, written back, named for outputs
// without them), triangle colours and materials, object names (named); and what lib3mf 1.8's
// writer does to positions (6 decimals at most) is measured from the written file.

#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace meshbridge {
namespace {

std::string scratch(const char* name) {
  return "/tmp/meshbridge_3mf_fidelity_" + std::to_string(::getpid()) + "_" + name;
}

//! True if one phrase of `phrases` holds `part`.
bool any_holds(const std::vector<std::string>& phrases, const std::string& part) {
  for (const std::string& phrase : phrases) {
    if (phrase.find(part) != std::string::npos)
      return true;
  }
  return false;
}

// A tetrahedron (x = 10 at one corner) in inches, named "Part A", its triangles coloured.
void write_inch_tetrahedron(const std::string& path) {
  NMR::PLib3MFModel* model = nullptr;
  NMR::PLib3MFModelMeshObject* object = nullptr;
  NMR::PLib3MFPropertyHandler* properties = nullptr;
  NMR::PLib3MFDefaultPropertyHandler* defaults = nullptr;
  NMR::PLib3MFModelBuildItem* item = nullptr;
  NMR::PLib3MFModelWriter* writer = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_setunit(model, NMR::MODELUNIT_INCH), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &object), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_object_setnameutf8(object, "Part A"), LIB3MF_OK);
  NMR::MODELMESHVERTEX vertices[4] = {{{0, 0, 0}}, {{10, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  NMR::MODELMESHTRIANGLE triangles[4] = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}};
  ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(object, vertices, 4, triangles, 4), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_meshobject_createpropertyhandler(object, &properties), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_propertyhandler_setsinglecolorrgb(properties, 0, 255, 0, 0), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_propertyhandler_setsinglecolorrgb(properties, 2, 0, 0, 255), LIB3MF_OK);
  // lib3mf writes triangle colours only with a default for the object: every triangle has one.
  ASSERT_EQ(NMR::lib3mf_object_createdefaultpropertyhandler(object, &defaults), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_defaultpropertyhandler_setcolorrgb(defaults, 128, 128, 128), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, object, nullptr, &item), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_querywriter(model, "3mf", &writer), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()), LIB3MF_OK);
  for (NMR::PLib3MFBase* p :
       std::vector<NMR::PLib3MFBase*>{writer, item, defaults, properties, object, model})
    NMR::lib3mf_release(p);
}

TEST(Format3mfFidelity, the_unit_is_kept_written_back_and_named_where_it_cannot_go) {
  const std::string path = scratch("inch.3mf");
  write_inch_tetrahedron(path);
  MeshAttributes attributes;
  const Soup soup = read_soup(path, nullptr, &attributes);
  std::remove(path.c_str());
  ASSERT_EQ(soup.num_faces(), 4u);
  EXPECT_EQ(soup.positions[1][0], 10.0);  // as written, in inches
  EXPECT_EQ(attributes.length_unit, "inch");
  // Outputs without a unit name it; a 3MF output keeps it.
  EXPECT_TRUE(any_holds(describe_unwritten("out.stl", attributes),
                        "3MF unit 'inch' not written: STL has no unit, and the coordinates stay "
                        "as written, in inches (a slicer reads them as millimetres)"));
  EXPECT_FALSE(any_holds(describe_unwritten("out.3mf", attributes), "unit"));
  EXPECT_TRUE(any_holds(describe_not_held(attributes), "3MF unit 'inch'"));
  IndexedMesh mesh;
  mesh.soup = soup;
  const std::string out = scratch("inch_out.3mf");
  write_mesh(out, mesh, &attributes);
  MeshAttributes back;
  read_soup(out, nullptr, &back);
  std::remove(out.c_str());
  EXPECT_EQ(back.length_unit, "inch");
  // Without attributes (or from another format) the output is in millimetres, the convention.
  write_mesh(out, mesh);
  read_soup(out, nullptr, &back);
  std::remove(out.c_str());
  EXPECT_EQ(back.length_unit, "millimeter");
  EXPECT_TRUE(describe_unwritten("out.stl", back).empty());
}

TEST(Format3mfFidelity, triangle_colors_and_object_names_are_named_as_read_past) {
  const std::string path = scratch("coloured.3mf");
  write_inch_tetrahedron(path);
  MeshAttributes attributes;
  read_soup(path, nullptr, &attributes);
  std::remove(path.c_str());
  const std::vector<std::string> left_out = describe_unwritten("out.ply", attributes);
  EXPECT_TRUE(any_holds(left_out,
                        "3MF triangle colours, materials or texture coordinates "
                        "(m:colorgroup, basematerials, texture2dgroup), on 4 triangles: "
                        "not written"));
  EXPECT_TRUE(any_holds(left_out, "3MF object names, on 1 object: not written"));
}

// A slicer's file with objects of every type: tetrahedra 10 apart along x, the first two of type
// model, then one each of support, solidsupport and surface, all in the build; then a model and
// an "other" in no build item (the specification lets no build item place an "other"). The
// model has two metadata entries.
const std::vector<std::pair<DWORD, bool>> kObjects = {
    {NMR::MODELOBJECTTYPE_MODEL, true},   {NMR::MODELOBJECTTYPE_MODEL, true},
    {NMR::MODELOBJECTTYPE_SUPPORT, true}, {NMR::MODELOBJECTTYPE_SOLIDSUPPORT, true},
    {NMR::MODELOBJECTTYPE_SURFACE, true}, {NMR::MODELOBJECTTYPE_MODEL, false},
    {NMR::MODELOBJECTTYPE_OTHER, false}};

void write_objects_of_every_type(const std::string& path) {
  NMR::PLib3MFModel* model = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addmetadatautf8(model, "Title", "Bracket & support"), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addmetadatautf8(model, "Designer", "M\xc3\xbcller"), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_setunit(model, NMR::MODELUNIT_CENTIMETER), LIB3MF_OK);
  std::vector<NMR::PLib3MFBase*> made;
  for (std::size_t k = 0; k < kObjects.size(); ++k) {
    const float x = 10.0f * float(k);
    NMR::MODELMESHVERTEX vertices[4] = {{{x, 0, 0}}, {{x + 1, 0, 0}}, {{x, 1, 0}}, {{x, 0, 1}}};
    NMR::MODELMESHTRIANGLE triangles[4] = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}};
    NMR::PLib3MFModelMeshObject* object = nullptr;
    ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &object), LIB3MF_OK);
    ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(object, vertices, 4, triangles, 4), LIB3MF_OK);
    ASSERT_EQ(NMR::lib3mf_object_settype(object, kObjects[k].first), LIB3MF_OK);
    made.push_back(object);
    if (kObjects[k].second) {
      NMR::PLib3MFModelBuildItem* item = nullptr;
      ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, object, nullptr, &item), LIB3MF_OK);
      made.push_back(item);
    }
  }
  NMR::PLib3MFModelWriter* writer = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_querywriter(model, "3mf", &writer), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()), LIB3MF_OK);
  made.push_back(writer);
  made.push_back(model);
  for (NMR::PLib3MFBase* p : made)
    NMR::lib3mf_release(p);
}

// A 3MF file's mesh objects as lib3mf reads them: type, in a build item, triangles.
struct ObjectSeen {
  DWORD type = 0;
  bool in_build = false;
  DWORD triangles = 0;
  friend bool operator==(const ObjectSeen& x, const ObjectSeen& y) {
    return x.type == y.type && x.in_build == y.in_build && x.triangles == y.triangles;
  }
};

std::vector<ObjectSeen> objects_in(const std::string& path) {
  std::vector<ObjectSeen> seen;
  NMR::PLib3MFModel* model = nullptr;
  NMR::PLib3MFModelReader* reader = nullptr;
  NMR::PLib3MFModelResourceIterator* objects = nullptr;
  NMR::PLib3MFModelBuildItemIterator* items = nullptr;
  EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_reader_readfromfileutf8(reader, path.c_str()), LIB3MF_OK);
  std::vector<DWORD> placed;
  EXPECT_EQ(NMR::lib3mf_model_getbuilditems(model, &items), LIB3MF_OK);
  BOOL more = false;
  while (NMR::lib3mf_builditemiterator_movenext(items, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFModelBuildItem* item = nullptr;
    DWORD id = 0;
    EXPECT_EQ(NMR::lib3mf_builditemiterator_getcurrent(items, &item), LIB3MF_OK);
    EXPECT_EQ(NMR::lib3mf_builditem_getobjectresourceid(item, &id), LIB3MF_OK);
    placed.push_back(id);
    NMR::lib3mf_release(item);
  }
  EXPECT_EQ(NMR::lib3mf_model_getmeshobjects(model, &objects), LIB3MF_OK);
  while (NMR::lib3mf_resourceiterator_movenext(objects, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFModelResource* object = nullptr;
    EXPECT_EQ(NMR::lib3mf_resourceiterator_getcurrent(objects, &object), LIB3MF_OK);
    ObjectSeen o;
    DWORD id = 0;
    EXPECT_EQ(NMR::lib3mf_resource_getresourceid(object, &id), LIB3MF_OK);
    EXPECT_EQ(NMR::lib3mf_object_gettype(object, &o.type), LIB3MF_OK);
    EXPECT_EQ(NMR::lib3mf_meshobject_gettrianglecount(object, &o.triangles), LIB3MF_OK);
    o.in_build = std::count(placed.begin(), placed.end(), id) > 0;
    seen.push_back(o);
    NMR::lib3mf_release(object);
  }
  for (NMR::PLib3MFBase* p : std::vector<NMR::PLib3MFBase*>{objects, items, reader, model})
    NMR::lib3mf_release(p);
  return seen;
}

TEST(Format3mfFidelity, object_types_are_kept_per_face_and_written_back_as_objects) {
  const std::string path = scratch("types.3mf");
  write_objects_of_every_type(path);
  MeshAttributes attributes;
  const Soup soup = read_soup(path, nullptr, &attributes);
  std::remove(path.c_str());
  ASSERT_EQ(soup.num_faces(), 28u);  // nothing dropped
  // The build in file order, then the objects in no build item.
  ASSERT_EQ(attributes.face_objects.size(), 28u);
  const std::vector<FaceObject> expected = {
      {ObjectType::model, true},        {ObjectType::model, true},   {ObjectType::support, true},
      {ObjectType::solidsupport, true}, {ObjectType::surface, true}, {ObjectType::model, false},
      {ObjectType::other, false}};
  for (std::size_t f = 0; f < 28; ++f)
    EXPECT_EQ(attributes.face_objects[f], expected[f / 4]) << "face " << f;
  EXPECT_EQ(soup.positions[4 * 4][0], 40.0);  // the surface, fifth
  EXPECT_EQ(attributes.length_unit, "centimeter");
  EXPECT_EQ(attributes.metadata,
            (std::vector<Metadata>{{"Title", "Bracket & support"}, {"Designer", "M\xc3\xbcller"}}));
  // Kept, so no longer among what is read past; a soup alone does not hold them.
  EXPECT_TRUE(attributes.not_kept.empty());
  EXPECT_TRUE(any_holds(describe_not_held(attributes),
                        "3MF objects that are not the printed model (4 faces of type support, 4 "
                        "faces of type solidsupport, 4 faces of type surface, 4 faces of an "
                        "object in no build item, 4 faces of type other in no build item)"));

  // Repaired and written as 3MF: one object per kind, of its type, in the build where it was.
  const RepairResult repaired = repair(soup);
  ASSERT_EQ(repaired.mesh.soup.num_faces(), 28u);
  const std::string out = scratch("types_out.3mf");
  write_mesh(out, repaired.mesh, &attributes);
  const std::vector<ObjectSeen> expected_objects = {
      {NMR::MODELOBJECTTYPE_MODEL, true, 8},        {NMR::MODELOBJECTTYPE_SUPPORT, true, 4},
      {NMR::MODELOBJECTTYPE_SOLIDSUPPORT, true, 4}, {NMR::MODELOBJECTTYPE_SURFACE, true, 4},
      {NMR::MODELOBJECTTYPE_MODEL, false, 4},       {NMR::MODELOBJECTTYPE_OTHER, false, 4}};
  EXPECT_EQ(objects_in(out), expected_objects);
  EXPECT_TRUE(describe_unwritten(out, attributes).empty());
  // Measured object by object: whole numbers come back exactly.
  EXPECT_TRUE(describe_written(out, repaired.mesh, attributes).left_out.empty());
  MeshAttributes back;
  const Soup again = read_soup(out, nullptr, &back);
  std::remove(out.c_str());
  EXPECT_EQ(again.num_faces(), 28u);
  EXPECT_EQ(back.face_objects, attributes.face_objects);
  EXPECT_EQ(back.length_unit, "centimeter");
  EXPECT_EQ(back.metadata, attributes.metadata);
  // carry_attributes() maps them to the repaired mesh's faces.
  EXPECT_EQ(carry_attributes(attributes, repaired.mesh).face_objects, attributes.face_objects);

  // Formats without objects say what becomes of them.
  const std::vector<std::string> stl = describe_unwritten("out.stl", attributes);
  EXPECT_TRUE(any_holds(stl,
                        "3MF objects that are not the printed model (4 faces of type support, "
                        "4 faces of type solidsupport, 4 faces of type surface, 4 faces of an "
                        "object in no build item, 4 faces of type other in no build item) "
                        "written into the one mesh with the model: STL has no objects, so a "
                        "slicer prints them as part of the model (write 3MF to keep them apart)"));
  EXPECT_TRUE(any_holds(stl,
                        "3MF metadata not written (2 entries: Title, Designer): STL holds "
                        "none"));
}

TEST(Format3mfFidelity, a_filled_hole_stays_in_the_object_it_closes) {
  // A closed tetrahedron of the model, and a support tetrahedron without its last face.
  Soup soup;
  for (int k = 0; k < 2; ++k) {
    const double x = 10.0 * k;
    for (const Point& p : {Point(x, 0, 0), Point(x + 1, 0, 0), Point(x, 1, 0), Point(x, 0, 1)})
      soup.add_vertex(p);
    const Index o = static_cast<Index>(4 * k);
    soup.add_polygon({o, o + 2, o + 1});
    soup.add_polygon({o, o + 1, o + 3});
    soup.add_polygon({o, o + 3, o + 2});
    if (k == 0)
      soup.add_polygon({o + 1, o + 2, o + 3});
  }
  MeshAttributes attributes;
  attributes.face_objects.assign(4, FaceObject{});
  attributes.face_objects.resize(7, FaceObject{ObjectType::support, true});
  RepairOptions options;
  options.fill_holes.max_edges = 3;
  const RepairResult repaired = repair(soup, options);
  ASSERT_EQ(repaired.mesh.soup.num_faces(), 8u);
  ASSERT_EQ(repaired.mesh.face_origin.back(), kNoIndex);  // the patch
  EXPECT_EQ(carry_attributes(attributes, repaired.mesh).face_objects.back().type,
            ObjectType::support);
  const std::string out = scratch("patched.3mf");
  write_mesh(out, repaired.mesh, &attributes);
  const std::vector<ObjectSeen> expected = {{NMR::MODELOBJECTTYPE_MODEL, true, 4},
                                            {NMR::MODELOBJECTTYPE_SUPPORT, true, 4}};
  EXPECT_EQ(objects_in(out), expected);
  EXPECT_TRUE(describe_written(out, repaired.mesh, attributes).left_out.empty());
  std::remove(out.c_str());
}

TEST(Format3mfFidelity, a_file_of_the_model_alone_has_no_objects_to_tell) {
  const std::string path = scratch("model.3mf");
  write_inch_tetrahedron(path);
  MeshAttributes attributes;
  read_soup(path, nullptr, &attributes);
  std::remove(path.c_str());
  EXPECT_TRUE(attributes.face_objects.empty());
  EXPECT_TRUE(attributes.metadata.empty());
  EXPECT_FALSE(any_holds(describe_unwritten("out.stl", attributes), "3MF objects"));
  EXPECT_FALSE(any_holds(describe_unwritten("out.stl", attributes), "metadata"));
}

TEST(Format3mfFidelity, what_lib3mf_writes_of_the_positions_is_measured_from_the_file) {
  // A tetrahedron 2 mm across with one corner 0.0000004 mm from another: lib3mf writes at most
  // 6 decimals, so the two land on one point and two triangles lose their area.
  Soup fine;
  fine.add_vertex({0, 0, 0});
  fine.add_vertex({0.002, 0, 0});
  fine.add_vertex({0, 0.002, 0});
  fine.add_vertex({4e-7, 3e-7, 2e-7});
  fine.add_polygon({0, 2, 1});
  fine.add_polygon({0, 1, 3});
  fine.add_polygon({1, 2, 3});
  fine.add_polygon({0, 3, 2});
  IndexedMesh mesh;
  mesh.soup = fine;
  const std::string path = scratch("fine.3mf");
  write_mesh(path, mesh);
  const WrittenOutput written = describe_written(path, fine, MeshAttributes());
  EXPECT_TRUE(any_holds(written.left_out,
                        "positions of 1 vertex moved by up to 4e-07 as lib3mf "
                        "wrote them (3MF text, at most 6 decimals)"))
      << (written.left_out.empty() ? std::string("nothing") : written.left_out.front());
  EXPECT_TRUE(any_holds(written.left_out,
                        "2 triangles written with two corners at one point: the mesh is finer "
                        "than lib3mf's 6 decimals"));
  // Whole millimetres come back exactly: nothing to say.
  Soup whole = fine;
  whole.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 1}};
  mesh.soup = whole;
  write_mesh(path, mesh);
  EXPECT_TRUE(describe_written(path, whole, MeshAttributes()).left_out.empty());
  std::remove(path.c_str());
  // Beyond lib3mf's 1e9: a clear error, no file.
  whole.positions[3] = {2e9, 0, 0};
  mesh.soup = whole;
  try {
    write_mesh(path, mesh);
    FAIL() << "no error";
  } catch (const WriteError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("vertex 3 has the coordinate 2000000000.000000, "
                        "beyond the 1e9 (1 billion mm) that lib3mf writes"),
              std::string::npos)
        << error.what();
  }
  EXPECT_NE(::access(path.c_str(), F_OK), 0);
}

}  // namespace
}  // namespace meshbridge
