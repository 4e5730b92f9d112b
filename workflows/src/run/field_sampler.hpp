// The implicit stage's fields as a run reads them: each sampled as it is
// solved (outputs/implicit_sample.hpp: the ground reaction curve's key
// points, the hand-off rule's strength ratio, the inversion check, the
// face distance's wall displacement), and held whole only while it may
// still be the one handed over. The run's peak at 420k triangles is set
// in this stage: every earlier alpha's field held beside the solver cost
// 16 MB each.
#pragma once

#include <cstddef>
#include <vector>

#include "outputs/implicit_sample.hpp"
#include "outputs/monitors.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/handoff_choice.hpp"

namespace rockfdem::workflows {

/// Frees a field's arrays (stress, active, ux, uy); its report stays.
void release_arrays(insitu::InsituField& f);

class FieldSampler {
 public:
  /// Which of a solve's fields keep their arrays.
  enum class Hold {
    kAll,      ///< every field
    kNone,     ///< none: the samples are all that is read
    kHandoff,  ///< only the one insitu.handoff's rule would hand over
  };
  FieldSampler(const Scene& scene, const mesh::Mesh& m);
  /// `spec`, its fields sampled into this one and held as `hold` says.
  insitu::InsituSpec attach(insitu::InsituSpec spec, Hold hold);
  /// The samples of the fields since the last take; with Hold::kHandoff
  /// the held field's arrays are put back into `fields` (the solve's).
  std::vector<ImplicitSample> take(std::vector<insitu::InsituField>& fields);

 private:
  void sample(insitu::InsituField& f);
  /// Hold::kHandoff: whether field `k` of the solve may still be handed over.
  bool may_hand_over(std::size_t k, double ratio);

  const Scene* scene_;
  const mesh::Mesh* mesh_;
  std::vector<KeyPointVertex> key_points_;
  StrengthRatio strength_ratio_;
  Hold hold_ = Hold::kAll;
  std::size_t fields_in_solve_ = 0;  ///< the attached spec's alphas
  bool past_first_crack_ = false;
  std::vector<ImplicitSample> samples_;
  insitu::InsituField held_;  ///< Hold::kHandoff: the candidate's arrays
  std::size_t held_index_ = 0;
};

}  // namespace rockfdem::workflows
