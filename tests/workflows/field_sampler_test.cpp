// The implicit stage's fields as a run holds them (run/field_sampler.hpp):
// each field's sample is exactly what the whole field gives, and only the
// field the hand-off rule chooses keeps its arrays. The scene is
// tests/workflows/handoff_circular.toml (alphas 1, 0.6, 0.3, 0.1, 0.03;
// its first crack over strength at 0.1, so "first_crack" hands over 0.3).
#include "run/field_sampler.hpp"

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "outputs/ground_reaction.hpp"
#include "rockfdem/mesh/build.hpp"
#include "run/engine_setup.hpp"

using namespace rockfdem;
using namespace rockfdem::workflows;

namespace {

struct Solved {
  Scene scene;
  mesh::Mesh mesh;
  std::vector<insitu::InsituField> whole;  ///< every field with its arrays
};

const Solved& solved() {
  static const Solved s = [] {
    Solved r{load_scene(test::kTestDir + "/handoff_circular.toml"), {}, {}};
    r.mesh = mesh::build_mesh(r.scene.mesh);
    r.whole = insitu::solve_insitu(r.mesh, insitu_spec(r.scene));
    return r;
  }();
  return s;
}

// The fields of `scene`'s sequence through a sampler holding the hand-off's.
std::pair<std::vector<insitu::InsituField>, std::vector<ImplicitSample>> sampled(
    const Scene& scene, const mesh::Mesh& m) {
  FieldSampler sampler(scene, m);
  const insitu::InsituSpec spec = sampler.attach(insitu_spec(scene), FieldSampler::Hold::kHandoff);
  std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, spec);
  std::vector<ImplicitSample> samples = sampler.take(fields);
  return {std::move(fields), std::move(samples)};
}

void expect_only_held(const std::vector<insitu::InsituField>& fields,
                      const std::vector<insitu::InsituField>& whole, std::size_t held) {
  ASSERT_EQ(fields.size(), whole.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i != held) {
      EXPECT_TRUE(fields[i].ux.empty() && fields[i].stress.empty()) << "field " << i;
      continue;
    }
    EXPECT_EQ(fields[i].ux, whole[i].ux);
    EXPECT_EQ(fields[i].uy, whole[i].uy);
    EXPECT_EQ(fields[i].active, whole[i].active);
    ASSERT_EQ(fields[i].stress.size(), whole[i].stress.size());
    for (std::size_t t = 0; t < whole[i].stress.size(); ++t)
      ASSERT_EQ(fields[i].stress[t].sxx, whole[i].stress[t].sxx) << t;
  }
}

}  // namespace

TEST(FieldSampler, samples_are_the_whole_fields_figures) {
  const Solved& s = solved();
  const auto [fields, samples] = sampled(s.scene, s.mesh);
  const std::vector<KeyPointVertex> keys = key_point_vertices(s.scene.mesh, s.mesh);
  ASSERT_EQ(keys.size(), 6u);
  ASSERT_EQ(samples.size(), s.whole.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const insitu::InsituField& f = s.whole[i];
    EXPECT_EQ(samples[i].alpha, f.alpha);
    ASSERT_EQ(samples[i].key_points.size(), keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const KeyPointSample& p = samples[i].key_points[k];
      EXPECT_EQ(p.ux, f.ux[keys[k].vertex]);
      EXPECT_EQ(p.uy, f.uy[keys[k].vertex]);
      EXPECT_EQ(p.core_pressure,
                core_pressure(s.mesh, f, keys[k].vertex, keys[k].inward_x, keys[k].inward_y)
                    .value_or(0.0));
    }
    EXPECT_EQ(samples[i].inverted, 0);
  }
  // The scene's closed form (handoff_test.cpp): over strength first at 0.1.
  EXPECT_LE(samples[2].strength_ratio, 1.0);
  EXPECT_GT(samples[3].strength_ratio, 1.0);
}

TEST(FieldSampler, first_crack_holds_only_the_field_handed_over) {
  const Solved& s = solved();
  const auto [fields, samples] = sampled(s.scene, s.mesh);
  std::vector<double> ratios;
  for (const ImplicitSample& x : samples) ratios.push_back(x.strength_ratio);
  const HandoffChoice c = choose_handoff(s.scene, ratios);
  EXPECT_EQ(c.index, 2u);
  expect_only_held(fields, s.whole, c.index);
}

TEST(FieldSampler, last_holds_only_the_last_field) {
  const Solved& s = solved();
  Scene last = s.scene;
  last.insitu.handoff_first_crack = false;
  const auto [fields, samples] = sampled(last, s.mesh);
  expect_only_held(fields, s.whole, fields.size() - 1);
}
