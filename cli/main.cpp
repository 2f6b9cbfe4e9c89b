// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge: check, compare, repair and picture non-manifold polygon meshes.

#include "arguments.h"
#include "commands.h"

#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: meshbridge <command> [options]\n"
    "\n"
    "commands:\n"
    "  check FILE [--json]             report singular edges/vertices, boundaries and other\n"
    "                                  defects; exit 0 = none, 1 = defects found, 2 = error\n"
    "  compare FILE [--json]           OpenMesh's stock loader next to the bridged build\n"
    "  repair IN OUT [options]         lossless manifold repair; OUT is .obj/.off/.ply/.stl\n"
    "      --report FILE.json          write the repair report as JSON\n"
    "      --pairing geometric|combinatorial   (default geometric)\n"
    "      --no-orient --no-stitch --cut-nonorientable\n"
    "      --remove-duplicates --remove-degenerate --remove-isolated\n"
    "      --separate EPS              move split vertex copies EPS into their own fan so the\n"
    "                                  repair survives STL's welding by position\n"
    "  batch INDIR OUTDIR [--format obj|off|ply|stl] [--json] [--quiet]\n"
    "                                  repair every mesh below INDIR into OUTDIR (same relative\n"
    "                                  paths), progress on stderr, a summary table on stdout;\n"
    "                                  exit 0 = all repaired, 2 = some failed\n"
    "  snapshot FILE OUT.png [--size N] [--view iso|x|y|z]\n"
    "                                  PNG picture of the defects (drawn with Qt, no display\n"
    "                                  needed): edges grey, boundary green, singular edges and\n"
    "                                  vertices red; N pixels square (default 800), view\n"
    "                                  iso (default) or along an axis; exit codes as check\n"
    "\n"
    "formats: OBJ, OFF, PLY, STL (read and written through OpenMesh)\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace meshbridge::cli;
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    std::cout << kUsage;
    return argc < 2 ? kError : kOk;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "check")
      return check_command(args);
    if (command == "compare")
      return compare_command(args);
    if (command == "repair")
      return repair_command(args);
    if (command == "batch")
      return batch_command(args);
    if (command == "snapshot")
      return snapshot_command(args);
    std::cerr << "meshbridge: unknown command '" << command << "' (try meshbridge --help)\n";
    return kError;
  } catch (const std::bad_alloc&) {
    std::cerr << "meshbridge: error: out of memory\n";
  } catch (const std::exception& error) {
    std::cerr << "meshbridge: error: " << error.what() << "\n";
  }
  return kError;
}
