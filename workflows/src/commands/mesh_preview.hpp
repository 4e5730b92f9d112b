// preview.png of `rockfdem mesh`: the model as meshed, before anything
// runs, so that bolts and key points can be checked by eye.
#pragma once

#include <string>

#include "record/summary.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

struct Scene;

/// DIR/preview.png: the triangles coloured by region (rock, rock with crack
/// elements, core, lining), the mesh's tagged edges in black, the bolts and
/// cables as dark red lines and the key points as labelled blue markers; a
/// window of one span (the opening's larger side) around the opening,
/// widened to hold every bolt; the whole model when it has no opening.
/// Without a display `skipped` says why (and stderr unless `quiet`).
void write_mesh_preview(const Scene& scene, const mesh::Mesh& m, const std::string& dir,
                        RunRecord& summary, bool quiet);

}  // namespace rockfdem::workflows
