// SPDX-License-Identifier: GPL-3.0-or-later
// What a 3MF holds beyond its triangles is named, not dropped without a word: the model's unit
// (kept, written back, named for outputs without units), triangle colours and materials, object
// names; and what lib3mf 1.8's writer does to positions (6 decimals at most) is measured from the
// written file.

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <string>
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

TEST(Format3mfFidelity, triangle_colours_and_object_names_are_named_as_read_past) {
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

// A tetrahedron in the build, a support tetrahedron in the build, and one in no build item.
void write_support_and_unplaced(const std::string& path) {
  NMR::PLib3MFModel* model = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  std::vector<NMR::PLib3MFBase*> made;
  NMR::MODELMESHVERTEX vertices[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  NMR::MODELMESHTRIANGLE triangles[4] = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}};
  for (const char* kind : {"model", "support", "unplaced"}) {
    NMR::PLib3MFModelMeshObject* object = nullptr;
    ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &object), LIB3MF_OK);
    ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(object, vertices, 4, triangles, 4), LIB3MF_OK);
    made.push_back(object);
    if (std::string(kind) == "support")
      ASSERT_EQ(NMR::lib3mf_object_settype(object, NMR::MODELOBJECTTYPE_SUPPORT), LIB3MF_OK);
    if (std::string(kind) != "unplaced") {
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

TEST(Format3mfFidelity, objects_a_slicer_would_not_print_as_the_model_are_named) {
  const std::string path = scratch("support.3mf");
  write_support_and_unplaced(path);
  MeshAttributes attributes;
  const Soup soup = read_soup(path, nullptr, &attributes);
  std::remove(path.c_str());
  EXPECT_EQ(soup.num_faces(), 12u);  // nothing dropped
  const std::vector<std::string> held = describe_not_held(attributes);
  EXPECT_TRUE(any_holds(held,
                        "3MF mesh objects in no build item (a slicer does not print them), "
                        "read as stored, after the build, on 1 object"));
  EXPECT_TRUE(any_holds(held,
                        "3MF object types other than 'model' (support, solidsupport, "
                        "surface, other), read as model shells, on 1 object"));
  for (const NotKept& n : attributes.not_kept)
    EXPECT_TRUE(n.fault) << n.what;  // check warns about both
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
