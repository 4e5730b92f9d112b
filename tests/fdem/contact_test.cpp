// Contact: Munjiza's potential-based penalty contact with Coulomb
// friction, the free-surface broad phase, and determinism.
#include "contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "boundary.hpp"
#include "contact_grid.hpp"
#include "engine_data.hpp"
#include "node_update.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/constants.hpp"
#include "test_models.hpp"
#include "topology.hpp"

namespace rockfdem::fdem {
namespace {

/// Sum of the node forces of triangle t's nodes (each node once).
std::array<double, 2> triangle_force(const Engine& e, int t) {
  std::array<double, 2> f{0, 0};
  for (int n : e.triangle_nodes(t)) {
    f[0] += e.node_force(n)[0];
    f[1] += e.node_force(n)[1];
  }
  return f;
}

ContactSettings contact_on(double penalty = 0) {
  ContactSettings c;
  c.enabled = true;
  c.penalty = penalty;
  return c;
}

// Target T = (0,0), (L,0), (L/2, H); contactor C below with its top edge
// from x1 to x2 at y = delta (inside T), apex depth Hc. To first order in
// delta/L both roles push with a uniform potential: C's top edge inside T
// sees phi = 3 delta / H, T's base inside C sees phi = 3 delta / Hc, so
//   F = 3 p delta (x2 - x1) (1/H + 1/Hc)
// up on T, down on C (0.1%; the ends add O(delta / (x2 - x1))). Apart by a
// gap: no force. Forces and moments balance exactly.
TEST(Contact, two_triangles_pressed_together_match_the_potential_closed_form) {
  using P = test::PressedTriangles;
  const double L = P::L, H = P::H, x1 = P::x1, x2 = P::x2, hc = P::hc, delta = 2e-6;
  const double p = 3e10;
  for (double gap : {-delta, delta}) {  // -delta: overlap by delta
    ModelInput in = P::model(-gap);
    in.contact = contact_on(p);
    Engine e(in);
    e.step();
    const auto ft = triangle_force(e, 0), fc = triangle_force(e, 1);
    const double expected = gap < 0 ? 3 * p * delta * (x2 - x1) * (1 / H + 1 / hc) : 0.0;
    std::printf("gap %g: force on target %.6g (closed form %.6g)\n", gap, ft[1], expected);
    EXPECT_NEAR(ft[1], expected, 1e-3 * 3 * p * delta * (x2 - x1) / H);
    EXPECT_NEAR(ft[0], 0.0, 1e-6 * std::max(expected, 1.0));
    EXPECT_NEAR(ft[0] + fc[0], 0.0, 1e-9 * std::max(expected, 1.0));
    EXPECT_NEAR(ft[1] + fc[1], 0.0, 1e-9 * std::max(expected, 1.0));
    // Moment about the origin of all contact forces vanishes.
    double moment = 0;
    for (std::size_t n = 0; n < e.n_nodes(); ++n)
      moment +=
          e.positions()[2 * n] * e.node_force(n)[1] - e.positions()[2 * n + 1] * e.node_force(n)[0];
    EXPECT_NEAR(moment, 0.0, 1e-9 * std::max(expected, 1.0) * L);
    EXPECT_EQ(e.contact_counters().pairs, 1);
    EXPECT_EQ(e.contact_counters().touching, gap < 0 ? 1 : 0);
  }
}

double total_energy(const Engine& e) { return e.kinetic_energy() + e.strain_energy(); }

struct Bounce {
  double e0 = 0, e1 = 0, rebound = 0;  ///< energies before and after, upward velocity
};

// An elastic block thrown onto a fixed block at 1 m/s (no gravity, friction,
// damping), dt the given fraction of the stability limit: the blocks'
// kinetic plus strain energy before and after the bounce, and the rebound.
Bounce bounce(double dt_fraction) {
  Material m = test::rock();
  ModelInput in = test::two_blocks(1e-4, m);
  in.contact = contact_on();
  in.contact.friction = false;
  in.threads = 1;
  Engine e(in);
  e.set_dt(dt_fraction * e.critical_dt());
  const std::size_t first_upper = e.n_triangles() / 3;  // lower block has 2/3 of the triangles
  std::vector<char> upper(e.n_nodes(), 0);
  for (std::size_t t = 2 * first_upper; t < e.n_triangles(); ++t)
    for (int n : e.triangle_nodes(t)) upper[n] = 1;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    if (upper[n]) e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], 0, -1.0);
  Bounce b;
  b.e0 = total_energy(e);
  bool touched = false, separated = false;
  long steps = 0;
  for (; steps < 200000 && !separated; ++steps) {
    e.step();
    if (e.contact_counters().touching > 0)
      touched = true;
    else if (touched)
      separated = true;
  }
  EXPECT_TRUE(separated) << "no bounce within " << steps << " steps";
  e.run(200);
  double vy = 0, mass = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    if (upper[n]) {
      vy += e.node_mass()[n] * e.velocities()[2 * n + 1];
      mass += e.node_mass()[n];
    }
  b.e1 = total_energy(e);
  b.rebound = vy / mass;
  std::printf(
      "dt %.2f of the limit: bounce after %ld steps, energy %.6g -> %.6g (%.3g%%), "
      "rebound velocity %.4g m/s\n",
      dt_fraction, steps, b.e0, b.e1, 100 * (b.e1 - b.e0) / b.e0, b.rebound);
  return b;
}

