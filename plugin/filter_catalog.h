// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file filter_catalog.h
//! What the MeshBridge filters are called and what they take: names, python names, descriptions
//! and parameters, shared by every MeshLab adapter (2020.09's MeshFilterInterface and 2022+'s
//! FilterPlugin). Knows neither Qt nor MeshLab; each adapter turns these specs into its own
//! RichParameters and reads the values back with the option readers at the end.
//!
//! Python names (pymeshlab, MeshLab >= 2022): filter and parameter names below are the ones a
//! script passes to `MeshSet.apply_filter`; parameter names are already snake_case, so MeshLab's
//! own python-name rule leaves them unchanged.

#include "filter_actions.h"

#include <string>
#include <vector>

namespace meshbridge::meshlab {

//! The filters, in menu order.
enum class FilterId {
  detect,  //!< "Detect Singular Defects (Bridged Half-Edge)", compute_singular_defects_bridged
  repair,  //!< "Repair Singular Defects (Bridged Half-Edge)",
           //!< meshing_repair_singular_defects_bridged
};

//! Both filters, in menu order.
const std::vector<FilterId>& all_filters();

//! Names and documentation of one filter.
struct FilterText {
  const char* name;         //!< menu and .mlx name
  const char* python_name;  //!< pymeshlab name (MeshLab >= 2022)
  const char* info;         //!< HTML help shown by MeshLab
};
const FilterText& filter_text(FilterId id);

//! Parameter names (also their python names).
namespace parameter {
inline constexpr const char* select_faces = "select_faces";
inline constexpr const char* color_faces = "color_faces";
inline constexpr const char* defect_layer = "defect_layer";
inline constexpr const char* pairing = "pairing";
inline constexpr const char* orient = "orient";
inline constexpr const char* stitch = "stitch";
inline constexpr const char* cut_nonorientable = "cut_nonorientable";
inline constexpr const char* remove_duplicate_faces = "remove_duplicate_faces";
inline constexpr const char* remove_degenerate_faces = "remove_degenerate_faces";
inline constexpr const char* remove_isolated_vertices = "remove_isolated_vertices";
inline constexpr const char* recompute_normals = "recompute_normals";
//! Gap closing (both filters): CloseGapsOptions::tolerance and ::close_t_junctions, the CLI's
//! `--weld TOL|auto|0`.
inline constexpr const char* weld_tolerance = "weld_tolerance";
inline constexpr const char* close_t_junctions = "close_t_junctions";
//! Hole filling (Repair only): FillHolesOptions::max_edges, the CLI's `--fill-holes N`; 0 = off.
inline constexpr const char* fill_holes = "fill_holes";
//! Detect only: DetectOptions::self_intersections, the CLI's `--self-intersections`; its default
//! depends on the mesh (self_intersections_by_default()).
inline constexpr const char* self_intersections = "self_intersections";
}  // namespace parameter

//! One parameter of a filter, of one of four kinds; only the default of its kind is read.
struct ParameterSpec {
  enum class Kind {
    boolean,      //!< RichBool
    enumeration,  //!< RichEnum: an index into `enum_values`
    integer,      //!< RichInt
    //! A real number, a distance in the mesh's units: RichAbsPerc (2020.09) / RichPercentage
    //! (>= 2022), which MeshLab shows both as a distance and as a percentage of the current
    //! mesh's bounding box diagonal (0 .. diagonal); pymeshlab takes PureValue(d) or
    //! PercentageValue(p). Negative values are allowed (below 0 the percentage goes negative).
    length,
  };
  Kind kind = Kind::boolean;
  const char* name = "";  //!< see namespace parameter
  bool bool_default = false;
  int enum_default = 0;
  std::vector<const char*> enum_values;  //!< labels, index = value
  int int_default = 0;
  double length_default = 0;  //!< in the mesh's units, whatever its size
  const char* label = "";     //!< the dialog's label
  std::string tooltip;
};

//! Builders of one ParameterSpec each, for the catalogue (and for parameters still to come).
ParameterSpec boolean_parameter(const char* name, bool default_value, const char* label,
                                std::string tooltip);
ParameterSpec integer_parameter(const char* name, int default_value, const char* label,
                                std::string tooltip);
ParameterSpec length_parameter(const char* name, double default_value, const char* label,
                               std::string tooltip);

//! The parameters of `id`, in dialog order. Defaults are DetectOptions{}'s and
//! RepairFilterOptions{}'s (so the core's RepairOptions{} for the core's options), except
//! Detect's `self_intersections`, whose default here is on (see the overload below).
const std::vector<ParameterSpec>& parameters(FilterId id);

//! The parameters of `id` for a mesh of `faces` faces: as parameters(id), with Detect's
//! `self_intersections` defaulting to self_intersections_by_default(faces).
std::vector<ParameterSpec> parameters(FilterId id, std::size_t faces);

//! The gap closing options of a `weld_tolerance` value: negative means automatic
//! (kAutoWeldTolerance), 0 off, anything else the distance itself.
CloseGapsOptions close_gaps_options(double weld_tolerance, bool close_t_junctions);

//! The FillHolesOptions::max_edges of a `fill_holes` value: 0 or negative means off.
std::size_t fill_holes_max_edges(int fill_holes);

//! Reads the gap closing parameters of either filter (getAbsPerc, getBool). A list without them
//! takes the core's defaults (automatic tolerance, T-junctions closed); MeshLab itself always
//! passes them (meshlabserver 2020.09 refuses a script that lacks one).
template <class ParameterList>
CloseGapsOptions close_gaps_options(const ParameterList& params) {
  const CloseGapsOptions defaults;
  const double tolerance = params.hasParameter(parameter::weld_tolerance)
                               ? double(params.getAbsPerc(parameter::weld_tolerance))
                               : defaults.tolerance;
  const bool t_junctions = params.hasParameter(parameter::close_t_junctions)
                               ? params.getBool(parameter::close_t_junctions)
                               : defaults.close_t_junctions;
  return close_gaps_options(tolerance, t_junctions);
}

//! Reads the detect filter's options from a MeshLab RichParameterList (either API generation:
//! both have getBool(name) and getEnum(name)), for a mesh of `faces` faces. A script that
//! predates `defect_layer` gets the default (tubes); one that predates `self_intersections`
//! gets self_intersections_by_default(faces).
template <class ParameterList>
DetectOptions detect_options(const ParameterList& params, std::size_t faces) {
  DetectOptions options;
  options.select_faces = params.getBool(parameter::select_faces);
  options.color_faces = params.getBool(parameter::color_faces);
  if (params.hasParameter(parameter::defect_layer)) {
    options.layer_form = params.getEnum(parameter::defect_layer) == 1 ? DefectLayerForm::edges
                                                                      : DefectLayerForm::tubes;
  }
  options.close_gaps = close_gaps_options(params);
  options.self_intersections = params.hasParameter(parameter::self_intersections)
                                   ? params.getBool(parameter::self_intersections)
                                   : self_intersections_by_default(faces);
  return options;
}

//! Reads the repair filter's options from a MeshLab RichParameterList (getBool, getEnum,
//! getAbsPerc, getInt). A script that predates `fill_holes` gets the default (off).
template <class ParameterList>
RepairFilterOptions repair_options(const ParameterList& params) {
  RepairFilterOptions options;
  options.core.pairing = params.getEnum(parameter::pairing) == 1 ? PairingPolicy::combinatorial
                                                                 : PairingPolicy::geometric;
  options.core.orient = params.getBool(parameter::orient);
  options.core.stitch = params.getBool(parameter::stitch);
  options.core.cut_nonorientable = params.getBool(parameter::cut_nonorientable);
  options.core.remove_duplicate_faces = params.getBool(parameter::remove_duplicate_faces);
  options.core.remove_degenerate_faces = params.getBool(parameter::remove_degenerate_faces);
  options.core.remove_isolated_vertices = params.getBool(parameter::remove_isolated_vertices);
  options.recompute_normals = params.getBool(parameter::recompute_normals);
  options.core.close_gaps = close_gaps_options(params);
  if (params.hasParameter(parameter::fill_holes))
    options.core.fill_holes.max_edges = fill_holes_max_edges(params.getInt(parameter::fill_holes));
  return options;
}

}  // namespace meshbridge::meshlab
