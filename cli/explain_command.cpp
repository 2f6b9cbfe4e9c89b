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
  std::vector<const char*> aliases;  //!< other words the reports use for it (matched as `term`)
};

// Keep in step with docs/cli.md "What the reports mean".
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
    {"midpoint",
     "'N edges split at the midpoint' (check: 'split N edges at the midpoint'). Where two pairs\n"
     "of faces, or a pair and a cut side, would end up on one edge of the result (the faces\n"
     "around a vertex pass the same neighbour twice: a fan winding twice around it, or both\n"
     "layers of a sheet written once per side), and cutting would open what was closed, repair\n"
     "keeps the pair and adds a new vertex in the middle of its edge, so the two sheets touch\n"
     "there without sharing an edge. Each split adds one vertex and gives the pair's two faces\n"
     "one corner more: 'M triangles became quads' (a triangle given a midpoint is a quad, still\n"
     "flat).",
     {"edges split at the midpoint", "split at the midpoint", "midpoint split"}},
    {"paired with copies",
     "Where a face is given twice (the same corners, either way round), as in a sheet written\n"
     "once for each side, and two pairs would otherwise share one edge of the result, the\n"
     "sides of the two copies are glued to each other back to back, and their former partners\n"
     "to each other, instead of being cut: no edge is opened (copies glued so all round close\n"
     "into a flat pillow of no volume, as a slicer sees them). 'N paired with copies' counts\n"
     "sides, 4 per exchange.",
     {"copies glued back to back"}},
    {"stitched",
     "Sides that were cut open (left without a partner) glued back together in pairs on their\n"
     "edge where the result stays consistently oriented and manifold, flipping a smaller piece\n"
     "if that makes them run opposite ways (not with --no-orient). 'N stitched' counts sides.\n"
     "--no-stitch: never.",
     {"stitch"}},
    {"fan",
     "The faces around a vertex that are connected to each other across its edges (also called\n"
     "an umbrella). A manifold vertex has exactly one fan. Repair gives each extra fan its own\n"
     "copy of the vertex: 'copies from split fans' in the repair report ('make N vertex\n"
     "copies (split fans)' in check's forecast). The copies sit at the same position; each\n"
     "fan's faces use their own one, so the vertex is no longer singular.",
     {"vertex copies", "vertex copy", "split fans", "copies from split fans"}},
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
     "and an outside (what 3D printing needs); faces consistently oriented too. Reports say\n"
     "'watertight yes' or 'watertight no' (repair on its 'after:' line, for the output)."},
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
     "counting them)': in the input each copy is a face of its own on edges it adds nothing to.",
     {"topology", "topology changed", "V - E + F"}},
    {"stacked face copies",
     "Faces with the same corners as an earlier face of the same piece (either way round),\n"
     "lying on the corners of that face: a hull or sheet written twice over. Repair keeps every\n"
     "copy; pairing makes each one a face of the output's surface, glued to its neighbours like\n"
     "any other (see 'paired with copies'). The topology line lists such pieces apart, 'by\n"
     "pairing stacked face copies', and counts each face once in the Euler characteristic\n"
     "before repair, since in the input a copy adds a face but no edge or vertex.",
     {"stacked copies", "stacked face copy"}},
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
    {"nested shell",
     "A closed shell inside another closed shell and wound the same way as it (its faces\n"
     "facing the same way, outward). The file does not say what it is: an insert (a part of an\n"
     "assembly placed inside another, solid) or a cavity whose faces were written the wrong\n"
     "way round (a void). By default repair keeps it as written, solid ('left as written';\n"
     "check: 'repair keeps them as written'); --nested-shells cavity makes it a void, its faces\n"
     "turned toward the void. Counted either way ('nested shells: N').",
     {"nested shells", "ambiguous nested shell"}},
    {"set aside",
     "Faces with fewer than 3 distinct corners (e.g. 'f 1 1 2'): they have no area and no\n"
     "edges to join, so repair keeps them out of the surface and counts them."},
    {"gaps",
     "Cracks left by rounding, closed before pairing: welds (near vertices merged) and\n"
     "T-junction closings together (see 'weld' and 'T-junction'). 'gaps (tolerance T)' gives the\n"
     "largest tolerance used. 'gaps kept open': near pairs left apart because closing them\n"
     "would move a vertex by more than a quarter of the shortest edge there (a feature, not a\n"
     "crack). 'gaps refused': all of them undone, because the repaired mesh would not have\n"
     "fewer open edges with them, or would have more non-orientable components.\n"
     "--weld 0 turns gap closing off.",
     {"gap", "gap closing", "gaps kept open", "gaps refused"}},
    {"weld",
     "Merging two boundary vertices (ends of open edges) that lie closer than the tolerance:\n"
     "the copies of one corner that a CAD export left a rounding error apart. With --weld auto\n"
     "(the default) each vertex has its own tolerance: 2^-21 (about 5e-7) times the size of its\n"
     "part, and in a file of 32-bit coordinates (STL, 3MF, float PLY) at least 2^-21 times the\n"
     "vertex's largest coordinate; --weld TOL gives one distance in model units. A weld never\n"
     "merges two corners of one polygon ('refused: same polygon') or moves a vertex more than a\n"
     "quarter of the shortest edge at it, and all welds are undone when they would not make the\n"
     "result better (see 'gaps'). Vertices at exactly the same position are never welded.",
     {"welds", "welded", "welding"}},
    {"T-junction",
     "A crack where one long open edge runs along two shorter open edges on the other side,\n"
     "their shared vertex lying on the long edge (within the weld tolerance). Closing it splits\n"
     "the long edge at that vertex (its face gets a corner more), so the two sides pair up:\n"
     "'N T-junctions closed (M sides split)'. Kept, refused or left open as welds are (see\n"
     "'gaps').",
     {"T-junctions", "T-junction closing", "T-junction crack"}},
    {"pinched polygon",
     "A polygon that passes twice through the same vertex (like a figure 8). Repair splits it\n"
     "into simple polygons: 'N split into M more' means N polygons became N + M (check: 'split\n"
     "N pinched polygons into K pieces'). A keyhole polygon is cut into triangles instead (see\n"
     "there; it is counted here too).",
     {"split", "pinched polygons"}},
    {"keyhole polygon",
     "A polygon that is an outline and holes joined by slits: it runs a-b and later b-a. Repair\n"
     "cuts it into triangles as one polygon with holes, the holes left open, so no triangle\n"
     "overlaps another ('keyhole polygon triangulated, holes left open'). A slit that leads to\n"
     "no hole of the outline is set aside ('keyhole slit set aside').",
     {"keyhole", "keyhole slit"}},
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
     "Only in `compare`: faces that OpenMesh's stock loader could not attach to their\n"
     "neighbours (a singular edge or vertex) and added on copies of their vertices, cut loose\n"
     "from the rest ('faces detached'). MeshBridge's column is always 0: it never detaches a\n"
     "face. Repair does not report it."},
};

