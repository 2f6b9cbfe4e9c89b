// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_meshbridge_2022.h"

#include "filter_actions.h"
#include "filter_catalog.h"
#include "meshlab_document_host.h"

#include <exception>
#include <string>

namespace mbm = meshbridge::meshlab;

namespace {

mbm::FilterId filter_id(MeshLabPlugin::ActionIDType filter) {
  return filter == FilterMeshBridgePlugin::FP_REPAIR_SINGULAR_DEFECTS ? mbm::FilterId::repair
                                                                      : mbm::FilterId::detect;
}

//! The counts as pymeshlab converts them: int (or bool for flags) QVariants.
std::map<std::string, QVariant> result_map(const std::vector<mbm::FilterCount>& counts) {
  std::map<std::string, QVariant> result;
  for (const mbm::FilterCount& c : counts) {
    if (c.is_flag) {
      result[c.name] = QVariant(c.value != 0);
    } else {
      result[c.name] = QVariant(int(c.value));
    }
  }
  return result;
}

}  // namespace

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
  switch (ID(action)) {
    case FP_DETECT_SINGULAR_DEFECTS:
      return MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_FACECOLOR;
    case FP_REPAIR_SINGULAR_DEFECTS:
      // Topology and vertex count change; copies of split vertices bring their colour/quality.
      return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTCOLOR |
             MeshModel::MM_VERTQUALITY | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY |
             MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTTEXCOORD;
  }
  return MeshModel::MM_ALL;
}

FilterPlugin::FilterArity FilterMeshBridgePlugin::filterArity(const QAction*) const {
  return SINGLE_MESH;
}

RichParameterList FilterMeshBridgePlugin::initParameterList(const QAction* action,
                                                            const MeshModel&) {
  RichParameterList params;
  for (const mbm::ParameterSpec& p : mbm::parameters(filter_id(ID(action)))) {
    if (p.kind == mbm::ParameterSpec::Kind::boolean) {
      params.addParam(RichBool(p.name, p.bool_default, p.label, p.tooltip));
    } else {
      QStringList values;
      for (const char* v : p.enum_values)
        values << v;
      params.addParam(RichEnum(p.name, p.enum_default, values, p.label, p.tooltip));
    }
  }
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
        mbm::MeshDocumentHost host(md);
        const mbm::DetectOutcome out =
            mbm::detect_singular_defects(m.cm, label, mbm::detect_options(params), host);
        log(out.log);
        postConditionMask = postCondition(action);
        return result_map(out.counts);
      }
      case FP_REPAIR_SINGULAR_DEFECTS: {
        const mbm::RepairOutcome out =
            mbm::repair_singular_defects(m.cm, label, mbm::repair_options(params));
        m.setMeshModified(true);
        log(out.log);
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
