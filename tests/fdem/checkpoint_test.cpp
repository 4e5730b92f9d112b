// Checkpoint: save_state / load_state restart a run bit for bit
// with another thread count, refuse truncated, corrupt, foreign-version and
// foreign-model states without touching the engine, and round-trip exactly.
//
// The scenario exercises every kind of state: a fracturing UCS specimen
// with heterogeneous strengths and an initial stress (crack pre-stress), contact and friction
// (enabled mid-run with its own settings), bolt-steel crack elements, triangles excavated and
// re-activated in their deformed shape (kCurrent), grout re-joining broken cracks, an explicit dt,
// and damping, stiffness, gravity and boundary conditions changed before and after the restarts.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "checkpoint_format.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr int kBoltSteel = 1, kGrout = 2;
constexpr long kSave = 600, kEnd = 1200;  // first cracks break near step 500

ModelInput scenario(int threads) {
  Material rock = test::rock();
  rock.damping_ratio = 0.1;
  rock.weibull_modulus = 3;  // heterogeneous strengths
  rock.heterogeneity_seed = 11;
  Material bolt = rock;  // a weak steel, so that it yields in so few steps
  bolt.crack_law = CrackLaw::kBoltSteel;
  bolt.yield_strength = 6e6;
  bolt.ultimate_strength = 8e6;
  bolt.shear_yield_strength = 8e6;
  bolt.weibull_modulus = 0;
  Material grout = rock;  // its own factors: a rejoined element draws again
  grout.tensile_strength = 1e6;
  grout.cohesion = 3e6;
  grout.heterogeneity_seed = 12;
  ModelInput in = ucs_specimen(ucs_grid(0.02, 0.04, 400), rock, 2.0);
  in.materials = {rock, bolt, grout};
  in.initial_stress.assign(in.triangles.size(), {-2e6, -2e6, 0.0});
  for (int t = 0; t < 8; ++t) in.initial_stress[t][0] = 8e6;  // beyond ft: clipped points
  in.threads = threads;                                       // contact: enabled at step 300
  return in;
}

std::size_t first_broken(const Engine& e) {
  for (std::size_t c = 0; c < e.n_cracks(); ++c)
    if (e.crack_state(c) == CrackState::kBroken) return c;
  ADD_FAILURE() << "no broken crack element at step " << e.step_count();
  return 0;
}

/// Platens at +-v, the left side on rollers (x fixed) or free, a pressure
/// on the right side.
std::vector<BoundaryCondition> sides(double v, bool rollers, double pressure) {
  std::vector<BoundaryCondition> bcs(4);
  bcs[0].tag = kTagBottom;
  bcs[1].tag = kTagTop;
  bcs[0].x = bcs[1].x = Constraint::kFixed;
  bcs[0].y = bcs[1].y = Constraint::kVelocity;
  bcs[0].vy = v;
  bcs[1].vy = -v;
  bcs[2].tag = kTagLeft;
  bcs[2].x = rollers ? Constraint::kFixed : Constraint::kFree;
  bcs[3].tag = kTagRight;
  bcs[3].pressure = pressure;
  return bcs;
}

/// The stage controls applied before step s: the same in every run.
void stage(Engine& e, long s) {
  const std::size_t core_a = e.n_triangles() / 2 + 3, core_b = e.n_triangles() / 2 - 40;
  const std::size_t soft = e.n_triangles() / 3;
  if (s == 0) {
    e.set_active(core_b, false);  // excavated
    for (std::size_t c = 0; c < e.n_cracks(); c += 5) e.set_crack_material(c, kBoltSteel);
  } else if (s == 300) {
    e.set_active(core_a, false);  // deformed by now: it keeps that shape
    e.set_damping({0.02, 0.0});
    e.set_stiffness_factor(soft, 0.5);
    e.set_gravity(0.0, -9.81);
    e.set_boundary_conditions(sides(1.5, true, 1e6));
    ContactSettings contact;
    contact.enabled = true;
    contact.penalty = 2e10;
    contact.damping_ratio = 0.05;
    e.set_contact(contact);
    e.set_mass_scaling({true, 0.0});  // rescaled at every later stage change
    e.set_dt(0.95 * e.stable_dt());
  } else if (s == 450) {
    e.set_active(core_a, true, ActivationReference::kCurrent);  // a lining
    e.set_initial_stress(core_a, {-1e5, -1e5, 0.0});
  } else if (s == 520) {
    e.rejoin_crack(first_broken(e), kGrout);
  } else if (s == 700) {
    e.set_active(core_b, true, ActivationReference::kCurrent);
  } else if (s == 800) {
    e.set_boundary_conditions(sides(1.0, false, 0.0));
    e.set_damping({0.0, 10.0, true});  // with kinetic damping from here on
  } else if (s == 900) {
    e.rejoin_crack(first_broken(e), kGrout);
    e.set_gravity(0.0, -19.62);
  }
}