// After separation the energy equals the initial kinetic energy. The
// penalty's error depends on where within a step the contact starts and
// ends, so it shrinks with dt but not smoothly: measured -0.14, +0.03,
// +0.24, +0.80, +0.51, -1.70, +1.95, +2.72 and -3.89% at 0.4, 0.5, 0.6,
// 0.7, 0.75, 0.8, 0.85, 0.9 and 0.95 of the power-iteration limit; with
// Lanczos' (0.3% shorter here) -0.06% at 0.5 and -2.32% at 0.8. At half
// the limit it must hold to 0.5%; at the default (0.8) to 3%, which a
// small change of the limit (0.03% moves the bounce by 13 steps) does not
// overturn.
TEST(Contact, elastic_block_bounces_with_energy_conserved) {
  const Bounce fine = bounce(0.5);
  EXPECT_GT(fine.rebound, 0.5);  // it did bounce back up
  EXPECT_NEAR(fine.e1, fine.e0, 0.005 * fine.e0);
  const Bounce coarse = bounce(0.8);
  EXPECT_GT(coarse.rebound, 0.5);
  EXPECT_NEAR(coarse.e1, coarse.e0, 0.03 * coarse.e0);
}

/// Places triangle 1 of the two-triangle model at offset (ux, uy) from its
/// mesh position with velocity (vx, 0); triangle 0 stays put.
void place_top(Engine& e, const ModelInput& in, double ux, double uy, double vx) {
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) {
      const int n = e.triangle_nodes(t)[k], v = in.triangles[t][k];
      e.set_node_state(n, in.x[v] + (t ? ux : 0), in.y[v] + (t ? uy : 0), t ? vx : 0, 0);
    }
}

