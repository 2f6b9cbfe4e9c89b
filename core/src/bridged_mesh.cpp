// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/bridged_mesh.h"

#include "meshbridge/validate.h"

#include "pipeline/run_pipeline.h"
#include "working_soup.h"

namespace meshbridge {

BridgedMesh build_bridged_mesh(const Soup& soup, const BridgedMeshOptions& options) {
  validate_soup(soup);
  const detail::WorkingSoup working(soup);
  detail::PipelineOptions pipeline_options;
  pipeline_options.pairing = options.pairing;
  pipeline_options.orient = false;
  pipeline_options.stitch = false;
  detail::PipelineResult pipeline = detail::run_pipeline(working, pipeline_options);

  BridgedMesh bridged;
  bridged.indexed = std::move(pipeline.mesh);
  bridged.bridges = std::move(pipeline.grouped.bridges);
  bridged.mate = std::move(pipeline.pairing.mate);

  const auto& origin = bridged.indexed.vertex_origin;
  bridged.copies_begin.assign(soup.num_vertices() + 1, 0);
  for (Index v : origin)
    ++bridged.copies_begin[v + 1];
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    bridged.copies_begin[v + 1] += bridged.copies_begin[v];
  }
  bridged.copies.resize(origin.size());
  std::vector<Index> fill(bridged.copies_begin.begin(), bridged.copies_begin.end() - 1);
  for (Index out = 0; out < origin.size(); ++out)
    bridged.copies[fill[origin[out]]++] = out;

  if (fill_openmesh(bridged.indexed, bridged.mesh) != 0)  // every add_face succeeds by construction
    throw std::logic_error("build_bridged_mesh: OpenMesh refused a face of the bridged mesh");
  return bridged;
}

}  // namespace meshbridge