/// Steps to `to`, calling stage(e, s) before each step s.
template <class Stage>
void advance(Engine& e, long to, Stage&& stage) {
  while (e.step_count() < to) {
    stage(e, e.step_count());
    e.step();
  }
}

std::string save(const Engine& e) {
  std::ostringstream out;
  e.save_state(out);
  return out.str();
}

void load(Engine& e, const std::string& bytes) {
  std::istringstream in(bytes);
  e.load_state(in);
}

/// The scenario's state at kSave (computed once for the tests below).
const std::string& saved_at_kSave() {
  static const std::string bytes = [] {
    Engine e(scenario(1));
    advance(e, kSave, stage);
    return save(e);
  }();
  return bytes;
}

/// Everything the engine reports, compared exactly.
struct Figures {
  std::string hash;
  long step;
  double time, dt, kinetic, unbalanced, strain, crack;
  std::array<double, 2> top, left;
  long mode_I, mode_II, mixed, clipped;
  double damage, broken_steps;
  long pairs, touching, detections, with_pairs, skipped;
  long kinetic_resets;
  auto tie() const {
    return std::tie(hash, step, time, dt, kinetic, unbalanced, strain, crack, top, left, mode_I,
                    mode_II, mixed, clipped, damage, broken_steps, pairs, touching, detections,
                    with_pairs, skipped, kinetic_resets);
  }
  bool operator==(const Figures& o) const { return tie() == o.tie(); }
  long broken() const { return mode_I + mode_II + mixed; }
};

std::ostream& operator<<(std::ostream& out, const Figures& f) {
  return out << "step " << f.step << " hash " << f.hash << " kinetic " << f.kinetic
             << " unbalanced " << f.unbalanced << " broken " << f.broken() << " damage " << f.damage
             << " touching " << f.touching << " detections " << f.detections;
}

Figures figures(const Engine& e) {
  Figures f;
  f.hash = e.state_hash();
  f.step = e.step_count();
  f.time = e.time();
  f.dt = e.dt();
  f.kinetic = e.kinetic_energy();
  f.unbalanced = e.unbalanced_force_ratio();
  f.strain = e.strain_energy();
  f.crack = e.crack_energy();
  f.top = e.boundary_force(kTagTop);
  f.left = e.boundary_force(kTagLeft);
  const BrokenCounts b = e.broken_counts();
  f.mode_I = b.mode_I;
  f.mode_II = b.mode_II;
  f.mixed = b.mixed;
  f.clipped = e.crack_prestress_clipped();
  f.damage = f.broken_steps = 0;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    f.damage += e.crack_damage(c);
    f.broken_steps += static_cast<double>(e.crack_broken_step(c));
  }
  const ContactCounters c = e.contact_counters();
  f.pairs = c.pairs;
  f.touching = c.touching;
  f.detections = c.detections;
  f.with_pairs = c.steps_with_pairs;
  f.skipped = c.steps_skipped;
  f.kinetic_resets = e.kinetic_damping_resets();
  return f;
}

/// Runs a model straight through with 1 thread (A), and again (B)
/// restarted at each of `restarts` from its saved state in a fresh engine of
/// the other thread count (2, 1, 2, ...). At a restart that step's stage
/// controls come before the save, so pending rebuilds and dirty flags are
/// saved too. Every figure must agree at each restart and at `end`, and so
/// must the whole state: the checkpoint holds no timings, so the two runs
/// write the same bytes. Returns A's figures at the restarts and at the end.
template <class Input, class Stage>
std::map<long, Figures> expect_restarts_match(Input&& input, const std::vector<long>& restarts,
                                              long end, Stage&& stage) {
  auto drive = [&](Engine e, auto&& at_restart) {
    for (long k : restarts) {
      advance(e, k, stage);
      stage(e, k);
      at_restart(k, e);
      e.step();
    }
    advance(e, end, stage);
    return e;
  };
  std::map<long, Figures> at;
  std::map<long, std::string> state_at;
  const Engine a = drive(Engine(input(1)), [&](long k, Engine& e) {
    at[k] = figures(e);
    state_at[k] = save(e);
  });
  int threads = 2;
  const Engine b = drive(Engine(input(threads)), [&](long k, Engine& e) {
    EXPECT_EQ(figures(e), at[k]) << "before the save at " << k;
    const std::string state = save(e);
    EXPECT_TRUE(state == state_at[k]) << "the two runs' states differ at " << k;
    threads = 3 - threads;
    Engine restarted(input(threads));
    load(restarted, state);
    EXPECT_EQ(restarted.threads(), threads) << "the thread count is a setting, not state";
    EXPECT_EQ(figures(restarted), at[k]) << "right after the load at " << k;
    e = std::move(restarted);
  });
  at[end] = figures(a);
  EXPECT_EQ(figures(b), at[end]) << "at the end";
  EXPECT_TRUE(save(b) == save(a)) << "the restarted run's final state differs";
  return at;
}