std::string lower(std::string text) {
  for (char& ch : text)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return text;
}

// The entry's term and aliases, lower case.
std::vector<std::string> names_of(const Entry& entry) {
  std::vector<std::string> names{lower(entry.term)};
  for (const char* alias : entry.aliases)
    names.push_back(lower(alias));
  return names;
}

// Whether `topic` names the entry exactly (exact) or one contains the other (!exact).
bool matches(const Entry& entry, const std::string& topic, bool exact) {
  for (const std::string& name : names_of(entry)) {
    if (exact ? name == topic
              : name.find(topic) != std::string::npos || topic.find(name) != std::string::npos)
      return true;
  }
  return false;
}

int run_explain(const std::vector<std::string>& words) {
  std::string topic;
  for (const std::string& word : words)
    topic += (topic.empty() ? "" : " ") + lower(word);
  // A topic that is a term or alias prints that entry only ("sides cut", not also "side");
  // any other prints every entry whose names contain it or that it contains ("copies").
  const bool exact = std::any_of(kEntries.begin(), kEntries.end(),
                                 [&](const Entry& entry) { return matches(entry, topic, true); });
  bool found = false;
  for (const Entry& entry : kEntries) {
    if (!topic.empty() && !matches(entry, topic, exact))
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
  command->add_option("TOPIC", *words, "a term, e.g. contender, fan, 'sides cut', midpoint");
  command->callback([words, &exit_code] { exit_code = run_explain(*words); });
}

}  // namespace meshbridge::cli
