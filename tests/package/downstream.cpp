// SPDX-License-Identifier: GPL-3.0-or-later
// Links the installed MeshBridge core and repairs a bowtie: prints "6 2" (vertices, faces).
#include <meshbridge/repair.h>

#include <iostream>

int main() {
  meshbridge::Soup soup;
  for (double x : {0.0, 1.0, -1.0}) {
    soup.add_vertex({x, 0, 0});
    if (x != 0)
      soup.add_vertex({x, 1, 0});
  }
  soup.add_polygon({0, 1, 2});
  soup.add_polygon({0, 3, 4});
  const meshbridge::RepairResult result = meshbridge::repair(soup);
  std::cout << result.mesh.soup.num_vertices() << " " << result.mesh.soup.num_faces() << "\n";
  return 0;
}
