// The traces of joints read from a user's .msh: each trace's ends from its
// mesh edges (joints.hpp, traces_of_joint_edges).
#include <algorithm>
#include <vector>

#include "rockfdem/mesh/joints.hpp"

namespace rockfdem::mesh {

std::vector<JointTrace> traces_of_joint_edges(const Mesh& m, JointTraceReport* report) {
  std::size_t n = 0;
  for (const JointEdge& e : m.joint_edges) n = std::max(n, std::size_t(e.trace) + 1);
  // Per trace: the vertices met once (its ends), in the order met.
  std::vector<std::vector<int>> once(n);
  for (const JointEdge& e : m.joint_edges)
    for (int v : {e.a, e.b}) {
      std::vector<int>& ends = once[std::size_t(e.trace)];
      const auto at = std::find(ends.begin(), ends.end(), v);
      if (at == ends.end())
        ends.push_back(v);
      else
        ends.erase(at);
    }
  std::vector<int> first(n, -1), last(n, -1);
  for (const JointEdge& e : m.joint_edges) {
    if (first[std::size_t(e.trace)] < 0) first[std::size_t(e.trace)] = e.a;
    last[std::size_t(e.trace)] = e.b;
  }
  std::vector<JointTrace> out;
  JointTraceReport r;
  for (std::size_t k = 0; k < once.size(); ++k) {
    // A curve has two ends; a closed one (or a stray shape) none or more:
    // its first and last edge's vertices stand for them.
    const bool path = once[k].size() == 2;
    const int a = path ? std::min(once[k][0], once[k][1]) : first[k];
    const int b = path ? std::max(once[k][0], once[k][1]) : last[k];
    out.push_back(
        {m.x[std::size_t(a)], m.y[std::size_t(a)], m.x[std::size_t(b)], m.y[std::size_t(b)]});
    r.length += trace_length(out.back());
  }
  r.given = r.kept = long(out.size());
  if (report) *report = r;
  return out;
}

}  // namespace rockfdem::mesh
