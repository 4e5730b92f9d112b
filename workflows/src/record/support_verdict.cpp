#include "record/support_verdict.hpp"

#include "record/number_text.hpp"

namespace rockfdem::workflows {
namespace {

// The lining's smallest safety factor, named with its part and place.
void check_lining(const LiningForceFigures& f, SupportVerdict& v) {
  if (!f.check) {
    v.notes.push_back("lining " + f.capacity);  // "not checked: why"
    return;
  }
  const LiningCapacityFigures& c = *f.check;
  if (!c.min_safety_factor || *c.min_safety_factor >= 1) return;
  std::string part = c.invert_compressive_strength_Pa
                         ? (c.min_safety_factor_in_invert ? "invert " : "arch and walls ")
                         : "";
  // A section with steel is named: its factor is of another diagram.
  const std::string& section =
      c.min_safety_factor_in_invert && c.invert_section ? *c.invert_section : c.section;
  if (section != "plain") part += "(" + section + ") ";
  v.findings.push_back("lining " + part + "SF " + fixed(*c.min_safety_factor, 2) + " at " +
                       fixed(c.min_safety_factor_angle_deg, 0) + " deg" +
                       (c.min_safety_factor_at_corner ? " (a corner)" : "") + ", " +
                       std::to_string(c.segments_below_1) + " of " + std::to_string(f.segments) +
                       " segments below 1");
}

// Bolts and cables whose steel broke (a station broken: one of its steel
// crack elements failed, in tension or in shear).
void check_bolts(const BoltRecord& b, SupportVerdict& v) {
  for (const char* kind : {"bolt", "cable"}) {
    long installed = 0, broken = 0;
    std::string names;
    for (const BoltFigures& f : b.each) {
      if (f.kind != kind || !f.installed) continue;
      ++installed;
      if (!f.peak || !f.peak->broken) continue;
      names += (broken++ ? ", " : "") + f.name;
    }
    if (broken > 0)
      v.findings.push_back(std::to_string(broken) + " of " + std::to_string(installed) + " " +
                           kind + "s with broken steel (" + names + ")");
  }
}

}  // namespace

std::string SupportVerdict::findings_text() const {
  std::string out;
  for (std::size_t i = 0; i < findings.size(); ++i) out += (i ? "; " : ": ") + findings[i];
  return out;
}

std::string SupportVerdict::line() const { return "support " + verdict + findings_text(); }

std::optional<SupportVerdict> support_verdict(const LiningRecord& lining,
                                              const std::optional<BoltRecord>& bolts) {
  const bool has_bolts = bolts && !bolts->each.empty();
  if (!lining.forces && !has_bolts) return std::nullopt;
  SupportVerdict v;
  if (lining.forces) check_lining(*lining.forces, v);
  if (has_bolts) check_bolts(*bolts, v);
  if (lining.interface && lining.interface->second > 0)
    v.notes.push_back("lining-rock bond: " + std::to_string(lining.interface->second) + " of " +
                      std::to_string(lining.interface->first) +
                      " bond elements broken (the ring slides on the rock there)");
  const bool checked = (lining.forces && lining.forces->check) || has_bolts;
  v.verdict = !v.findings.empty() ? "overstressed" : checked ? "holds" : "not checked";
  return v;
}

}  // namespace rockfdem::workflows
