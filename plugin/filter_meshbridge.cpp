// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_meshbridge.h"

#include "filter_actions.h"
#include "filter_catalog.h"
#include "meshlab_document_host.h"
#include "rich_parameters.h"

#include <algorithm>
#include <exception>
#include <string>

namespace mbm = meshbridge::meshlab;

namespace {

mbm::FilterId filter_id(MeshFilterInterface::FilterIDType filter) {
  return filter == FilterMeshBridgePlugin::FP_REPAIR_SINGULAR_DEFECTS ? mbm::FilterId::repair
                                                                      : mbm::FilterId::detect;
}

}  // namespace

FilterMeshBridgePlugin::FilterMeshBridgePlugin() {
  typeList << FP_DETECT_SINGULAR_DEFECTS << FP_REPAIR_SINGULAR_DEFECTS;
  for (FilterIDType id : types())
    actionList << new QAction(filterName(id), this);
}

FilterMeshBridgePlugin::~FilterMeshBridgePlugin() = default;  // actions are QObject children

QString FilterMeshBridgePlugin::pluginName() const {
  return "FilterMeshBridge";
}

QString FilterMeshBridgePlugin::filterName(FilterIDType filter) const {
  return mbm::filter_text(filter_id(filter)).name;
}

QString FilterMeshBridgePlugin::filterInfo(FilterIDType filter) const {
  return mbm::filter_text(filter_id(filter)).info;
}

MeshFilterInterface::FilterClass FilterMeshBridgePlugin::getClass(QAction*) {
  return MeshFilterInterface::Cleaning;
}

int FilterMeshBridgePlugin::getRequirements(QAction*) {
  return MeshModel::MM_NONE;
}

int FilterMeshBridgePlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterMeshBridgePlugin::postCondition(QAction* action) const {
  return mbm::changed_data_mask(filter_id(ID(action)));
}

MeshFilterInterface::FILTER_ARITY FilterMeshBridgePlugin::filterArity(QAction*) const {
  return SINGLE_MESH;
}

void FilterMeshBridgePlugin::initParameterSet(QAction* action, MeshModel& m,
                                              RichParameterList& params) {
  // Lengths are shown as a distance and as a percentage of this diagonal.
  const float diagonal = m.cm.bbox.IsNull() || !(m.cm.bbox.Diag() > 0) ? 1.0f : m.cm.bbox.Diag();
  mbm::add_rich_parameters<RichAbsPerc>(filter_id(ID(action)), std::size_t(std::max(m.cm.fn, 0)),
                                        diagonal, params);
}

bool FilterMeshBridgePlugin::applyFilter(QAction* action, MeshDocument& md,
                                         const RichParameterList& params, vcg::CallBackPos*) {
  errorMessage.clear();
  if (md.mm() == nullptr) {
    errorMessage = "No current layer: open a mesh first.";
  } else {
    try {
      switch (ID(action)) {
        case FP_DETECT_SINGULAR_DEFECTS:
          detect(md, params);
          break;
        case FP_REPAIR_SINGULAR_DEFECTS:
          repair(md, params);
          break;
        default:
          errorMessage = "Unknown MeshBridge filter";
          break;
      }
    } catch (const mbm::FilterInputError& e) {
      errorMessage = e.what();
    } catch (const std::exception& e) {
      errorMessage = QString("%1 failed: %2").arg(filterName(action)).arg(e.what());
    }
  }
  if (errorMessage.isEmpty())
    return true;
  // meshlabserver prints the log but not errorMessage: put the reason in both.
  Log(GLLogStream::WARNING, errorMessage.toStdString());
  return false;
}

void FilterMeshBridgePlugin::log_lines(const std::string& text) {
  // MeshLab's log is rich text and breaks lines between entries only: one entry per line.
  for (const std::string& line : mbm::html_log_lines(text))
    Log(line);
}

void FilterMeshBridgePlugin::detect(MeshDocument& md, const RichParameterList& params) {
  MeshModel& m = *md.mm();
  mbm::MeshDocumentHost host(md, false);  // MeshLab 2020.09 has no 3MF exporter
  const mbm::DetectOutcome out = mbm::detect_singular_defects(
      m.cm, m.label().toStdString(), mbm::detect_options(params, std::size_t(m.cm.fn)), host);
  log_lines(out.log);
}

void FilterMeshBridgePlugin::repair(MeshDocument& md, const RichParameterList& params) {
  MeshModel& m = *md.mm();
  mbm::MeshDocumentHost host(md, false);
  const mbm::RepairOutcome out = mbm::repair_singular_defects(m.cm, m.label().toStdString(),
                                                              mbm::repair_options(params), host);
  m.setMeshModified(true);
  log_lines(out.log);
}
