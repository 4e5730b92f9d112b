// The elastic counterpart solved as the implicit stage's own solve gone on
// (run/continuum_solve.hpp, CounterpartTail): the implicit stage's fields
// are bit for bit those of its solve alone, and the counterpart's hand-off
// and end those of the counterpart solved apart. Scenes:
// tests/workflows/handoff_circular.toml (alphas 1 to 0.03, no lining, the
// core removed) and lined_elastic_circular.toml (alphas 1, 0.3, the ring
// installed as a lining at 0.3, then the core removed).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "cli_runner.hpp"
#include "rockfdem/mesh/build.hpp"
#include "run/continuum_solve.hpp"
#include "run/engine_setup.hpp"

using namespace rockfdem;
using namespace rockfdem::workflows;

namespace {

void expect_same(const insitu::InsituField& a, const insitu::InsituField& b, const char* what) {
  EXPECT_EQ(a.alpha, b.alpha) << what;
  EXPECT_EQ(a.ux, b.ux) << what;
  EXPECT_EQ(a.uy, b.uy) << what;
  EXPECT_EQ(a.active, b.active) << what;
  ASSERT_EQ(a.stress.size(), b.stress.size()) << what;
  for (std::size_t t = 0; t < a.stress.size(); ++t) {
    ASSERT_EQ(a.stress[t].sxx, b.stress[t].sxx) << what << ", triangle " << t;
    ASSERT_EQ(a.stress[t].syy, b.stress[t].syy) << what << ", triangle " << t;
    ASSERT_EQ(a.stress[t].sxy, b.stress[t].sxy) << what << ", triangle " << t;
    ASSERT_EQ(a.stress[t].szz, b.stress[t].szz) << what << ", triangle " << t;
  }
}

}  // namespace

TEST(CounterpartTail, continues_the_implicit_stage_with_the_fields_of_both_solved_apart) {
  for (const char* file : {"handoff_circular.toml", "lined_elastic_circular.toml"}) {
    SCOPED_TRACE(file);
    const Scene scene = load_scene(test::kTestDir + "/" + file);
    const mesh::Mesh m = mesh::build_mesh(scene.mesh);
    const std::vector<insitu::InsituField> alone = insitu::solve_insitu(m, insitu_spec(scene));
    const ContinuumStates apart = solve_continuum_counterpart(scene, m);

    insitu::InsituSpec spec = insitu_spec(scene);
    std::optional<CounterpartTail> tail = counterpart_tail(scene, spec);
    ASSERT_TRUE(tail.has_value());
    EXPECT_EQ(spec.alphas, apart.alphas);
    EXPECT_GT(spec.alphas.size(), alone.size()) << "no alpha after the implicit stage's";
    spec.on_field = [&](insitu::InsituField& f) { tail->take(f); };
    const std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, spec);

    ASSERT_EQ(tail->implicit_alphas, alone.size());
    for (std::size_t i = 0; i < alone.size(); ++i) expect_same(fields[i], alone[i], "implicit");
    for (std::size_t i = alone.size(); i < fields.size(); ++i)
      EXPECT_TRUE(fields[i].ux.empty()) << "the tail's field " << i << " kept its arrays";
    const ContinuumStates& c = tail->states;
    EXPECT_EQ(c.alphas, apart.alphas);
    EXPECT_EQ(c.lining_alpha, apart.lining_alpha);
    // The "last" rule hands over the implicit stage's last field: the
    // counterpart reads it there instead of holding a copy.
    EXPECT_EQ(c.handoff_is_runs, !scene.insitu.handoff_first_crack);
    EXPECT_EQ(c.handoff.alpha, apart.handoff.alpha);
    expect_same(c.handoff_field(fields[alone.size() - 1]), apart.handoff, "counterpart hand-off");
    expect_same(c.end, apart.end, "counterpart end");
  }
}

// No tail where the counterpart is another problem (Mohr-Coulomb) or
// there is none (the core stays): the spec is left as it was.
TEST(CounterpartTail, none_for_a_mohr_coulomb_counterpart_or_a_core_left_in_place) {
  Scene scene = load_scene(test::kTestDir + "/handoff_circular.toml");
  const insitu::InsituSpec plain = insitu_spec(scene);
  scene.insitu.continuum = "mohr_coulomb";
  insitu::InsituSpec spec = insitu_spec(scene);
  EXPECT_FALSE(counterpart_tail(scene, spec).has_value());
  EXPECT_EQ(spec.alphas, plain.alphas);
  scene.insitu.continuum = "elastic";
  scene.stages.erase(std::remove_if(scene.stages.begin(), scene.stages.end(),
                                    [](const StageSpec& s) { return s.kind == "remove_core"; }),
                     scene.stages.end());
  EXPECT_FALSE(counterpart_tail(scene, spec).has_value());
  EXPECT_EQ(spec.alphas, plain.alphas);
}
