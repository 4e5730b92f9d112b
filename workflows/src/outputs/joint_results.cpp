// Each meshed trace's joint elements by state, for joints.csv and the summary.
#include "outputs/joint_results.hpp"

#include <cstdio>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/joint_cracks.hpp"

namespace rockfdem::workflows {

JointRecord joint_results(const fdem::Engine& e, const mesh::Mesh& m,
                          const std::vector<mesh::JointTrace>& traces,
                          const std::string& csv_path) {
  const std::vector<std::int32_t> on = coupling::joint_crack_traces(e, m);
  const coupling::JointCounts n = coupling::count_joint_cracks(e, on);
  JointRecord r;
  r.elements = n.elements;
  r.active = n.active;
  r.yielding = n.yielding;
  r.residual = n.residual;
  // Per trace: the same counts over its own elements.
  std::vector<coupling::JointCounts> per(traces.size());
  for (std::size_t k = 0; k < traces.size(); ++k) {
    std::vector<std::int32_t> only(on.size(), 0);
    for (std::size_t c = 0; c < on.size(); ++c) only[c] = on[c] == std::int32_t(k + 1);
    per[k] = coupling::count_joint_cracks(e, only);
  }
  std::string csv = "trace,x0_m,y0_m,x1_m,y1_m,length_m,elements,active,yielding,residual\n";
  char row[256];
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const mesh::JointTrace& t = traces[k];
    std::snprintf(row, sizeof row, "%zu,%.6f,%.6f,%.6f,%.6f,%.6f,%ld,%ld,%ld,%ld\n", k + 1, t.x0,
                  t.y0, t.x1, t.y1, mesh::trace_length(t), per[k].elements, per[k].active,
                  per[k].yielding, per[k].residual);
    csv += row;
  }
  coupling::atomic_write_text(csv_path, csv);
  return r;
}

}  // namespace rockfdem::workflows
