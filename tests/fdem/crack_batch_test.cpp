// The crack loop's batch kernel (fdem/src/crack_batch.hpp) against the
// scalar element evaluation it stands in for, bit by bit, on every
// instruction set.
#include "crack_batch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include "crack_elements.hpp"
#include "engine_data.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"
#include "test_models.hpp"
#include "topology.hpp"

namespace {

using namespace rockfdem::fdem;
using detail::CrackBatch;
using detail::kCrackBatch;
using detail::SimdIsa;

struct Element {
  double x[4], y[4], off_o[3], off_s[3], damage[3];
};

/// An element of length 0.1-2 m at a random angle, its four nodes moved by
/// up to 1e-6, 1e-5 or 1e-4 of its length times `reach` (below and past the
/// peaks of the default rock, op = 3.3e-5 h, sp about 1e-4 h, at reach 1),
/// with or without offsets.
Element random_element(std::mt19937& rng, bool offsets, double reach) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double len = 1.05 + 0.95 * u(rng), angle = 3.14159 * u(rng);
  const double scale = reach * len * std::pow(10.0, -5.0 + std::round(u(rng)));
  const double ex = std::cos(angle), ey = std::sin(angle);
  const double base_x[4] = {0, len, len, 0};  // 0, 1 one face; 3 faces 0, 2 faces 1
  Element e;
  for (int j = 0; j < 4; ++j) {
    e.x[j] = 3.0 + base_x[j] * ex + scale * u(rng);
    e.y[j] = -2.0 + base_x[j] * ey + scale * u(rng);
  }
  for (int i = 0; i < 3; ++i) {
    e.off_o[i] = offsets ? 0.3 * scale * u(rng) : 0.0;
    e.off_s[i] = offsets ? 0.3 * scale * u(rng) : 0.0;
    const double pick = u(rng);  // half intact, some at 1, the rest softened
    e.damage[i] = pick < 0.0 ? 0.0 : pick > 0.8 ? 1.0 : 0.5 * (1.0 + u(rng));
  }
  return e;
}

/// The scalar evaluation of crack_elements.cpp for an element of law Law:
/// geometry, Law::point at the points' histories, Simpson weights. Returns
/// false where a point's damage would grow.
template <class Law>
bool scalar_element(const CrackConstants& k, const Element& e, bool offsets, double out[8]) {
  const double tx = 0.5 * ((e.x[1] + e.x[2]) - (e.x[0] + e.x[3]));
  const double ty = 0.5 * ((e.y[1] + e.y[2]) - (e.y[0] + e.y[3]));
  const double h = std::sqrt(tx * tx + ty * ty), inv_h = 1.0 / h;
  const double ex = tx * inv_h, ey = ty * inv_h, nx = -ey, ny = ex;
  const double d0x = e.x[0] - e.x[3], d0y = e.y[0] - e.y[3];
  const double d1x = e.x[1] - e.x[2], d1y = e.y[1] - e.y[2];
  const double o0 = d0x * nx + d0y * ny, s0 = d0x * ex + d0y * ey;
  const double o1 = d1x * nx + d1y * ny, s1 = d1x * ex + d1y * ey;
  double o[3] = {o0, 0.5 * (o0 + o1), o1}, s[3] = {s0, 0.5 * (s0 + s1), s1};
  if (offsets)
    for (int i = 0; i < 3; ++i) {
      o[i] -= e.off_o[i];
      s[i] -= e.off_s[i];
    }
  CrackPoint p[3];
  for (int i = 0; i < 3; ++i) {
    double damage = e.damage[i];
    p[i] = Law::point(k, material_terms(k), o[i], s[i], h, inv_h, damage);
    if (damage != e.damage[i]) return false;  // grew: the scalar path's case
  }
  const double w_end = h / 6.0, w_mid = h / 3.0;
  const double sn0 = w_end * p[0].sigma + w_mid * p[1].sigma;
  const double st0 = w_end * p[0].tau + w_mid * p[1].tau;
  const double sn1 = w_end * p[2].sigma + w_mid * p[1].sigma;
  const double st1 = w_end * p[2].tau + w_mid * p[1].tau;
  const double f0x = -(st0 * ex + sn0 * nx), f0y = -(st0 * ey + sn0 * ny);
  const double f1x = -(st1 * ex + sn1 * nx), f1y = -(st1 * ey + sn1 * ny);
  const double f[8] = {f0x, f0y, f1x, f1y, -f1x, -f1y, -f0x, -f0y};
  std::memcpy(out, f, sizeof f);
  return true;
}