// The fracturing scenario restarted at five steps, two of them right after
// stage changes (mass scaling is on from step 300, so every later change
// rescales the masses). The save at kSave is checked to hold broken cracks,
// touching contact pairs with friction, clipped pre-stress points and a
// damaged bolt-steel crack, so that a state left out would show.
TEST(Checkpoint, restart_continues_bit_for_bit_with_another_thread_count) {
  const auto at = expect_restarts_match(scenario, {450, kSave, kSave + 1, 900, 1000}, kEnd, stage);
  const Figures& f = at.at(kSave);
  std::printf(
      "at step %ld: %ld broken, %ld pairs, %ld touching, %ld pre-stress points "
      "clipped; at the end: %s, %ld broken, kinetic damping resets %ld (%ld at step 900)\n",
      kSave, f.broken(), f.pairs, f.touching, f.clipped, at.at(kEnd).hash.c_str(),
      at.at(kEnd).broken(), at.at(kEnd).kinetic_resets, at.at(900).kinetic_resets);
  EXPECT_GT(f.broken(), 0) << "nothing broke by the save";
  EXPECT_GT(f.touching, 0) << "no contact pair touches at the save";
  EXPECT_GT(f.clipped, 0) << "no crack point was clipped by the pre-stress";
  EXPECT_GT(at.at(900).kinetic_resets, 0) << "kinetic damping never reset before step 900";
  EXPECT_GT(at.at(kEnd).kinetic_resets, at.at(1000).kinetic_resets)
      << "kinetic damping never reset after the last restart";
  Engine e(scenario(1));
  load(e, saved_at_kSave());
  double bolt_damage = 0;
  for (std::size_t c = 0; c < e.n_cracks(); c += 5) bolt_damage += e.crack_damage(c);
  EXPECT_GT(bolt_damage, 0.0) << "no bolt-steel crack element yielded by the save";
}

/// A block pressed (0.5 MPa) onto a fixed block, friction angle 20 deg; the
/// upper block is made of crack-jointed triangles (which stay intact), so
/// that its outline's neighbours are told apart by their crack components.
ModelInput pressed_blocks(int threads) {
  Material m = test::rock();
  m.residual_friction_deg = 20;
  ModelInput in = test::two_blocks(0.0, m);
  for (std::size_t t = 2 * (in.triangles.size() / 3); t < in.triangles.size(); ++t)
    in.fracture[t] = 1;
  BoundaryCondition press;
  press.tag = kTagTop + 10;
  press.pressure = 0.5e6;
  in.boundary_conditions.push_back(press);
  in.contact.enabled = true;
  in.threads = threads;
  return in;
}

/// Throws the upper block sideways at 5 m/s before the first step.
void throw_sideways(Engine& e, long s) {
  if (s != 0) return;
  for (std::size_t t = 2 * (e.n_triangles() / 3); t < e.n_triangles(); ++t)
    for (int n : e.triangle_nodes(t))
      e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], 5.0, 0.0);
}

// The block slides, decelerated by friction, and sticks. No crack breaks,
// so contact is detected again only when the block has drifted: a restart
// must bring back the candidates, watched positions, pairs and friction
// springs as they were, not detect them afresh.
TEST(Checkpoint, sliding_contact_restarts_with_its_springs_and_detection_state) {
  const long end = 3000;
  const auto at = expect_restarts_match(pressed_blocks, {200, 900, 901, 2000}, end, throw_sideways);
  for (const auto& [k, f] : at)
    std::printf("step %ld: touching %ld, detections %ld, kinetic %.6g\n", k, f.touching,
                f.detections, f.kinetic);
  EXPECT_EQ(at.at(end).broken(), 0);
  EXPECT_GT(at.at(900).touching + at.at(2000).touching, 0);
  EXPECT_GT(at.at(end).detections, at.at(901).detections) << "no detection by drift after 901";
}

/// Rewrites the trailing checksum to match the contents: a forged file that
/// only the section checks can refuse.
std::string with_checksum(std::string bytes) {
  detail::Fnv1a sum;
  sum.add(bytes.data(), bytes.size() - 8);
  const std::uint64_t h = sum.value();
  std::memcpy(&bytes[bytes.size() - 8], &h, sizeof h);
  return bytes;
}

