// SPDX-License-Identifier: GPL-3.0-or-later
#include "printer_options.h"

#include "commands.h"
#include "validators.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/fill_holes.h"
#include "meshbridge/io.h"
#include "meshbridge/separate_copies.h"
#include "meshbridge/stl_round_trip.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <ostream>
#include <sstream>

namespace meshbridge::cli {

namespace {

double parse_distance(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < 0) {
    throw UsageError("--" + option + " expects 'auto' or a distance >= 0, got '" + text + "'");
  }
  return value;
}

}  // namespace

double parse_separation(const std::string& text) {
  return text == "auto" ? kAutoSeparation : parse_distance("separate", text);
}

void add_nested_shells_option(CLI::App& command, AmbiguousNesting& nested) {
  const std::map<std::string, AmbiguousNesting> names{{"material", AmbiguousNesting::material},
                                                      {"cavity", AmbiguousNesting::cavity}};
  command
      .add_option("--nested-shells", nested,
                  "a closed shell inside another and wound the same way as it (an insert of an "
                  "assembly, or a cavity wound the wrong way) is ambiguous: material = keep it "
                  "as written, solid (default); cavity = turn it into a void")
      // The help names the words only ("TEXT:{material,cavity}=material", as --pairing), not
      // CLI11's mapping of them to the enum's values.
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case).description("{material,cavity}"))
      ->type_name("TEXT")
      ->default_str("material");
}

void add_fill_holes_option(CLI::App& command, std::string& max_edges) {
  // A flag whose bare form means kDefaultFillHolesMaxEdges ({32}), that also takes a value
  // (expected(0, 1)); the help shows no default, since the default is off. CLI11 never takes a
  // required positional (IN, OUT) for the value, so `--fill-holes in.obj out.obj` works too.
  command
      .add_flag("--fill-holes{" + std::to_string(kDefaultFillHolesMaxEdges) + "}", max_edges,
                "after the repair, close every hole (boundary loop) of at most MAX_EDGES edges "
                "with new triangles between its own vertices (CGAL's hole triangulation), "
                "oriented with the faces around it and appended after them; without a number " +
                    std::to_string(kDefaultFillHolesMaxEdges) +
                    " (the holes of a broken export, not the rims of a model open on purpose); "
                    "0 or absent = off")
      ->type_name("[MAX_EDGES]")
      ->expected(0, 1)
      ->check(CLI::Validator(
          [](std::string& text) {
            // A bare --fill-holes before IN or OUT with more options after them takes the next
            // word as its value (CLI11 only keeps the last required positionals back).
            std::string error = whole_number_in(0, 1000000)(text);
            if (!error.empty()) {
              error +=
                  " (a bare --fill-holes takes the next word as MAX_EDGES: put it after IN "
                  "and OUT, or write --fill-holes=N)";
            }
            return error;
          },
          "INT in [0 - 1000000]"));
}

std::size_t parse_fill_holes(const std::string& text) {
  return text.empty() ? 0 : static_cast<std::size_t>(std::stoul(text));  // validated: 0..10^6
}

CloseGapsOptions parse_weld(const std::string& text) {
  CloseGapsOptions options;
  if (text != "auto")
    options.tolerance = parse_distance("weld", text);
  return options;
}

std::string gaps_line(const CloseGapsReport& g, bool would) {
  std::ostringstream out;
  if (!(g.tolerance > 0) && g.automatic) {
    out << "gaps: none to close (no boundary edge)\n";
    return out.str();
  }
  if (!(g.tolerance > 0)) {
    out << "gaps: not closed (weld tolerance 0: --weld 0, or every coordinate is 0)\n";
    return out.str();
  }
  out << "gaps (weld tolerance " << g.tolerance << "): " << (would ? "would weld " : "welded ")
      << g.vertices_welded << " vertices (largest move " << g.largest_weld_distance << ", "
      << g.welds_refused << " refused in one polygon), " << (would ? "would close " : "closed ")
      << g.t_junctions_closed << " T-junction cracks\n";
  return out.str();
}

std::string wider_weld_hint(const Soup& soup, const CloseGapsOptions& weld,
                            const CloseGapsReport& gaps, const DefectReport& detected) {
  if (weld.tolerance >= 0 || !(gaps.tolerance > 0) || detected.boundary_edges.empty())
    return "";
  // 100x, rounded up to one significant digit (4.8e-7 -> 5e-5): still far below printable
  // detail, but it spans the cracks CAD exports leave at a coarser rounding.
  const double wide = gaps.tolerance * 100;
  const double unit = std::pow(10.0, std::floor(std::log10(wide)));
  CloseGapsOptions wider = weld;
  wider.tolerance = std::ceil(wide / unit) * unit;
  const CloseGapsReport w = preview_close_gaps(soup, wider, &detected);
  if (w.vertices_welded + w.t_junctions_closed <= gaps.vertices_welded + gaps.t_junctions_closed)
    return "";
  std::ostringstream out;
  out << "hint: " << detected.boundary_edges.size()
      << " boundary edges; cracks wider than the automatic tolerance stay open: --weld "
      << wider.tolerance << " would weld " << w.vertices_welded << " vertices (largest move "
      << w.largest_weld_distance << ") and close " << w.t_junctions_closed
      << " T-junction cracks (repair keeps them only where the result has fewer open edges)\n";
  return out.str();
}

bool is_stl_path(const std::string& path) {
  return mesh_format(path) == MeshFormat::stl;
}

std::string separation_summary(const StlSeparation& separated, std::size_t vertices_split,
                               const std::string& text, bool given, const std::string& out) {
  std::ostringstream summary;
  if (!separated.kept_reason.empty()) {
    summary << "separate: the " << vertices_split << " split vertex copies keep their positions ("
            << separated.kept_reason << ")\n";
  } else if (separated.vertices_moved > 0 && text == "auto") {
    summary << "separated the " << vertices_split << " split vertex copies for STL: moved "
            << separated.vertices_moved << " vertices by " << separated.distance
            << " (the smallest move a reader's weld by float32 position keeps apart; "
               "--separate 0 keeps positions exact)\n";
  } else if (separated.vertices_moved > 0) {
    summary << "separated the " << vertices_split << " split vertex copies: moved "
            << separated.vertices_moved << " vertices (every copy of a split vertex) by "
            << separated.distance << "\n";
  } else if (vertices_split > 0 && text == "auto" && given && !is_stl_path(out)) {
    summary << "separate: not needed for " << out << " (the format keeps shared vertices)\n";
  }
  return summary.str();
}

}  // namespace meshbridge::cli
