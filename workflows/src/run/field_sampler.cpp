#include "run/field_sampler.hpp"

#include <stdexcept>
#include <utility>

#include "outputs/face_distance.hpp"
#include "outputs/ground_reaction.hpp"
#include "run/implicit_check.hpp"

namespace rockfdem::workflows {
namespace {

void swap_arrays(insitu::InsituField& a, insitu::InsituField& b) {
  a.stress.swap(b.stress);
  a.active.swap(b.active);
  a.ux.swap(b.ux);
  a.uy.swap(b.uy);
}

}  // namespace

void release_arrays(insitu::InsituField& f) {
  insitu::InsituField none;
  swap_arrays(none, f);
}

FieldSampler::FieldSampler(const Scene& scene, const mesh::Mesh& m)
    : scene_(&scene),
      mesh_(&m),
      key_points_(key_point_vertices(scene.mesh, m)),
      strength_ratio_(scene, m) {}

insitu::InsituSpec FieldSampler::attach(insitu::InsituSpec spec, Hold hold) {
  hold_ = hold;
  fields_in_solve_ = spec.alphas.size();
  past_first_crack_ = false;
  spec.on_field = [this](insitu::InsituField& f) { sample(f); };
  return spec;
}

void FieldSampler::sample(insitu::InsituField& f) {
  ImplicitSample& s = samples_.emplace_back();
  s.alpha = f.alpha;
  for (const KeyPointVertex& k : key_points_)
    s.key_points.push_back(
        {f.ux[k.vertex], f.uy[k.vertex],
         core_pressure(*mesh_, f, k.vertex, k.inward_x, k.inward_y).value_or(0.0)});
  s.strength_ratio = strength_ratio_(f);
  const Inversion inv = inverted_triangles(*mesh_, f);
  s.inverted = inv.count;
  s.first_inverted = inv.first;
  if (scene_->insitu.install_at_face_distance) s.wall_displacement = wall_displacement(*mesh_, f);
  if (hold_ == Hold::kAll) return;
  const std::size_t k = samples_.size() - 1;
  if (hold_ == Hold::kHandoff && may_hand_over(k, s.strength_ratio)) {
    release_arrays(held_);  // the previous candidate's
    swap_arrays(held_, f);
    held_index_ = k;
  } else {
    release_arrays(f);
  }
}

// choose_handoff's rule as the ratios come: "last" holds the solve's last
// field alone (an earlier one would be held through the next alpha's solve
// for nothing: 17 MB at 420k triangles); "first_crack" the first, then each
// while no ratio has exceeded 1.
bool FieldSampler::may_hand_over(std::size_t k, double ratio) {
  if (!scene_->insitu.handoff_first_crack) return k + 1 == fields_in_solve_;
  past_first_crack_ = past_first_crack_ || (k > 0 && !(ratio <= 1.0));
  return k == 0 || !past_first_crack_;
}

std::vector<ImplicitSample> FieldSampler::take(std::vector<insitu::InsituField>& fields) {
  if (hold_ == Hold::kHandoff && !samples_.empty()) {
    if (held_index_ >= fields.size())
      throw std::logic_error("FieldSampler: the held field is not in the solve's");
    swap_arrays(fields[held_index_], held_);
    held_ = insitu::InsituField{};
  }
  return std::exchange(samples_, {});
}

}  // namespace rockfdem::workflows
