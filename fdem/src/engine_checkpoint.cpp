// The engine's checkpoint: which members are state (saved), which are the
// model (fingerprinted: built from the ModelInput and never changed) and
// which are neither (derived, scratch or a setting). Every member of every
// engine record appears below exactly once, and every list is checked
// against its record's member count at compile time: a new member fails
// the build here until it is listed. Format and framing:
// checkpoint_format.hpp.
//
// To add a member: one line in its record's list (ar.state / ar.model /
// ar.skip, and the count in that list's ROCKFDEM_CHECKPOINT_MEMBERS; the
// value records' each_member lists count themselves), and
// kCheckpointVersion + 1 when the saved bytes change.
#include <istream>
#include <ostream>

#include "checkpoint_format.hpp"
#include "engine_impl.hpp"

// A member count, with what to do when it changes.
#define ROCKFDEM_CHECKPOINT_MEMBERS(Record, n)                                    \
  static_assert(member_count<Record>() == (n), #Record                            \
                " gained or lost a member: classify it in engine_checkpoint.cpp " \
                "(state, model or skip) and update this count")

namespace rockfdem::fdem {
namespace detail {

// --- Value records (inside state or model members): all of their members ---

template <class Ar>
void fields(Ar& ar, Material& m) {
  each_member(ar, m, m.density, m.young, m.poisson, m.tensile_strength, m.cohesion, m.friction_deg,
              m.residual_friction_deg, m.gf_I, m.gf_II, m.normal_penalty, m.tangential_penalty,
              m.damping_ratio, m.crack_law, m.yield_strength, m.ultimate_strength,
              m.shear_yield_strength, m.jrc, m.jcs, m.weibull_modulus, m.heterogeneity_seed);
}

template <class Ar>
void fields(Ar& ar, SolidConstants& s) {
  each_member(ar, s, s.mu, s.lambda, s.rho, s.cp, s.cs, s.plane_strain);
}

template <class Ar>
void fields(Ar& ar, BoundaryRecord& r) {
  each_member(ar, r, r.x, r.y, r.vx, r.vy, r.cxx, r.cxy, r.cyy);
}

template <class Ar>
void fields(Ar& ar, NodalLoad& l) {
  each_member(ar, l, l.node, l.fx, l.fy);
}

template <class Ar>
void fields(Ar& ar, DeadLoads& l) {
  each_member(ar, l, l.dense, l.node, l.force, l.none_x, l.none_y);
}

template <class Ar>
void fields(Ar& ar, TagNodes& t) {
  each_member(ar, t, t.tag, t.nodes);
}

template <class Ar>
void fields(Ar& ar, DampingSettings& s) {
  each_member(ar, s, s.local, s.mass_proportional, s.kinetic);
}

template <class Ar>
void fields(Ar& ar, KineticDampingState& s) {
  each_member(ar, s, s.previous, s.rising, s.resets);
}

template <class Ar>
void fields(Ar& ar, MassScaling& s) {
  each_member(ar, s, s.enabled, s.dt);
}

template <class Ar>
void fields(Ar& ar, EnergyLedger& e) {
  each_member(ar, e, e.started, e.last_dt, e.initial, e.external, e.viscous, e.nodal_damping,
              e.contact_damping, e.kinetic_damping, e.absorbing, e.fracture, e.friction,
              e.joint_friction, e.softening, e.removed);
}

template <class Ar>
void fields(Ar& ar, ContactSettings& s) {
  each_member(ar, s, s.enabled, s.penalty, s.buffer, s.damping_ratio, s.friction);
}

// --- Engine records: each member classified -------------------------------------

template <class Ar>
void fields(Ar& ar, Nodes& n) {
  ROCKFDEM_CHECKPOINT_MEMBERS(Nodes, 9);
  ar.tag("NODE");
  ar.state(n.pos);
  ar.state(n.vel);
  ar.model(n.vertex_pos);
  ar.state(n.mass);  // rebuilt only when masses_dirty: saved as they are
  ar.state(n.fext);
  ar.state(n.bc_node);
  ar.model(n.vertex);
  ar.model(n.slot_start);
  ar.model(n.slot_index);
}

template <class Ar>
void fields(Ar& ar, Triangles& t) {
  ROCKFDEM_CHECKPOINT_MEMBERS(Triangles, 10);
  ar.tag("TRIS");
  ar.model(t.nodes);
  ar.state(t.ref_inv);  // set_active(..., kCurrent) re-references
  ar.state(t.area0);
  ar.model(t.eta);  // from the initial shape, set once
  ar.state(t.alpha);
  ar.state(t.sigma0);
  ar.model(t.material);
  ar.state(t.active);
  ar.state(t.viscous_stress);  // the energy ledger books its work at the next step
  ar.state(t.mass_scale);      // rebuilt only when masses_dirty, like the masses
}

template <class Ar>
void fields(Ar& ar, Cracks& c) {
  ROCKFDEM_CHECKPOINT_MEMBERS(Cracks, 12);
  ar.tag("CRAK");
  ar.model(c.nodes);
  ar.state(c.damage);
  ar.state(c.material);
  ar.state(c.state);
  ar.state(c.mode);
  ar.state(c.active);
  ar.state(c.broken_step);
  ar.skip(c.broke_in_block);  // scratch: each crack pass rewrites it before contact reads it
  ar.state(c.offset);
  ar.state(c.strength);     // set_crack_material draws again with the new material
  ar.state(c.joints);       // follows set_crack_material
  ar.state(c.joint_force);  // the energy ledger books its work at the next step
}

template <class Ar>
void fields(Ar& ar, ContactData& c) {
  ROCKFDEM_CHECKPOINT_MEMBERS(ContactData, 32);
  ar.tag("CONT");
  ar.state(c.settings);
  ar.state(c.penalty);  // set_contact may come after construction: all of it is state
  ar.state(c.buffer);
  ar.state(c.mu);
  ar.state(c.candidates);
  ar.state(c.boxes);
  ar.state(c.watch_nodes);
  ar.state(c.detect_shift);  // boxes of later candidates and the drift check start here
  ar.state(c.pairs);         // in their order (sorted, then appended), not detected again
  ar.state(c.sorted_pairs);  // where the appended ones start
  ar.state(c.friction);      // the tangential springs
  ar.state(c.pair_force);
  // The gather follows from the pairs and the candidates: rebuilt after loading.
  ar.skip(c.appended_order);
  ar.skip(c.gather_tri);
  ar.skip(c.gather_start);
  ar.skip(c.gather_entry);
  ar.skip(c.extra_head);
  ar.skip(c.extra_next);
  ar.skip(c.appended_rows);
  ar.skip(c.entry_row);
  ar.skip(c.grid);         // scratch: every detection rewrites it before reading it
  ar.skip(c.breaks);       // scratch: every local update rewrites it before reading it
  ar.skip(c.narrow);       // scratch: every contact pass rewrites it before reading it
  ar.skip(c.drift_bound);  // set unknown after loading: the first drift check measures
  ar.state(c.dirty);
  ar.state(c.topology_dirty);
  ar.state(c.detections);
  ar.state(c.steps_with_pairs);
  ar.state(c.steps_skipped);
  ar.state(c.touching);
  ar.state(c.updates);
  ar.state(c.energy_partial);  // scratch, but sized with the pairs at detection
}

template <class Ar>
void fields(Ar& ar, EngineData& d) {
  ROCKFDEM_CHECKPOINT_MEMBERS(EngineData, 36);  // reversal and gravity count twice
  fields(ar, d.nodes);
  fields(ar, d.tris);
  fields(ar, d.cracks);
  ar.tag("MATS");
  ar.model(d.solids);
  ar.skip(d.crack_laws);  // derived from materials
  ar.model(d.materials);
  ar.tag("BNDY");
  ar.state(d.bc_records);
  ar.model(d.edges);
  ar.model(d.vertex_node_start);
  ar.model(d.vertex_nodes);
  ar.state(d.loads);
  ar.state(d.tag_nodes);
  ar.tag("STEP");
  ar.state(d.masses_dirty);
  ar.state(d.slots);  // the last step's forces: node_force(), reactions, ratios
  ar.state(d.block_partial);
  ar.state(d.reversal);
  ar.skip(d.kinetic_after_step);  // the next node loop sums it before it is read
  ar.skip(d.fastest_speed);       // likewise
  ar.state(d.damping);
  ar.state(d.kinetic_damping);  // the peak test continues across a restart
  ar.state(d.mass_scaling);     // set_mass_scaling may come after construction
  ar.state(d.scaled_dt);        // resolved once, kept through stage changes
  ar.state(d.gravity);
  ar.state(d.contact_on);
  fields(ar, d.contact);
  ar.state(d.dt);
  ar.state(d.step);
  ar.state(d.broken_by_mode);
  ar.state(d.time);
  ar.state(d.dead_loads);
  ar.state(d.energy_partial);  // scratch, kept for its size
  ar.state(d.energy);          // the energy ledger: a restart's balance continues
  ar.skip(d.threads);          // a setting, not state: a restart may use another count
  ar.skip(d.crack_batch);      // a path, not state: both give the same bits
}

/// Engine::Impl is private to Engine: deduced here, never named.
template <class Ar, class Impl>
void impl_fields(Ar& ar, Impl& im) {
  ROCKFDEM_CHECKPOINT_MEMBERS(Impl, 9);
  fields(ar, im.d);
  ar.tag("IMPL");
  ar.skip(im.times);  // timings of this process: a restarted engine times its own steps
  ar.state(im.dt_safety);
  ar.state(im.critical_dt);  // the cached limit, as the uninterrupted run has it
  ar.state(im.auto_dt);
  ar.state(im.forced_dt);
  ar.state(im.reversals);
  ar.state(im.prestress_pending);
  ar.state(im.prestress_clipped);
}

}  // namespace detail

// --- Engine -------------------------------------------------------------------------

std::uint64_t Engine::model_fingerprint() const {
  detail::ModelHasher h;
  detail::impl_fields(h, *impl_);
  return h.value();
}

void Engine::save_state(std::ostream& out) const {
  detail::CheckpointSizer size;
  detail::impl_fields(size, *impl_);  // the archives only read the engine
  detail::CheckpointWriter w(out, model_fingerprint(), size.bytes());
  detail::impl_fields(w, *impl_);
  w.finish();
}

void Engine::load_state(std::istream& in) {
  const std::string file = detail::read_checkpoint(in);
  const std::uint64_t theirs = detail::checkpoint_fingerprint(file), ours = model_fingerprint();
  if (theirs != ours)
    throw InputError("fdem: checkpoint belongs to another model (fingerprint " +
                     detail::hex64(theirs) + ", this engine's is " + detail::hex64(ours) +
                     "); load it into an Engine built from the same ModelInput");
  // Read in place, not into a copy of the engine (which would double the
  // memory at a restart): the checker first walks the same members through
  // the same bytes without storing them, so every fault is found before
  // the reader changes anything. The model members and the thread count
  // stay this engine's.
  const std::size_t begin = detail::kCheckpointHeaderBytes,
                    end = file.size() - detail::kCheckpointChecksumBytes;
  detail::CheckpointChecker check(file, begin, end);
  detail::impl_fields(check, *impl_);
  check.finish();
  detail::CheckpointReader r(file, begin, end);
  detail::impl_fields(r, *impl_);
  r.finish();
  detail::build_gather(impl_->d);
  detail::contact_drift_unknown(impl_->d.contact);
}

}  // namespace rockfdem::fdem
