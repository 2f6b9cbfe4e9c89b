// SPDX-License-Identifier: GPL-3.0-or-later
// The deflated model part found in the package's own memory (Package3mf::deflated_in_place(),
// core/src/io/package_3mf.cpp) is byte for byte what libzip copies out, in packages written by
// lib3mf (zip64 extra fields) and by libzip (plain records, a comment, the part not first); a
// package whose records were damaged gives the same bytes or none (libzip's copy is then read),
// never others.

#include "io/package_3mf.h"
#include "meshbridge/io.h"

#include <gtest/gtest.h>
#include <zip.h>

#include <unistd.h>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <vector>

namespace meshbridge::detail {
namespace {

std::string scratch(const char* name) {
  return "/tmp/meshbridge_3mf_package_" + std::to_string(::getpid()) + "_" + name;
}

std::vector<unsigned char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// What deflated_in_place() gives for the root model part of `bytes`: 1 for the bytes libzip
// copies out, 0 for none (nullptr), -1 for other bytes; -2 when libzip reads no such part.
int in_place_against_copy(const std::vector<unsigned char>& bytes) {
  Package3mf package(bytes.data(), bytes.size());
  if (!package.is_open())
    return -2;
  std::string root;
  try {
    root = package.root_model();
  } catch (const std::bad_alloc&) {  // a damaged size of _rels/.rels
    return -2;
  }
  PartStat part, copied;
  const unsigned char* in_place = package.deflated_in_place(root, part);
  PartBytes copy;
  bool copied_out = false;
  try {
    copied_out = package.read_deflated(root, copied, copy);
  } catch (const std::bad_alloc&) {  // a damaged size (package_without_meshes() catches it too)
  }
  if (!copied_out)
    return in_place == nullptr ? -2 : -1;
  if (in_place == nullptr)
    return 0;
  return part.compressed_size == copy.size && std::memcmp(in_place, copy.data.get(), copy.size) == 0
             ? 1
             : -1;
}

// A tetrahedron fan big enough to be deflated in several blocks.
IndexedMesh fan(int n) {
  IndexedMesh mesh;
  mesh.soup.add_vertex({0, 0, 0});
  for (int k = 0; k <= n; ++k)
    mesh.soup.add_vertex({double(k), double(k % 7), 1});
  for (int k = 1; k <= n; ++k)
    mesh.soup.add_polygon({0, Index(k), Index(k + 1)});
  return mesh;
}

TEST(Format3mfPackage, deflated_part_in_place_is_what_libzip_copies_out) {
  // Written by lib3mf: sizes and offsets in zip64 extra fields, a zip64 end record.
  const std::string lib3mf = scratch("lib3mf.3mf");
  write_mesh(lib3mf, fan(5000));
  const std::vector<unsigned char> written = file_bytes(lib3mf);
  std::remove(lib3mf.c_str());
  ASSERT_GT(written.size(), 1000u);
  EXPECT_EQ(in_place_against_copy(written), 1);

  // Written by libzip: plain records, the model part third, an archive comment.
  const std::string plain = scratch("libzip.3mf");
  const std::string rels =
      R"(<?xml version="1.0" encoding="UTF-8"?>)"
      R"(<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
      R"(<Relationship Target="/3D/3dmodel.model" Id="rel0" )"
      R"(Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>)";
  std::string model = "<model>";
  for (int k = 0; k < 3000; ++k)
    model += "<vertex x=\"" + std::to_string(k) + "\" y=\"1\" z=\"2\"/>";
  model += "</model>";
  int error = 0;
  zip_t* archive = zip_open(plain.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(archive, nullptr);
  for (const auto& [name, text] : std::vector<std::pair<const char*, const std::string*>>{
           {"[Content_Types].xml", &rels}, {"_rels/.rels", &rels}, {"3D/3dmodel.model", &model}}) {
    zip_source_t* source = zip_source_buffer(archive, text->data(), text->size(), 0);
    ASSERT_GE(zip_file_add(archive, name, source, ZIP_FL_ENC_UTF_8), 0);
  }
  ASSERT_EQ(zip_set_archive_comment(archive, "a comment", 9), 0);
  ASSERT_EQ(zip_close(archive), 0);
  const std::vector<unsigned char> zipped = file_bytes(plain);
  std::remove(plain.c_str());
  EXPECT_EQ(in_place_against_copy(zipped), 1);

  // Every byte of the records after the model part's data damaged in turn: the same bytes or
  // none (libzip's copy then), never others, and no read past the package.
  for (const std::vector<unsigned char>* package : {&written, &zipped}) {
    int same = 0, refused = 0;
    for (std::size_t at = package->size() - 400; at < package->size(); ++at) {
      std::vector<unsigned char> damaged = *package;
      damaged[at] ^= 0x5a;
      const int outcome = in_place_against_copy(damaged);
      EXPECT_NE(outcome, -1) << "byte " << at;
      same += outcome == 1;
      refused += outcome == -2;
    }
    EXPECT_GT(same, 0);     // bytes neither reads (times, attributes, other parts)
    EXPECT_GT(refused, 0);  // signatures, offsets, names: libzip refuses the package
  }
}

}  // namespace
}  // namespace meshbridge::detail
