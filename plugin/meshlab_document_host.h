// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file meshlab_document_host.h
//! The MeshLab document as the shared filters see it. Header-only and written against the
//! MeshDocument / MeshModel names both MeshLab generations share: each adapter includes it
//! after its own SDK's headers (the two adapters are never compiled together).

#include "filter_actions.h"
#include "filter_catalog.h"

#include <algorithm>
#include <string>
#include <vector>

namespace meshbridge::meshlab {

//! The data masks filter `id` changes (the adapters' postCondition()). Detect: the selection, and
//! not MM_FACECOLOR, which would switch the mesh's rendering to per-face colour (a grey STL turns
//! white); with "colour faces" the colour mask is turned on (2020.09 compares the data masks
//! before and after the filter, the >= 2022 adapter adds MM_FACECOLOR to the mask it returns).
//! Repair: topology and vertex count change; copies of split vertices bring their colour,
//! quality and texture coordinates.
inline int changed_data_mask(FilterId id) {
  if (id == FilterId::detect)
    return MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_FACEFLAGSELECT;
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTCOLOR |
         MeshModel::MM_VERTQUALITY | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY |
         MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTTEXCOORD;
}

class MeshDocumentHost final : public DocumentHost {
 public:
  //! `can_save_3mf`: whether the running MeshLab has a 3MF exporter (the adapter asks its API).
  MeshDocumentHost(MeshDocument& md, bool can_save_3mf)
      : md_(md), mesh_(*md.mm()), can_save_3mf_(can_save_3mf) {}
  void enable_face_color() override { mesh_.updateDataMask(MeshModel::MM_FACECOLOR); }
  CMeshO& add_defect_layer(const std::string& label, bool face_color) override {
    remove_layers(label);
    MeshModel* layer = md_.addNewMesh("", QString::fromStdString(label), false);
    int mask = MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY;
    if (face_color)
      mask |= MeshModel::MM_FACECOLOR;
    layer->updateDataMask(mask);
    return layer->cm;
  }
  std::size_t remove_layers(const std::string& label) override {
    const QString wanted = QString::fromStdString(label);
    std::vector<MeshModel*> doomed;
    for (MeshModel* m = md_.nextMesh(); m != nullptr; m = md_.nextMesh(m)) {
      if (m != &mesh_ && m->label() == wanted)
        doomed.push_back(m);
    }
    // MeshLab >= 2022's delMesh() makes the mesh after a deleted one current when the deleted
    // one was current, and may move the current mesh otherwise; the filters never change which
    // mesh is current (a following save_current_mesh() saves the mesh the user chose).
    MeshModel* const current = md_.mm();
    for (MeshModel* m : doomed) {
#if __has_include(<common/ml_document/mesh_document.h>)
      md_.delMesh(m->id());  // MeshLab >= 2022
#else
      md_.delMesh(m);             // MeshLab 2020.09
#endif
    }
    if (current != nullptr && md_.mm() != current &&
        std::find(doomed.begin(), doomed.end(), current) == doomed.end())
      md_.setCurrentMesh(current->id());
    return doomed.size();
  }
  bool can_save_3mf() const override {
    return can_save_3mf_;
  }
  std::string file_name() const override {
    return mesh_.fullName().toStdString();
  }
  void update_box_and_normals(CMeshO&) override {
#if __has_include(<common/ml_document/mesh_document.h>)
    mesh_.updateBoxAndNormals();  // MeshLab >= 2022
#else
    mesh_.UpdateBoxAndNormals();  // MeshLab 2020.09
#endif
  }

 private:
  MeshDocument& md_;
  MeshModel& mesh_;
  bool can_save_3mf_;
};

}  // namespace meshbridge::meshlab