// Every lane's eight slot values equal the scalar evaluation's bit for bit,
// and exactly the lanes where a point's damage would grow are flagged, with
// and without offsets, with and without per-lane strength factors (0.05-5,
// the scalar side on scale_crack_strength) where the law admits them, on
// every instruction set the processor has, for lane counts that leave a
// partial last register. Returns the lanes compared and those flagged.
template <class Law>
std::pair<int, int> expect_lanes_match_scalar(const Material& m, double reach) {
  const CrackConstants k = make_crack_constants(m);
  int below = 0, past = 0;
  for (bool scaled : {false, true})
    for (SimdIsa isa : {SimdIsa::kBaseline, SimdIsa::kAvx2, SimdIsa::kAvx512}) {
      if (!detail::simd_isa_available(isa) || (scaled && !Law::kHeterogeneous)) continue;
      std::mt19937 rng(11);
      CrackBatch b{};
      for (int draw = 0; draw < 200; ++draw) {
        const bool offsets = draw % 2;
        const int n = kCrackBatch - draw % 5;
        Element e[kCrackBatch];
        for (int r = 0; r < n; ++r) {
          e[r] = random_element(rng, offsets, reach);
          for (int j = 0; j < 4; ++j) {
            b.x[j][r] = e[r].x[j];
            b.y[j][r] = e[r].y[j];
          }
          for (int i = 0; i < 3; ++i) {
            b.off_o[i][r] = e[r].off_o[i];
            b.off_s[i][r] = e[r].off_s[i];
            b.damage[i][r] = e[r].damage[i];
          }
          b.strength[r] = scaled ? std::pow(10.0, std::uniform_real_distribution<double>(
                                                      std::log10(kMinStrengthFactor),
                                                      std::log10(kMaxStrengthFactor))(rng))
                                 : 1.0;
        }
        detail::run_crack_batch(b, n, k, scaled, isa);
        for (int r = 0; r < n; ++r) {
          double want[8];
          const bool ok =
              scalar_element<Law>(scale_crack_strength(k, b.strength[r]), e[r], offsets, want);
          EXPECT_EQ(b.grows[r], ok ? 0.0 : 1.0) << "draw " << draw << " lane " << r;
          if (!ok) {
            ++past;
            continue;
          }
          ++below;
          for (int i = 0; i < 8; ++i)
            EXPECT_EQ(std::memcmp(&b.out[i][r], &want[i], sizeof(double)), 0)
                << "draw " << draw << " lane " << r << " slot " << i << ": " << b.out[i][r]
                << " against " << want[i];
        }
      }
    }
  return {below, past};
}

TEST(CrackBatch, matches_the_scalar_element_bit_for_bit) {
  const auto [below, past] = expect_lanes_match_scalar<RockLaw>(Material{}, 1.0);
  EXPECT_GT(below, 2000);  // both branches exercised
  EXPECT_GT(past, 2000);
}

// The same kernel runs bolt steel (its peaks lie about ten times further
// out than the rock's: op = 4e-4 h).
TEST(CrackBatch, bolt_steel_lanes_match_the_scalar_element_bit_for_bit) {
  const auto [below, past] = expect_lanes_match_scalar<BoltSteelLaw>(test::bolt_steel(), 10.0);
  EXPECT_GT(below, 1000);
  EXPECT_GT(past, 1000);
}