// After its crack element breaks, the two triangles are a contact pair:
// pressed together they resist with about 6 p delta (two roles, phi =
// 3 delta / h over the shared edge, 5% for the tapered ends), and sliding
// while pressed they feel Coulomb friction mu F_n against the motion. While
// the element is intact they are no pair at all.
TEST(Contact, broken_crack_resists_interpenetration_and_slides_with_friction) {
  const double h = 0.01;
  Material m = test::rock();
  m.residual_friction_deg = 25;
  ModelInput in = test::two_triangles(h, m);
  in.contact = contact_on();
  Engine e(in);
  e.step();
  EXPECT_EQ(e.contact_counters().pairs, 0);
  const double op_range = 2 * h * m.tensile_strength / (10 * m.young) + 0.01;  // far beyond or
  place_top(e, in, 0, op_range, 0);
  e.step();
  ASSERT_EQ(e.crack_state(0), CrackState::kBroken);
  const double p = m.young, delta = 1e-6;
  place_top(e, in, 0, -delta, 0);
  e.step();
  EXPECT_EQ(e.contact_counters().pairs, 1);
  const auto f = triangle_force(e, 1);
  std::printf("pressed by %g m: %.5g N/m up (6 p delta = %.5g)\n", delta, f[1], 6 * p * delta);
  EXPECT_NEAR(f[1], 6 * p * delta, 0.05 * 6 * p * delta);
  // Slide to +x at 10 m/s while pressed: the spring saturates at mu F_n.
  const double mu = std::tan(25 * kPi / 180);
  for (int i = 0; i < 50; ++i) {  // 10 m/s: the velocity reset never reverses it
    place_top(e, in, 1e-4 + 10 * e.dt() * i, -delta, 10);
    e.step();
  }
  const auto g = triangle_force(e, 1);
  std::printf("sliding: tangential %.5g, normal %.5g, ratio %.4f (mu %.4f)\n", g[0], g[1],
              -g[0] / g[1], mu);
  EXPECT_NEAR(-g[0] / g[1], mu, 0.03 * mu);
}

// The same fracturing UCS with contact gives identical hashes, broken
// counts and contact counters with 1 and 2 threads.
TEST(Contact, fracturing_ucs_with_contact_same_hash_with_1_and_2_threads) {
  auto run = [](int threads) {
    RectangleSpec grid = ucs_grid(0.02, 0.04, 800);
    Material m = test::rock();
    m.damping_ratio = 0.1;
    ModelInput in = ucs_specimen(grid, m, 2.0);
    in.threads = threads;
    in.contact = contact_on();
    Engine e(in);
    e.run(5000);
    const ContactCounters c = e.contact_counters();
    return std::make_tuple(e.state_hash(), e.broken_counts().total(), c.pairs, c.touching,
                           c.detections, e.kinetic_energy());
  };
  const auto one = run(1), two = run(2);
  std::printf("broken %ld, pairs %ld, touching %ld, detections %ld\n", std::get<1>(one),
              std::get<2>(one), std::get<3>(one), std::get<4>(one));
  EXPECT_GT(std::get<1>(one), 0);
  EXPECT_GT(std::get<3>(one), 0) << "contact must act to test anything";
  EXPECT_EQ(one, two);
}

bool keep_by_parity(const void* context, int i, int j) {
  const auto& drop = *static_cast<const std::vector<char>*>(context);
  return !drop[(static_cast<std::size_t>(i) * 7919 + j) % drop.size()];
}

// The cell grid finds exactly the overlapping, accepted pairs that testing
// every pair finds: random boxes of mixed sizes (clustered and spread out),
// a random pair filter, several seeds and 1 and 2 threads.
TEST(Contact, grid_broad_phase_matches_brute_force) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(0, seed % 2 ? 1.0 : 50.0), size(0.001, 0.05);
    std::vector<double> boxes;
    const int n = 300 + 200 * seed;
    for (int i = 0; i < n; ++i) {
      const double x = pos(rng), y = pos(rng) * 0.5, w = size(rng), h = size(rng);
      boxes.insert(boxes.end(), {x, y, x + w, y + h});
    }
    std::vector<char> drop(97);
    for (auto& d : drop) d = rng() % 5 == 0;
    std::vector<std::array<int, 2>> brute, grid1, grid2;
    detail::brute_force_pairs(boxes, keep_by_parity, &drop, brute);
    detail::GridScratch s;
    detail::grid_pairs(boxes, keep_by_parity, &drop, 1, s, grid1);
    detail::grid_pairs(boxes, keep_by_parity, &drop, 2, s, grid2);
    if (seed % 2) {  // clustered seeds overlap
      EXPECT_GT(brute.size(), 0u);
    }
    EXPECT_EQ(grid1, brute) << "seed " << seed;
    EXPECT_EQ(grid2, brute) << "seed " << seed;
  }
}

/// Breaks crack element e in the current step, as crack_forces does.
void break_crack(detail::EngineData& d, int e) {
  d.cracks.state[e] = std::uint8_t(CrackState::kBroken);
  d.cracks.broken_step[e] = static_cast<std::int32_t>(d.step);
  d.cracks.broke_in_block[std::size_t(e / detail::kEnergyBlock)] = 1;  // as the crack pass marks
}

