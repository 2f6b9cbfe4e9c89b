// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file filter_meshbridge.h
//! MeshLab 2020.09 filter plugin (MeshFilterInterface): the API glue around filter_catalog.h and
//! filter_actions.h. The MeshLab >= 2022 glue is filter_meshbridge_2022.h.

#include <common/interfaces.h>

#include <QObject>

#include <string>

class FilterMeshBridgePlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID MESH_FILTER_INTERFACE_IID FILE "filter_meshbridge.json")
  Q_INTERFACES(MeshFilterInterface)

 public:
  //! Filter IDs (MeshLab convention: FP_ + what it does), in meshlab::all_filters() order.
  enum { FP_DETECT_SINGULAR_DEFECTS, FP_REPAIR_SINGULAR_DEFECTS };

  FilterMeshBridgePlugin();
  ~FilterMeshBridgePlugin() override;

  QString pluginName() const override;
  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  int getRequirements(QAction* action) override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  FILTER_ARITY filterArity(QAction* action) const override;
  using MeshFilterInterface::initParameterSet;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& params) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& params,
                   vcg::CallBackPos* cb) override;

 private:
  void detect(MeshDocument& md, const RichParameterList& params);
  void repair(MeshDocument& md, const RichParameterList& params);
  void log_lines(const std::string& text);  //!< html_log_lines(), one Log() each
};
