// SPDX-License-Identifier: GPL-3.0-or-later
// `meshbridge explain [TOPIC]`: the words and notation of the reports, in plain words.

#include "commands.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace meshbridge::cli {

namespace {

struct Entry {
  const char* term;
  const char* text;
};

// Keep in step with README.md "What the reports mean".
const std::vector<Entry> kEntries = {
    {"manifold",
     "A surface is manifold when every edge has at most two faces (one on each side) and the\n"
     "faces around every vertex form a single fan. Most tools (OpenMesh, slicers, booleans)\n"
     "need this; MeshBridge's repair always produces it and never deletes a face to get it."},
    {"singular edge",
     "An edge shared by three or more faces, like the spine of a book with three pages.\n"
     "`check` lists them as [3-7 (4 faces)]: the edge between vertices 3 and 7 (vertex numbers\n"
     "count from 0 in file order), with 4 faces on it. Two cubes glued at one edge give one\n"
     "singular edge with 4 faces."},
    {"contender",
     "One face on a singular edge, seen as a candidate to pair with another face across that\n"
     "edge. The faces counted after a singular edge, 3-7 (4 faces), are its contenders.\n"
     "Repair pairs contenders two by two (by angle around the edge with --pairing geometric,\n"
     "by face order with --pairing combinatorial); each pair becomes one manifold edge."},
    {"side",
     "A contender's half of an edge. A side that finds no partner is 'cut': it becomes a\n"
     "boundary edge of its own (an odd number of faces on an edge always leaves one cut)."},
    {"sides cut",
     "Contenders left without a partner, so the edge is opened into boundary there.\n"
     "  cut on singular edges: left over by pairing (e.g. the third page of a book)\n"
     "  cut for orientation: pairing them would force two faces to face opposite ways\n"
     "  cut to stay manifold: always 0 now. Where a fan winds twice around a vertex and two\n"
     "    pairs would share one edge, they are glued again in their new fans, or one pair gets a\n"
     "    new vertex in the middle of the edge ('edges split at the midpoint'), so the two\n"
     "    sheets touch without sharing it and nothing closed is opened; each adds a vertex and\n"
     "    gives the pair's two faces a corner more (a triangle becomes a quad)\n"
     "  paired with copies instead: where a face is given twice (a sheet written once per side),\n"
     "    the two copies are glued back to back (a closed pillow of no volume) instead of cut\n"
     "  stitched: cut sides glued back in pairs where that stays manifold (--no-stitch: never)"},
    {"fan",
     "The faces around a vertex that are connected to each other across its edges (also called\n"
     "an umbrella). A manifold vertex has exactly one fan. Repair gives each extra fan its own\n"
     "copy of the vertex: 'copies from split fans' in the repair report."},
    {"pinch vertex",
     "A vertex where two or more fans touch in one point only, like the waist of an hourglass\n"
     "(two cones tip to tip), with no singular edge there. Repair splits it into one copy per\n"
     "fan."},
    {"singular vertex",
     "A vertex that is not manifold: either an end of a singular edge ('singular vertices on\n"
     "singular edges') or a pinch vertex."},
    {"boundary edge",
     "An edge with exactly one face: the rim of a hole or an open sheet. 'boundary loops'\n"
     "counts the closed rims. A closed (watertight) surface has none."},
    {"filled hole",
     "With --fill-holes [MAX_EDGES], repair closes each boundary loop of at most MAX_EDGES\n"
     "edges (32 without a number) with new triangles between the loop's own vertices, running\n"
     "the same way as the faces around it. They come after every original face and have no\n"
     "original (no colour of their own). 'left open': loops longer than MAX_EDGES, or ones\n"
     "that no valid patch closes."},
    {"watertight",
     "No boundary edge and no singular edge or vertex: the surface closes up with an inside\n"
     "and an outside (what 3D printing needs). The repair report calls this 'closed'."},
    {"component",
     "A piece of the mesh whose faces are connected across edges. `check` connects through\n"
     "singular edges too, so two cubes on one edge are 1 component before repair and 2 after."},
    {"Euler characteristic",
     "vertices - edges + faces. 2 for each closed sphere-like piece, 0 for a torus; a quick\n"
     "sanity number, not a defect. 'N component's topology changed by pairing: Euler\n"
     "characteristic 2 -> -2': a piece of the result whose number differs from that of the\n"
     "same faces in the input (each vertex and edge counted once, a singular edge too), because\n"
     "pairing joined two sheets at a singular edge into a handle, or sides were cut or a vertex\n"
     "split within the piece. Pieces that pairing separates keep theirs. A piece where sides\n"
     "were cut for orientation (a Moebius strip cut open: 0 -> 1) is listed apart: 'changed\n"
     "where sides were cut for orientation'. Pieces holding stacked face copies (faces on the\n"
     "corners of another, as in a hull written twice) are listed apart too, 'by pairing stacked\n"
     "face copies', with each face counted once: '4 -> -8 (2194 faces, 484 of them copies: 488\n"
     "counting them)': in the input each copy is a face of its own on edges it adds nothing to."},
    {"inconsistently oriented edge",
     "An edge whose two faces run through it in the same direction, so one of them faces the\n"
     "wrong way. Repair flips faces to fix it ('flipped') unless --no-orient."},
    {"non-orientable component",
     "A piece with no consistent inside and outside, such as a Moebius strip. By default\n"
     "repair keeps its faces' directions and cuts each edge whose two faces run through it the\n"
     "same way. With --cut-nonorientable its faces take the orientation of a breadth-first\n"
     "spanning tree over the pairs, and the edges that disagree with it are cut. Either way\n"
     "the cut makes the piece orientable, but it is not necessarily the fewest edges.\n"
     "('cut for orientation' in the report.)"},
    {"set aside",
     "Faces with fewer than 3 distinct corners (e.g. 'f 1 1 2'): they have no area and no\n"
     "edges to join, so repair keeps them out of the surface and counts them."},
    {"split",
     "A pinched polygon (one that passes twice through the same vertex) is split into simple\n"
     "polygons: 'N split into M more' means N polygons became N + M. A keyhole polygon (an\n"
     "outline and holes joined by slits: it runs a-b and later b-a) is cut into triangles as\n"
     "one polygon with holes, the holes left open ('keyhole polygon triangulated')."},
    {"degenerate face",
     "A face that repeats a vertex index, not a keyhole polygon (counted as one, and\n"
     "triangulated). --remove-degenerate drops them."},
    {"zero-area face", "A face whose corners lie on one line or one point (area 0)."},
    {"duplicate face",
     "A face whose vertex set an earlier face already has. --remove-duplicates drops them."},
    {"isolated vertex",
     "A vertex no face uses. Listed, not a defect (check can exit 0): repair keeps them; "
     "--remove-isolated drops them."},
    {"self-intersection",
     "Two faces that cross each other, or overlap when they lie in one plane: shells of an\n"
     "assembly pushed into each other, or a fold. `check --self-intersections` counts the\n"
     "face pairs [f0-f1], the faces in them, and the pairs of components (shells) that cross.\n"
     "Faces that only touch at a vertex or an edge they share (compared by position, so the\n"
     "copies repair splits count as shared) are not counted. Repair does not resolve them.\n"
     "Shown violet: `snapshot --self-intersections` and MeshLab's Detect."},
    {"detached",
     "Last resort: faces cut loose (given their own vertices) because OpenMesh could not\n"
     "represent them otherwise. Normally 0."},
};

std::string lower(std::string text) {
  for (char& ch : text)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return text;
}

int run_explain(const std::vector<std::string>& words) {
  std::string topic;
  for (const std::string& word : words)
    topic += (topic.empty() ? "" : " ") + lower(word);
  bool found = false;
  for (const Entry& entry : kEntries) {
    const std::string term = lower(entry.term);
    if (!topic.empty() && term.find(topic) == std::string::npos &&
        topic.find(term) == std::string::npos)
      continue;
    std::cout << entry.term << "\n";
    std::string text = entry.text;
    std::size_t start = 0;
    while (start < text.size()) {  // indent every line by two spaces
      const std::size_t end = std::min(text.find('\n', start), text.size());
      std::cout << "  " << text.substr(start, end - start) << "\n";
      start = end + 1;
    }
    std::cout << "\n";
    found = true;
  }
  if (!found) {
    std::string terms;
    for (const Entry& entry : kEntries)
      terms += std::string(terms.empty() ? "" : ", ") + entry.term;
    throw UsageError("no entry for '" + topic + "'; known terms: " + terms);
  }
  return kOk;
}

}  // namespace

void add_explain_command(CLI::App& app, int& exit_code) {
  auto words = std::make_shared<std::vector<std::string>>();
  CLI::App* command = app.add_subcommand(
      "explain",
      "Tell what the words and notation in the reports mean (all terms, or those matching "
      "TOPIC).");
  command->add_option("TOPIC", *words, "a term, e.g. contender, fan, 'sides cut'");
  command->callback([words, &exit_code] { exit_code = run_explain(*words); });
}

}  // namespace meshbridge::cli