/// A fracture mesh of 12 x 12 squares over 2 cm, contact on and set up,
/// nothing detected: the broad phase's data without an engine (these tests
/// call the phases themselves).
detail::EngineData contact_square() {
  RectangleSpec spec;
  spec.width = spec.height = 0.02;
  spec.nx = spec.ny = 12;
  ModelInput in = structured_rectangle(spec, test::rock());
  detail::EngineData d;
  d.materials = in.materials;
  detail::build_topology(in, d);
  detail::resolve_edges(in, d);  // the vertex -> node lists
  d.threads = 1;
  d.contact.settings = contact_on();
  d.contact_on = true;
  detail::contact_setup(d);
  return d;
}

/// A pair (its triangles) with its friction springs.
using PairSprings = std::pair<std::array<int, 2>, std::array<double, 6>>;

/// The pairs with their springs in canonical order, whatever their layout.
std::vector<PairSprings> canonical_pairs(const detail::ContactData& c) {
  std::vector<PairSprings> out;
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    std::array<double, 6> f;
    std::copy_n(&c.friction[6 * q], 6, f.begin());
    out.push_back({c.pairs[q], f});
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Per contact triangle, its gathered entries as (pair, side) in the order
/// the gather sums them; and whether entry_row inverts the gather.
std::map<int, std::vector<std::pair<std::array<int, 2>, int>>> gathered(
    const detail::ContactData& c, bool& inverse) {
  std::map<int, std::vector<std::pair<std::array<int, 2>, int>>> out;
  inverse = c.entry_row.size() >= 2 * c.pairs.size();
  for (std::size_t g = 0; g < c.gather_tri.size(); ++g) {
    auto& list = out[c.gather_tri[g]];
    detail::each_gather_entry(c, long(g), [&](int e) {
      inverse = inverse && c.entry_row[e] == int(g) && c.pairs[e / 2][e % 2] == c.gather_tri[g];
      list.push_back({c.pairs[e / 2], e % 2});
    });
  }
  return out;
}

// Breakage updates the broad phase locally (contact_breaks): after a few
// random crack elements break, candidates, components, boxes, watched
// nodes, the pairs (in canonical order: a local update appends them) and
// each triangle's gathered entries, in the order it sums them, equal those
// of a full detection at the same positions (so the forces have the same
// bits), and the pairs that were there keep their friction springs.
// A fracture mesh with every node jiggled (faces open and overlap), a fifth
// of the crack elements broken beforehand, full detections between rounds
// after the nodes moved again.
TEST(Contact, local_update_after_breakage_equals_a_full_detection) {
  detail::EngineData d = contact_square();
  std::mt19937 rng(11);
  const double h = 0.02 / 12;  // the squares' side
  std::uniform_real_distribution<double> jiggle(-0.04 * h, 0.04 * h), spring(-1, 1);
  const int nc = static_cast<int>(d.cracks.size());
  for (int e = 0; e < nc; ++e)
    if (rng() % 5 == 0) break_crack(d, e);
  long local = 0, resorted = 0;  // updates that added pairs, that sorted them again
  for (int round = 0; round < 40; ++round) {
    if (round % 8 == 0) {  // move, detect in full
      for (double& x : d.nodes.pos) x += jiggle(rng);
      d.contact.dirty = true;
      detail::contact_detect(d);
    }
    for (double& f : d.contact.friction) f = spring(rng);
    const std::vector<PairSprings> before = canonical_pairs(d.contact);
    ++d.step;
    for (int k = 1 + round % 4; k > 0;) {
      const int e = static_cast<int>(rng() % nc);
      if (d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
      break_crack(d, e);
      --k;
    }
    detail::contact_breaks(d);
    ASSERT_FALSE(d.contact.dirty) << "round " << round << ": fell back to a full detection";
    local += d.contact.pairs.size() > before.size();
    resorted += d.contact.pairs.size() > before.size() && round % 8 != 0 &&
                d.contact.sorted_pairs == d.contact.pairs.size();
    detail::EngineData full = d;
    full.contact.dirty = full.contact.topology_dirty = true;
    detail::contact_detect(full);
    const detail::ContactData &a = d.contact, &b = full.contact;
    EXPECT_EQ(a.candidates, b.candidates) << "round " << round;
    EXPECT_EQ(a.boxes, b.boxes) << "round " << round;
    EXPECT_EQ(a.watch_nodes, b.watch_nodes) << "round " << round;
    EXPECT_EQ(b.sorted_pairs, b.pairs.size()) << "round " << round;
    const std::vector<PairSprings> now = canonical_pairs(a), full_pairs = canonical_pairs(b);
    ASSERT_EQ(now.size(), full_pairs.size()) << "round " << round;
    for (std::size_t q = 0, o = 0; q < now.size(); ++q) {
      EXPECT_EQ(now[q].first, full_pairs[q].first) << "round " << round;
      EXPECT_EQ(now[q].first, b.pairs[q]) << "round " << round;  // canonical after a detection
      EXPECT_EQ(now[q].second, full_pairs[q].second) << "round " << round;
      while (o < before.size() && before[o].first < now[q].first) ++o;
      const bool kept = o < before.size() && before[o].first == now[q].first;
      const std::array<double, 6> none{};
      EXPECT_EQ(now[q].second, kept ? before[o].second : none) << "round " << round;
    }
    bool inverse_a = false, inverse_b = false;
    EXPECT_EQ(gathered(a, inverse_a), gathered(b, inverse_b)) << "round " << round;
    EXPECT_TRUE(inverse_a && inverse_b) << "round " << round;
  }
  std::printf(
      "%ld of 40 local updates added pairs, %ld sorted them again; %zu candidates, "
      "%zu pairs\n",
      local, resorted, d.contact.candidates.size(), d.contact.pairs.size());
  EXPECT_GT(local, 20);
  EXPECT_GT(resorted, 0);
  EXPECT_LT(resorted, local);
  EXPECT_EQ(d.contact.updates, 40);
}

// The drift check measures the watched nodes only once a bound on their
// drift could exceed half the buffer (contact_force.cpp): the node loop adds
// the fastest node's speed times dt at each step, and a local update adds
// the drift its new candidates' nodes have had since the detection. Here the
// watched nodes creep and the others fly (so a new candidate's node has
// drifted far more than any measure saw), the bound is measured anew as the
// check does, crack elements break and detections come; at every step the
// bound is at least the largest drift of a watched node. Leaving out either
// term makes it fall below.
TEST(Contact, drift_bound_never_falls_below_the_largest_drift) {
  detail::EngineData d = contact_square();
  std::mt19937 rng(5);
  const int nc = static_cast<int>(d.cracks.size());
  for (int e = 0; e < nc; ++e)
    if (rng() % 4 == 0) break_crack(d, e);
  detail::contact_detect(d);
  // The node loop's needs: masses, its block sums, dt; no forces (the
  // slots hold zero), so each node keeps its velocity.
  d.nodes.mass.assign(d.nodes.size(), 1.0f);
  d.block_partial.assign(7 * (d.nodes.size() / detail::kNodeBlock + 1), 0.0);
  d.dt = 1e-6;
  std::uniform_real_distribution<double> unit(-1, 1);
  auto set_speeds = [&] {
    const auto& watched = d.contact.watch_nodes;
    for (std::size_t i = 0; i < d.nodes.size(); ++i) {
      const bool w = std::binary_search(watched.begin(), watched.end(), int(i));
      for (int k = 0; k < 2; ++k) d.nodes.vel[2 * i + k] = (w ? 1.0 : 50.0) * unit(rng);
    }
  };
  set_speeds();
  const double buffer = d.contact.buffer;
  double worst_margin = 1e300;
  for (int step = 1; step <= 200; ++step) {
    detail::node_update(d);  // as Engine::step: the loop, then contact's bound
    detail::contact_nodes_moved(d.contact, d.fastest_speed * d.dt);
    ++d.step;
    if (step % 7 == 0) {  // a measure, as the check makes once the bound is large
      const auto& w = d.contact.watch_nodes;
      d.contact.drift_bound = detail::bound_drift(
          std::sqrt(detail::largest_drift2(d, w.data(), long(w.size()))), buffer);
    }
    if (step % 5 == 0) {  // breaks: new candidates, fast nodes among them
      for (int k = 0; k < 3;) {
        const int e = static_cast<int>(rng() % nc);
        if (d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
        break_crack(d, e);
        ++k;
      }
      detail::contact_breaks(d);
    }
    if (step % 50 == 0) {  // a detection: drift starts again (from rounding)
      d.contact.dirty = true;
      detail::contact_detect(d);
      set_speeds();
    }
    const auto& w = d.contact.watch_nodes;
    const double drift = std::sqrt(detail::largest_drift2(d, w.data(), long(w.size())));
    ASSERT_GE(d.contact.drift_bound, drift) << "step " << step;
    worst_margin = std::min(worst_margin, (d.contact.drift_bound - drift) / buffer);
  }
  std::printf("smallest margin of the bound over the drift: %.3g buffers\n", worst_margin);
}

// Contact on, intact fracture specimen: candidates on the outline, no pairs,
// no narrow phase (the step costs only the drift check).
TEST(Contact, intact_body_has_no_pairs) {
  RectangleSpec grid = ucs_grid(0.02, 0.04, 400);
  ModelInput in = ucs_specimen(grid, test::rock(), 0.1);
  in.contact = contact_on();
  Engine e(in);
  e.run(100);
  const ContactCounters c = e.contact_counters();
  EXPECT_GT(c.candidates, 0);
  EXPECT_EQ(c.pairs, 0);
  EXPECT_FALSE(e.contact_active());
  EXPECT_EQ(c.steps_skipped, 100);
}

// Excavation: removing the core (set_active false) makes the ring around
// it a free surface. Candidates = active triangles with an edge on the
// outline or next to an inactive triangle, counted here independently from
// the mesh; the solid (shared-node) ring has no pairs.
TEST(Contact, excavation_boundary_becomes_a_free_surface) {
  RectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nx = spec.ny = 8;
  spec.fracture = false;
  ModelInput in = structured_rectangle(spec, test::rock());
  in.contact = contact_on();
  in.threads = 1;
  Engine e(in);
  std::vector<char> core(in.triangles.size(), 0);
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    double cx = 0, cy = 0;
    for (int v : in.triangles[t]) {
      cx += in.x[v] / 3;
      cy += in.y[v] / 3;
    }
    core[t] = std::fabs(cx - 0.5) < 0.25 && std::fabs(cy - 0.5) < 0.25;
  }
  // Expected candidates: active triangles with an edge that no other active
  // triangle shares.
  auto expected_candidates = [&] {
    long n = 0;
    for (std::size_t t = 0; t < in.triangles.size(); ++t) {
      if (core[t]) continue;
      bool free_edge = false;
      for (int k = 0; k < 3; ++k) {
        const int a = in.triangles[t][k], b = in.triangles[t][(k + 1) % 3];
        bool shared = false;
        for (std::size_t u = 0; u < in.triangles.size(); ++u) {
          if (u == t || core[u]) continue;
          int hits = 0;
          for (int v : in.triangles[u]) hits += v == a || v == b;
          shared = shared || hits == 2;
        }
        free_edge = free_edge || !shared;
      }
      n += free_edge;
    }
    return n;
  };
  e.step();
  const long outline = e.contact_counters().candidates;
  for (std::size_t t = 0; t < in.triangles.size(); ++t)
    if (core[t]) e.set_active(t, false);
  e.step();
  const ContactCounters c = e.contact_counters();
  EXPECT_EQ(c.candidates, expected_candidates());
  EXPECT_GT(c.candidates, outline);
  EXPECT_EQ(c.pairs, 0);
  EXPECT_EQ(c.detections, 2);
}

}  // namespace
}  // namespace rockfdem::fdem
