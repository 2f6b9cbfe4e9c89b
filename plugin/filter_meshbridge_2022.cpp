// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_meshbridge_2022.h"

#include "filter_actions.h"
#include "filter_catalog.h"
#include "meshlab_document_host.h"
#include "rich_parameters.h"

#include <common/globals.h>
#include <common/plugins/plugin_manager.h>

#include <algorithm>
#include <exception>
#include <string>

namespace mbm = meshbridge::meshlab;

namespace {

mbm::FilterId filter_id(MeshLabPlugin::ActionIDType filter) {
  return filter == FilterMeshBridgePlugin::FP_REPAIR_SINGULAR_DEFECTS ? mbm::FilterId::repair
                                                                      : mbm::FilterId::detect;
}

//! The counts as pymeshlab converts them: int, bool (flags) or double (reals) QVariants.
std::map<std::string, QVariant> result_map(const std::vector<mbm::FilterCount>& counts) {
  std::map<std::string, QVariant> result;
  using Kind = mbm::FilterCount::Kind;
  for (const mbm::FilterCount& c : counts) {
    if (c.kind == Kind::flag) {
      result[c.name] = QVariant(c.value != 0);
    } else if (c.kind == Kind::real) {
      result[c.name] = QVariant(c.real);
    } else {
      result[c.name] = QVariant(int(c.value));
    }
  }
  return result;
}

//! Whether MeshLab's plugin manager has a 3MF exporter (Debian's 2025.07 has none).
bool can_save_3mf() {
  for (const QString& format : meshlab::pluginManagerInstance().outputMeshFormatList()) {
    if (format.compare("3mf", Qt::CaseInsensitive) == 0)
      return true;
  }
  return false;
}

}  // namespace

void FilterMeshBridgePlugin::log_lines(const std::string& text) {
  // MeshLab's log is rich text: one entry per line, escaped.
  for (const std::string& line : mbm::html_log_lines(text))
    log(line);
}

FilterMeshBridgePlugin::FilterMeshBridgePlugin() {
  typeList = {FP_DETECT_SINGULAR_DEFECTS, FP_REPAIR_SINGULAR_DEFECTS};
  for (ActionIDType id : typeList)
    actionList.push_back(new QAction(filterName(id), this));
}

FilterMeshBridgePlugin::~FilterMeshBridgePlugin() = default;  // actions are QObject children

QString FilterMeshBridgePlugin::pluginName() const {
  return "FilterMeshBridge";
}

QString FilterMeshBridgePlugin::vendor() const {
  return "MeshBridge";
}

QString FilterMeshBridgePlugin::filterName(ActionIDType filter) const {
  return mbm::filter_text(filter_id(filter)).name;
}

QString FilterMeshBridgePlugin::pythonFilterName(ActionIDType filter) const {
  return mbm::filter_text(filter_id(filter)).python_name;
}

QString FilterMeshBridgePlugin::filterInfo(ActionIDType filter) const {
  return mbm::filter_text(filter_id(filter)).info;
}

FilterPlugin::FilterClass FilterMeshBridgePlugin::getClass(const QAction*) const {
  return FilterPlugin::Cleaning;
}

int FilterMeshBridgePlugin::getRequirements(const QAction*) {
  return MeshModel::MM_NONE;
}

int FilterMeshBridgePlugin::getPreConditions(const QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterMeshBridgePlugin::postCondition(const QAction* action) const {
  return mbm::changed_data_mask(filter_id(ID(action)));
}

FilterPlugin::FilterArity FilterMeshBridgePlugin::filterArity(const QAction*) const {
  return SINGLE_MESH;
}

RichParameterList FilterMeshBridgePlugin::initParameterList(const QAction* action,
                                                            const MeshModel& m) {
  // Lengths are shown as a distance and as a percentage of this diagonal.
  const Scalarm diagonal =
      m.cm.bbox.IsNull() || !(m.cm.bbox.Diag() > 0) ? Scalarm(1) : m.cm.bbox.Diag();
  RichParameterList params;
  mbm::add_rich_parameters<RichPercentage>(filter_id(ID(action)), std::size_t(std::max(m.cm.fn, 0)),
                                           diagonal, params);
  return params;
}

std::map<std::string, QVariant> FilterMeshBridgePlugin::applyFilter(const QAction* action,
                                                                    const RichParameterList& params,
                                                                    MeshDocument& md,
                                                                    unsigned int& postConditionMask,
                                                                    vcg::CallBackPos*) {
  if (md.mm() == nullptr)
    throw MLException("No current layer: open a mesh first.");
  MeshModel& m = *md.mm();
  const std::string label = m.label().toStdString();
  try {
    switch (ID(action)) {
      case FP_DETECT_SINGULAR_DEFECTS: {
        mbm::MeshDocumentHost host(md, can_save_3mf());
        const mbm::DetectOptions options = mbm::detect_options(params, std::size_t(m.cm.fn));
        const mbm::DetectOutcome out = mbm::detect_singular_defects(m.cm, label, options, host);
        log_lines(out.log);
        postConditionMask = postCondition(action);
        if (options.color_faces)
          postConditionMask |= MeshModel::MM_FACECOLOR;
        return result_map(out.counts);
      }
      case FP_REPAIR_SINGULAR_DEFECTS: {
        mbm::MeshDocumentHost host(md, can_save_3mf());
        const mbm::RepairOutcome out =
            mbm::repair_singular_defects(m.cm, label, mbm::repair_options(params), host);
        m.setMeshModified(true);
        log_lines(out.log);
        postConditionMask = postCondition(action);
        return result_map(out.counts);
      }
      default:
        wrongActionCalled(action);
    }
  } catch (const mbm::FilterInputError& e) {
    throw MLException(QString::fromStdString(e.what()));
  } catch (const MLException&) {
    throw;
  } catch (const std::exception& e) {
    throw MLException(QString("%1 failed on layer '%2': %3")
                          .arg(filterName(action))
                          .arg(m.label())
                          .arg(e.what()));
  }
  return {};
}
