// SPDX-License-Identifier: GPL-3.0-or-later
//! \file abi_mismatch_plugin.cpp
//! A MeshLab >= 2022 filter plugin that does nothing, compiled with a MESHLAB_VERSION or a
//! MESHLAB_SCALAR other than the installed MeshLab's (tests/meshlab2025/CMakeLists.txt): what a
//! user sees when a plugin was built for another pymeshlab (test_pymeshlab.py). MeshLab reads
//! both from getMLVersion(), which MESHLAB_PLUGIN_IID_EXPORTER compiles into every plugin.

#include <common/plugins/interfaces/filter_plugin.h>

#include <QAction>
#include <QObject>

class AbiMismatchPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  AbiMismatchPlugin() {
    typeList = {0};
    actionList.push_back(new QAction(filterName(0), this));
  }
  QString pluginName() const override { return "AbiMismatch"; }
  using FilterPlugin::filterInfo;
  using FilterPlugin::filterName;
  using FilterPlugin::pythonFilterName;
  QString filterName(ActionIDType) const override { return "ABI mismatch"; }
  QString pythonFilterName(ActionIDType) const override { return "abi_mismatch"; }
  QString filterInfo(ActionIDType) const override { return "Does nothing."; }
  FilterArity filterArity(const QAction*) const override { return NONE; }
  std::map<std::string, QVariant> applyFilter(const QAction*, const RichParameterList&,
                                              MeshDocument&, unsigned int&,
                                              vcg::CallBackPos*) override {
    return {};
  }
};

#include "abi_mismatch_plugin.moc"