// crack_forces with the batch path against crack_forces with every element
// on the scalar loop, bit for bit, over a fracturing mesh: two rock
// materials and bolt steel mixed within the blocks, offsets on a third of
// the elements, nodes moved further each round so that points soften,
// histories grow and elements break, and a few intact elements carry a
// damage history (the scalar loop marks them yielding). Compared after
// each round: slots,
// damage, state, mode, broken step, broken count, fracture energy. With
// `factors`, every element has its own strength factor (0.3-3).
void expect_batch_equals_scalar_loop(bool factors) {
  RectangleSpec spec;
  spec.width = spec.height = 0.02;
  spec.nx = spec.ny = 16;
  Material weak = test::rock();
  weak.tensile_strength *= 0.5;
  weak.cohesion *= 0.7;
  ModelInput in = structured_rectangle(spec, test::rock());
  in.materials = {test::rock(), weak, test::bolt_steel()};
  detail::EngineData a;
  a.materials = in.materials;
  for (const Material& m : in.materials) a.crack_laws.push_back(make_crack_constants(m));
  detail::build_topology(in, a);
  const int nc = static_cast<int>(a.cracks.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double h = spec.width / spec.nx;
  a.cracks.offset.assign(6 * nc, 0.0);
  for (int e = 0; e < nc; ++e) {
    const double pick = u(rng);
    a.cracks.material[e] = pick > 0.6 ? 1 : pick < -0.9 ? 2 : 0;
    if (u(rng) > 0.33) continue;
    for (int i = 0; i < 6; ++i) a.cracks.offset[6 * e + i] = 2e-6 * h * u(rng);
  }
  for (int e = 0; e < nc; e += 97) a.cracks.damage[3 * e + 1] = 0.3;  // intact with a history
  if (factors) {
    a.cracks.strength.resize(nc);
    for (int e = 0; e < nc; ++e) a.cracks.strength[e] = std::pow(10.0, 0.48 * u(rng));
  }
  a.energy_partial.assign(nc / 128 + 2, 0.0);
  a.energy.last_dt = 1e-7;
  a.threads = 2;
  detail::EngineData b = a;
  b.crack_batch = false;
  int batched_rounds = 0;
  long broken = 0;
  for (int round = 0; round < 30; ++round) {
    const double step = 1e-5 * h * std::pow(2.0, round / 3.0);  // to beyond the softening
    for (std::size_t i = 0; i < a.nodes.pos.size(); ++i) {
      const double move = step * u(rng);
      a.nodes.pos[i] += move;
      b.nodes.pos[i] += move;
    }
    a.step = b.step = round;
    const long na = detail::crack_forces(a), nb = detail::crack_forces(b);
    broken += na;
    ASSERT_EQ(na, nb) << "round " << round;
    ASSERT_EQ(std::memcmp(a.slots.data(), b.slots.data(), a.slots.size() * sizeof(double)), 0)
        << "round " << round;
    ASSERT_EQ(a.cracks.damage, b.cracks.damage) << "round " << round;
    ASSERT_EQ(a.cracks.state, b.cracks.state) << "round " << round;
    ASSERT_EQ(a.cracks.mode, b.cracks.mode) << "round " << round;
    ASSERT_EQ(a.cracks.broken_step, b.cracks.broken_step) << "round " << round;
    ASSERT_EQ(std::memcmp(&a.energy.fracture, &b.energy.fracture, sizeof(double)), 0)
        << "round " << round;
    long yielding = 0;
    for (int e = 0; e < nc; ++e)
      yielding += a.cracks.state[e] == std::uint8_t(CrackState::kYielding);
    batched_rounds += yielding > 0;
  }
  EXPECT_GT(broken, 10);          // breakage exercised
  EXPECT_GT(batched_rounds, 10);  // softened elements in the batch exercised
}

TEST(CrackBatch, crack_forces_equal_the_scalar_loop_over_a_fracturing_mesh) {
  expect_batch_equals_scalar_loop(false);
}

TEST(CrackBatch, crack_forces_with_strength_factors_equal_the_scalar_loop) {
  expect_batch_equals_scalar_loop(true);
}

// Damage is stored in single precision, rounded up (engine_data.hpp): the
// stored value is the least float at or above the law's, so the law never
// finds a history below the one it reached. Random damages in (0, 1), the
// floats themselves and values just below 1 (which round up to 1).
TEST(StoredDamage, is_the_least_float_at_or_above_the_laws) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> values = {0.0, 1.0, 0.5, 1.0 - 1e-12, 1e-30, 0.1};
  for (int i = 0; i < 100000; ++i) values.push_back(u(rng));
  for (int i = 0; i < 1000; ++i) values.push_back(double(float(u(rng))));
  int exact = 0;
  for (const double v : values) {
    const float f = detail::round_up_to_float(v);
    ASSERT_GE(double(f), v) << v;
    if (double(f) == v) {
      ++exact;
      continue;
    }
    ASSERT_LT(double(std::nextafter(f, 0.0f)), v) << v;
  }
  EXPECT_GE(exact, 1003);  // 0, 1, 0.5 and the floats stay as they are
  EXPECT_EQ(detail::round_up_to_float(1.0 - 1e-12), 1.0f);
}

}  // namespace
