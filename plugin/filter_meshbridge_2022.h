// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file filter_meshbridge_2022.h
//! MeshLab >= 2022 filter plugin (FilterPlugin, common/plugins/interfaces/filter_plugin.h; built
//! and tested against MeshLab 2025.07): the API glue around filter_catalog.h and
//! filter_actions.h. The MeshLab 2020.09 glue is filter_meshbridge.h.
//!
//! For pymeshlab (`pymeshlab.load_plugin(path)`) the filters are
//!   compute_singular_defects_bridged(select_faces=True, color_faces=False)
//!   meshing_repair_singular_defects_bridged(pairing=0, orient=True, stitch=True,
//!       cut_nonorientable=False, remove_duplicate_faces=False, remove_degenerate_faces=False,
//!       remove_isolated_vertices=False, recompute_normals=True)
//! and apply_filter returns their counts as a dict (keys: DetectOutcome::counts,
//! RepairOutcome::counts in filter_actions.h; ints, and bools for flags). Errors are thrown as
//! MLException, which pymeshlab raises as PyMeshLabException.
//!
//! MeshLab loads a plugin only if it was compiled with the same MESHLAB_VERSION (first six
//! characters) and MESHLAB_SCALAR as MeshLab itself; plugin/cmake/MeshLabSDK.cmake takes both
//! from the installed MeshLab.

#include <common/plugins/interfaces/filter_plugin.h>

#include <QObject>

#include <string>

class FilterMeshBridgePlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  //! Filter IDs (MeshLab convention: FP_ + what it does), in meshlab::all_filters() order.
  enum { FP_DETECT_SINGULAR_DEFECTS, FP_REPAIR_SINGULAR_DEFECTS };

  FilterMeshBridgePlugin();
  ~FilterMeshBridgePlugin() override;

  QString pluginName() const override;
  QString vendor() const override;
  using FilterPlugin::filterInfo;
  using FilterPlugin::filterName;
  using FilterPlugin::pythonFilterName;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  int getRequirements(const QAction* action) override;
  int getPreConditions(const QAction* action) const override;
  int postCondition(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  using FilterPlugin::initParameterList;
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
  std::map<std::string, QVariant> applyFilter(const QAction* action,
                                              const RichParameterList& params, MeshDocument& md,
                                              unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;

 private:
  void log_lines(const std::string& text);  //!< html_log_lines(), one log() each
};