void expect_refused(Engine& e, const std::string& bytes, const std::string& message) {
  const std::string hash = e.state_hash(), before = save(e);
  try {
    load(e, bytes);
    ADD_FAILURE() << "loaded a bad state (expected: " << message << ")";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find(message), std::string::npos) << err.what();
  }
  EXPECT_EQ(e.state_hash(), hash);
  EXPECT_TRUE(save(e) == before) << "a failed load changed the engine";
}

// Every refusal is an InputError naming the cause, and leaves the engine
// exactly as it was (same hash, same saved bytes).
TEST(Checkpoint, truncated_corrupt_or_foreign_state_is_refused_and_engine_unchanged) {
  const std::string& good = saved_at_kSave();
  Engine e(scenario(1));
  e.run(20);
  // Truncated: 50 cut points over the whole file, and the last byte.
  for (int i = 0; i <= 50; ++i) {
    const std::size_t cut = i == 50 ? good.size() - 1 : good.size() * i / 50;
    expect_refused(e, good.substr(0, cut), "truncated at byte " + std::to_string(cut));
  }
  // One byte changed anywhere (header, payload, checksum).
  for (int i = 0; i < 20; ++i) {
    std::string bad = good;
    const std::size_t at = 24 + (bad.size() - 24) * i / 19 - (i == 19 ? 1 : 0);
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    expect_refused(e, bad, "corrupt");
  }
  // Found wrong only while the state is read in (the last section's tag,
  // with a valid checksum): the members read so far must not stick.
  std::string forged = good;
  forged[forged.rfind("IMPL") + 3] = 'X';
  expect_refused(e, with_checksum(forged), "section 'IMPL' expected");
  std::string other_order = good;
  std::swap(other_order[8], other_order[11]);
  expect_refused(e, other_order, "other byte order");
  std::string other_version = good;
  other_version[12] = 99;
  expect_refused(e, other_version, "engine format version 99; this build reads");
  expect_refused(e, "not a checkpoint at all", "not a rockfdem engine checkpoint");
  // A model of another mesh, and of another crack material.
  ModelInput coarse = ucs_specimen(ucs_grid(0.02, 0.04, 200), test::rock(), 2.0);
  coarse.materials = scenario(1).materials;
  Engine other(coarse);
  expect_refused(other, good, "belongs to another model (fingerprint");
  ModelInput weaker = scenario(1);
  weaker.materials[kGrout].tensile_strength *= 0.9;
  Engine other_grout(weaker);
  expect_refused(other_grout, good, "belongs to another model (fingerprint");
  // The engine still loads a good state after all that.
  load(e, good);
  EXPECT_EQ(e.step_count(), kSave);
}

// A loaded state saves to the very same bytes, and saving twice does too.
TEST(Checkpoint, save_load_save_gives_identical_bytes) {
  const std::string& first = saved_at_kSave();
  Engine e(scenario(2));
  load(e, first);
  const std::string second = save(e);
  EXPECT_EQ(second.size(), first.size());
  EXPECT_TRUE(second == first) << "the loaded engine saves other bytes";
  EXPECT_TRUE(save(e) == second);
}

// A restart reads into the engine's own arrays rather than into a copy of
// the engine (which would double the memory at a restart): the node arrays,
// of the same length before and after, keep their storage, and the state
// is the saved one.
TEST(Checkpoint, load_reads_in_place_into_the_engines_arrays) {
  Engine e(scenario(2));
  e.run(20);
  const double* pos = e.positions().data();
  const double* vel = e.velocities().data();
  load(e, saved_at_kSave());
  EXPECT_EQ(e.positions().data(), pos) << "the positions were read into another array";
  EXPECT_EQ(e.velocities().data(), vel) << "the velocities were read into another array";
  EXPECT_EQ(e.step_count(), kSave);
  EXPECT_TRUE(save(e) == saved_at_kSave()) << "the state read in place saves other bytes";
}

// Equal for engines of the same input, whatever the thread count; different
// for another mesh or another material constant.
TEST(Checkpoint, fingerprint_tracks_mesh_and_materials_not_threads) {
  const std::uint64_t base = Engine(scenario(1)).model_fingerprint();
  EXPECT_EQ(Engine(scenario(2)).model_fingerprint(), base);
  ModelInput moved = scenario(1);
  moved.x[5] += 1e-6;
  EXPECT_NE(Engine(moved).model_fingerprint(), base);
  ModelInput stiffer = scenario(1);
  stiffer.materials[0].young *= 1.01;
  EXPECT_NE(Engine(stiffer).model_fingerprint(), base);
}

}  // namespace
}  // namespace rockfdem::fdem
