// report.md, as an engineer reads it: written at the end of a tunnel run,
// its figures the summary's, the scene's references compared, the
// pictures it links present.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "outputs/run_report.hpp"
#include "outputs/run_timeline.hpp"
#include "record/summary.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

// The cells of the Markdown table row that starts with "| `name` |".
std::vector<std::string> row_of(const std::string& md, const std::string& name) {
  const std::size_t at = md.find("\n| " + name + " |");
  if (at == std::string::npos) return {};
  const std::string line = md.substr(at + 1, md.find('\n', at + 1) - at - 1);
  std::vector<std::string> cells;
  std::size_t from = 1;
  for (std::size_t bar = line.find('|', from); bar != std::string::npos;
       from = bar + 1, bar = line.find('|', from)) {
    const std::string cell = line.substr(from, bar - from);
    const std::size_t first = cell.find_first_not_of(' ');
    cells.push_back(first == std::string::npos
                        ? std::string()
                        : cell.substr(first, cell.find_last_not_of(' ') - first + 1));
  }
  return cells;
}

// history.csv's first row (the hand-off step), by column name.
std::map<std::string, double> first_history_row(const fs::path& csv) {
  std::istringstream in(read_text(csv));
  std::string header, line, name, value;
  std::getline(in, header);
  std::getline(in, line);
  std::map<std::string, double> row;
  std::istringstream names(header), values(line);
  while (std::getline(names, name, ',') && std::getline(values, value, ','))
    row[name] = std::stod(value);
  return row;
}

// A stage's report entry as the timeline reads it: kind, duration, changes.
rockfdem::workflows::StageRecord stage_record(
    const std::string& kind, double simulated_time,
    const rockfdem::workflows::StageChanges& changes = {}) {
  rockfdem::workflows::StageRecord r;
  r.kind = kind;
  r.simulated_time = simulated_time;
  r.changes = changes;
  return r;
}

// A grout stage's changes: triggered or not, and how many it re-joined.
rockfdem::workflows::StageChanges grouting(bool triggered, std::optional<long> rejoined) {
  rockfdem::workflows::StageChanges c;
  c.triggered = triggered;
  c.rejoined = rejoined;
  return c;
}

std::string two_decimals(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

}  // namespace

// The supported circular tunnel (lining, 8 bolts) for 1000 steps of
// equilibrium: too few to settle, so the report says "not at equilibrium"
// as the summary does. Each key point's radial displacement in the report
// is the summary's to the 0.01 mm shown; the vault's reference (5 mm,
// given on the command line) appears with the difference computed - 5.
TEST(Report, tunnel_run_writes_a_report_with_the_summary_figures) {
  const fs::path out = scratch("report");
  const bool xvfb = !std::string(ROCKFDEM_XVFB_RUN).empty();
  const std::string prefix =
      xvfb ? std::string(ROCKFDEM_XVFB_RUN) + " -n " + std::to_string(100 + getpid() % 800) + " -a"
           : "";
  const Result r = run("run " + kTestDir +
                           "/support_pair_supported.toml -j 1 -q --set 'stages[4].max_steps=1000'"
                           " --set references.vault=5.0 --set 'references.source=\"a test\"'"
                           " --set output.plots=" +
                           std::string(xvfb ? "true" : "false") + " -o " + out.string(),
                       prefix);
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  ASSERT_TRUE(fs::exists(out / "report.md"));
  const std::string md = read_text(out / "report.md");
  EXPECT_NE(md.find("**" + j["status"].get<std::string>() + "**"), std::string::npos) << md;
  if (j.contains("status_reason")) {
    EXPECT_NE(md.find(j["status_reason"].get<std::string>()), std::string::npos);
  }
  for (const char* p :
       {"vault", "left_shoulder", "right_shoulder", "left_wall", "right_wall", "invert"}) {
    const auto cells = row_of(md, p);
    ASSERT_GE(cells.size(), 6u) << p << " in\n" << md;
    EXPECT_EQ(cells[1], two_decimals(j["monitors"][p]["radial_mm"].get<double>())) << p;
  }
  // The lining is installed right after the hand-off step, whose history
  // row is the origin of "since support": the summary's figure less that
  // row's; the row itself is the implicit stage's share ("at hand-off").
  const auto handoff = first_history_row(out / "history.csv");
  for (const char* p : {"vault", "left_wall", "invert"}) {
    const double at = handoff.at(std::string(p) + "_radial_mm");
    EXPECT_EQ(row_of(md, p)[2], two_decimals(at)) << p;
    // history.csv holds 10 significant digits
    EXPECT_NEAR(j["monitors"][p]["radial_at_handoff_mm"].get<double>(), at, 1e-9 * std::abs(at))
        << p;
    const double total = j["monitors"][p]["radial_mm"].get<double>();
    EXPECT_NEAR(j["monitors"][p]["explicit_share"].get<double>(), (total - at) / total, 1e-8);
  }
  for (const char* p : {"vault", "left_wall", "invert"})
    EXPECT_NEAR(
        std::stod(row_of(md, p)[3]),
        j["monitors"][p]["radial_mm"].get<double>() - handoff.at(std::string(p) + "_radial_mm"),
        0.0051 + 1e-9 * std::abs(handoff.at(std::string(p) + "_radial_mm")))
        << p;
  const auto vault = row_of(md, "vault");
  EXPECT_EQ(vault[4], "5.00");
  const double computed = j["monitors"]["vault"]["radial_mm"].get<double>();
  EXPECT_EQ(vault[5].substr(0, vault[5].find(' ')), two_decimals(computed - 5.0)) << vault[5];
  // The rock set's figures, as summary.json has them: c 3 MPa, phi 30 deg
  // give UCS = 6 sqrt(3) MPa; E 3 GPa, ft 1 MPa.
  const nlohmann::json& rock = j["rock_plausibility"];
  EXPECT_NEAR(rock["ucs_Pa"].get<double>(), 6e6 * std::sqrt(3.0), 1.0);
  EXPECT_NEAR(rock["figures"]["ucs_over_young"]["value"].get<double>(), 6e6 * std::sqrt(3.0) / 3e9,
              1e-12);
  EXPECT_EQ(row_of(md, "ucs_over_young")[1], "0.00346") << md;
  EXPECT_EQ(row_of(md, "ft_over_ucs")[3], "yes");
  EXPECT_EQ(row_of(md, "wall_chord")[1],
            two_decimals(j["monitors"]["wall_chord_convergence_mm"].get<double>()));
  EXPECT_NE(md.find("a test"), std::string::npos);
  // The lining and broken-zone tables carry the summary's figures with units.
  const nlohmann::json& lining = j["lining"];
  EXPECT_EQ(row_of(md, "lining-rock bond")[1],
            std::to_string(lining["interface_broken"].get<long>()) + " of " +
                std::to_string(lining["interface_cracks"].get<long>()) + " crack elements broken");
  const std::string thrust_at =
      "at " + std::to_string(std::lround(lining["max_thrust_angle_deg"].get<double>())) + " deg";
  EXPECT_NE(row_of(md, "largest thrust")[2].find(thrust_at), std::string::npos) << md;
  const double thrust = lining["max_thrust_kN_per_m"].get<double>();
  EXPECT_NEAR(std::stod(row_of(md, "largest thrust")[1]), thrust, 0.005 * std::abs(thrust));
  EXPECT_EQ(row_of(md, "deepest from the opening")[1],
            two_decimals(j["broken_zone"]["depth_m"].get<double>()) + " m");
  const long all = j["broken"]["mode_I"].get<long>() + j["broken"]["mode_II"].get<long>() +
                   j["broken"]["mixed"].get<long>();
  const std::string broken = row_of(md, "broken crack elements, all")[1];
  EXPECT_EQ(broken.substr(0, broken.find(' ')), std::to_string(all));
  // Every bolt of the summary has its row.
  for (const auto& b : j["bolts"]["each"])
    EXPECT_FALSE(row_of(md, b["name"].get<std::string>()).empty()) << b["name"];
  // The pictures it links exist.
  const std::regex link(R"(!\[[^\]]*\]\(([^)]+)\))");
  int links = 0;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), link); it != std::sregex_iterator();
       ++it, ++links)
    EXPECT_TRUE(fs::exists(out / (*it)[1].str())) << (*it)[1];
  if (xvfb) {
    EXPECT_GE(links, 7) << md;
  }
  fs::remove_all(out);
}

// A run that fails (a forced dt of 2 ms inverts a triangle at step 3)
// still leaves its report: status "failed" with the diagnostic, and the
// key points of the last good state the summary reports.
// report.md's continuum section gives each key point's radial displacement
// of the FDEM and of its continuum counterpart: summary.json's
// continuum_comparison [ux, uy] projected on the key point's inward
// direction (monitors.<point>.inward), to the 0.01 mm the table prints.
TEST(Report, continuum_and_convergence_confinement_sections_project_the_summary) {
  const fs::path out = scratch("report-continuum");
  const Result r = run("run " + kTestDir + "/grout_trigger.toml -q -j 1 -o " + out.string() +
                       " --set stages[4].trigger_steps=20");
  ASSERT_TRUE(r.code == 0 || r.code == 4) << r.output;  // 4: not at equilibrium
  const nlohmann::json j = read_json(out / "summary.json");
  const std::string md = read_text(out / "report.md");
  const std::size_t at = md.find("## The continuum counterpart");
  ASSERT_NE(at, std::string::npos) << md;
  const std::string section = md.substr(at, md.find("\n## ", at + 1) - at);
  const nlohmann::json& c = j.at("continuum_comparison").at("key_points");
  for (const char* p :
       {"vault", "left_shoulder", "right_shoulder", "left_wall", "right_wall", "invert"}) {
    const nlohmann::json& in = j.at("monitors").at(p).at("inward");
    const auto radial = [&](const char* key) {
      const nlohmann::json& u = c.at(p).at(key);
      return u[0].get<double>() * in[0].get<double>() + u[1].get<double>() * in[1].get<double>();
    };
    const auto cells = row_of(section, p);
    ASSERT_EQ(cells.size(), 4u) << p << " in\n" << section;
    EXPECT_NEAR(std::stod(cells[1]), radial("fdem_end_mm"), 0.006) << p;
    EXPECT_NEAR(std::stod(cells[2]), radial("continuum_end_mm"), 0.006) << p;
    EXPECT_NEAR(std::stod(cells[3]), radial("fdem_end_mm") - radial("continuum_end_mm"), 0.006)
        << p;
  }
  // Convergence-confinement: each support line's meeting with the ground
  // as summary.json states it.
  const std::size_t cc = md.find("## Convergence-confinement");
  ASSERT_NE(cc, std::string::npos) << md;
  const std::string lines = md.substr(cc, md.find("\n## ", cc + 1) - cc);
  const nlohmann::json& eq = j.at("convergence_confinement").at("equilibrium");
  ASSERT_FALSE(eq.empty());
  for (const nlohmann::json& e : eq) {
    const auto cells = row_of(lines, e.at("name").get<std::string>());
    ASSERT_EQ(cells.size(), 8u) << lines;
    if (!e.at("found").get<bool>()) continue;
    EXPECT_NEAR(std::stod(cells[4]), e.at("radial_mm").get<double>(), 0.06) << cells[0];
    if (e.at("factor_of_safety").is_number()) {
      EXPECT_NEAR(std::stod(cells[6]), e.at("factor_of_safety").get<double>(), 0.006) << cells[0];
    }
  }
  fs::remove_all(out);
}

TEST(Report, failed_run_reports_its_last_good_state) {
  const fs::path out = scratch("report-failed");
  const Result r = run("run " + kTestDir +
                       "/support_pair_supported.toml -j 1 -q --force-dt --set engine.dt=0.002 -o " +
                       out.string());
  ASSERT_EQ(r.code, 3) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  ASSERT_EQ(j["status"], "failed");
  const std::string md = read_text(out / "report.md");
  EXPECT_NE(md.find("**failed**: " + j["failure"].get<std::string>()), std::string::npos) << md;
  EXPECT_EQ(row_of(md, "vault")[1],
            two_decimals(j["monitors"]["vault"]["radial_mm"].get<double>()));
  fs::remove_all(out);
}

// A scene's title is free text; ESC sequences, a BEL, a NUL and a C1 CSI
// in it reach report.md as escapes (summary.json escapes them as JSON
// does). report.md holds no control byte but line breaks.
TEST(Report, control_bytes_of_a_title_are_escaped_in_the_report) {
  const fs::path out = scratch("report-title");
  const Result r = run("run " + kTestDir +
                       "/study_elastic.toml -j 1 -q --set 'model.title=\"Tunnel "
                       "\\u001b[2J\\u001b]0;pwned\\u0007 A\\u0000B\\u009b1m\"' -o " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string md = read_text(out / "report.md");
  EXPECT_NE(md.find("# Run report: Tunnel \\x1b[2J\\x1b]0;pwned\\x07 A\\x00B\\u009b1m\n"),
            std::string::npos)
      << md.substr(0, 200);
  for (std::size_t i = 0; i < md.size(); ++i) {
    const auto c = static_cast<unsigned char>(md[i]);
    const bool c1 =
        c == 0xC2 && i + 1 < md.size() && (static_cast<unsigned char>(md[i + 1]) & 0xE0) == 0x80;
    ASSERT_FALSE((c < 0x20 && c != '\n') || c == 0x7F || c1) << "byte " << int(c) << " at " << i;
  }
  fs::remove_all(out);
}

// The seed's sequence as the summary reports it: three stages of no steps
// at the hand-off (t = 0.5 ms), a grout stage of 4.8 ms that grouted 324
// cracks, then equilibrium. One marker holds the three with the grout
// stage's start; the grouting and the equilibrium's start share the next.
TEST(StageMarkers, stages_starting_together_share_a_marker_and_grouting_has_its_own) {
  using rockfdem::workflows::StageRecord;
  const std::vector<StageRecord> stages = {
      stage_record("lining", 0.0), stage_record("bolts", 0.0), stage_record("remove_core", 0.0),
      stage_record("grout", 0.0048, grouting(true, 324)), stage_record("equilibrium", 0.736)};
  using namespace rockfdem::workflows;
  const std::vector<StageSpan> spans = stage_spans(stages, 0.0005);
  const auto markers = stage_markers(spans);
  ASSERT_EQ(markers.size(), 2u);
  EXPECT_EQ(markers[0].x, 0.0005);
  EXPECT_EQ(markers[0].label, "lining, bolts, remove_core, grout");
  EXPECT_DOUBLE_EQ(markers[1].x, 0.0053);
  EXPECT_EQ(markers[1].label, "grouting: 324 broken cracks re-joined, equilibrium");
  ASSERT_NE(support_stage(spans), nullptr);
  EXPECT_EQ(support_stage(spans)->kind, "lining");
  // Rows at the hand-off and every 1000 steps: the support's row is the
  // hand-off's, found despite the stage times' rounding.
  EXPECT_EQ(row_at({0.0005, 0.0053, 0.37, 0.74}, 0.0005 + 1e-15), 0u);
  EXPECT_EQ(row_at({0.0005, 0.0053, 0.37, 0.74}, 0.0053 - 1e-12), 1u);
  EXPECT_EQ(since_row({3.0, 5.0, 9.0}, 1), (std::vector<double>{0.0, 4.0}));
}

// The seed's sequence on the step axis (hand-off at step 1): a band per
// stage that took steps, numbered; the three stages of no steps named at
// the head of the grout band's label, the grouting's count at its end.
TEST(StageBands, stages_of_no_steps_join_the_next_band_and_grouting_is_counted) {
  using rockfdem::workflows::StageRecord;
  std::vector<StageRecord> stages = {
      stage_record("lining", 0.0), stage_record("bolts", 0.0), stage_record("remove_core", 0.0),
      stage_record("grout", 0.0048, grouting(true, 324)), stage_record("equilibrium", 0.736)};
  const long steps[] = {0, 0, 0, 14, 9000};
  for (std::size_t i = 0; i < stages.size(); ++i) {
    stages[i].number = int(i) + 1;
    stages[i].steps = steps[i];
  }
  using namespace rockfdem::workflows;
  const auto bands = stage_bands(stage_spans(stages, 0.0005, 1));
  ASSERT_EQ(bands.size(), 2u);
  EXPECT_EQ(bands[0].x0, 1);
  EXPECT_EQ(bands[0].x1, 15);
  EXPECT_EQ(bands[0].label,
            "1 lining, 2 bolts, 3 remove_core, then 4 grout (324 cracks re-joined)");
  EXPECT_EQ(bands[1].x0, 15);
  EXPECT_EQ(bands[1].x1, 9015);
  EXPECT_EQ(bands[1].label, "5 equilibrium");
}

// A grout stage that did not trigger adds no grouting marker; a run
// without lining or bolts stages has no support to measure from.
TEST(StageMarkers, untriggered_grout_and_no_support) {
  using rockfdem::workflows::StageRecord;
  const std::vector<StageRecord> stages = {stage_record("remove_core", 0.0),
                                           stage_record("grout", 0.1, grouting(false, {})),
                                           stage_record("equilibrium", 0.2)};
  using namespace rockfdem::workflows;
  const std::vector<StageSpan> spans = stage_spans(stages, 0.0);
  const auto markers = stage_markers(spans);
  ASSERT_EQ(markers.size(), 2u);
  EXPECT_EQ(markers[0].label, "remove_core, grout");
  EXPECT_EQ(markers[1].label, "equilibrium");
  EXPECT_DOUBLE_EQ(markers[1].x, 0.1);
  EXPECT_EQ(support_stage(spans), nullptr);
}

// A checkpoint keeps the stages' reports as summary.json writes them; a
// restart reads them back field for field. A stage that took no step has
// no dt, settle, verdict or moving key point: null in the file, none again.
TEST(StageRecords, checkpoint_copy_reads_back_every_field) {
  using namespace rockfdem::workflows;
  StageRecord none = stage_record("lining", 0.0);
  none.max_steps = 0;
  // Named changes of each kind, and a stage kind's own by name.
  StageChanges changes = grouting(true, 70);
  changes.positions_file = "grouted_cracks.csv";
  changes.trigger = "trigger_broken_growth";  // the trigger and its moment
  changes.trigger_value = 1.5;
  changes.trigger_step = 1234;
  changes.trigger_time = 0.0625;
  changes.broken_at_support = 45;
  changes.other = {{"released", 0.5}, {"stepped", true}, {"count", 3L}, {"note", "x"}};
  StageRecord full = stage_record("equilibrium", 0.736, changes);
  full.steps = 2000;
  full.dt = 3.68e-4;
  full.unbalanced_ratio = 1.12e-3;
  full.settle = 0.532;
  full.converged = false;
  full.max_steps = 2000;
  full.ratio = 1e-3;
  full.settle_limit = 1e-3;
  full.hold = 3;
  full.unstable_fraction = 0.1;
  full.moving_most = MovingMost{"invert", 18.3};
  full.support_pressure_ratio = 0.25;
  const nlohmann::json j = stage_records_json({none, full});
  EXPECT_TRUE(j[0]["dt"].is_null());
  EXPECT_TRUE(j[0]["converged"].is_null());
  EXPECT_TRUE(j[0]["moving_most"].is_null());
  EXPECT_EQ(j[1]["criteria"]["hold"], 3);
  EXPECT_EQ(j[1]["moving_most"]["key_point"], "invert");
  EXPECT_EQ(j[0]["changes"], nlohmann::json::object());
  EXPECT_EQ(j[1]["changes"].dump(),
            R"({"broken_at_support":45,"count":3,"note":"x","positions_file":"grouted_cracks.csv",)"
            R"("rejoined":70,"released":0.5,"stepped":true,"trigger":"trigger_broken_growth",)"
            R"("trigger_step":1234,"trigger_time":0.0625,"trigger_value":1.5,"triggered":true})");
  const std::vector<StageRecord> back = stage_records_from_json(nlohmann::json::parse(j.dump()));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_FALSE(back[0].dt || back[0].settle || back[0].converged || back[0].moving_most);
  const StageRecord& b = back[1];
  EXPECT_EQ(b.kind, "equilibrium");
  EXPECT_EQ(b.changes.triggered, std::optional<bool>(true));
  EXPECT_EQ(b.changes.rejoined, std::optional<long>(70));
  EXPECT_EQ(b.changes.positions_file, full.changes.positions_file);
  EXPECT_EQ(b.changes.trigger, full.changes.trigger);
  EXPECT_EQ(b.changes.trigger_value, full.changes.trigger_value);
  EXPECT_EQ(b.changes.trigger_step, full.changes.trigger_step);
  EXPECT_EQ(b.changes.trigger_time, full.changes.trigger_time);
  EXPECT_EQ(b.changes.broken_at_support, full.changes.broken_at_support);
  EXPECT_FALSE(b.changes.broken_before || b.changes.bolts || b.changes.interface_cracks);
  EXPECT_EQ(b.changes.other, full.changes.other);
  EXPECT_EQ(b.steps, 2000);
  EXPECT_EQ(b.simulated_time, 0.736);
  EXPECT_EQ(b.dt, full.dt);
  EXPECT_EQ(b.unbalanced_ratio, full.unbalanced_ratio);
  EXPECT_EQ(b.settle, full.settle);
  EXPECT_EQ(b.converged, std::optional<bool>(false));
  EXPECT_EQ(b.max_steps, 2000);
  EXPECT_EQ(b.ratio, 1e-3);
  EXPECT_EQ(b.settle_limit, 1e-3);
  EXPECT_EQ(b.hold, 3);
  EXPECT_EQ(b.unstable_fraction, 0.1);
  ASSERT_TRUE(b.moving_most);
  EXPECT_EQ(b.moving_most->key_point, "invert");
  EXPECT_EQ(b.moving_most->mm_per_1000_steps, 18.3);
  EXPECT_EQ(b.support_pressure_ratio, 0.25);
  EXPECT_EQ(stage_records_json(back), j);
}

// The support verdict is stated once, under the status: its warning line
// (summary.json and stderr carry it) is not repeated in the list below,
// while every other warning is.
TEST(Report, the_support_verdict_is_stated_once) {
  using namespace rockfdem::workflows;
  const Scene scene = load_scene(kTestDir + "/support_pair_supported.toml");
  RunRecord r(scene, 1);
  r.status = "completed";
  r.support = SupportVerdict{"overstressed", {"lining SF 0.56 at 238 deg"}, {}};
  r.warnings = {r.support->line(), "another warning"};
  const std::string md = report_markdown(scene, r, ReportExtras{});
  EXPECT_NE(md.find("**Support overstressed**: lining SF 0.56 at 238 deg"), std::string::npos)
      << md;
  EXPECT_EQ(md.find("- warning: support overstressed"), std::string::npos) << md;
  EXPECT_NE(md.find("- warning: another warning"), std::string::npos) << md;
}

// report.md and summary.json read the support equilibria the record found
// once (record_convergence_confinement), not a computation of their own:
// the record holds the hand-solved meeting (elastic curve through
// (0 mm, 10 MPa) and (10 mm, 5 MPa), a line installed at 10 mm with
// K = 0.5 MPa/mm: 15 mm, as SupportEquilibrium solves it), and a figure
// changed in the record afterwards shows in both files.
TEST(Report, support_equilibria_are_found_once_and_read_by_both_files) {
  using namespace rockfdem::workflows;
  const Scene scene = load_scene(kTestDir + "/support_pair_supported.toml");
  RunRecord r(scene, 1);
  r.status = "completed";
  for (const auto& [u_mm, p_Pa] : {std::pair{0.0, 10e6}, std::pair{10.0, 5e6}}) {
    GroundReactionPoint g;
    g.key_points["vault"] = {u_mm, p_Pa, 1e7};
    r.ground_reaction_curve.push_back(g);
  }
  ConvergenceConfinementFigures c;
  c.install_radial_mm = 10;
  c.support.push_back({"shotcrete", 4e6, 0.5e9, 8, {}});
  r.record_convergence_confinement(c);
  ASSERT_TRUE(r.support_equilibria.has_value());
  ASSERT_EQ(r.support_equilibria->lines.size(), 1u);
  ASSERT_TRUE(r.support_equilibria->lines[0].found);
  EXPECT_NEAR(r.support_equilibria->lines[0].radial_mm, 15.0, 1e-9);

  r.support_equilibria->lines[0].radial_mm = 123.4;
  const nlohmann::json j = r.to_json();
  EXPECT_EQ(j.at("convergence_confinement").at("equilibrium").at(0).at("radial_mm"), 123.4);
  const std::string md = report_markdown(scene, r, ReportExtras{});
  const auto cells = row_of(md, "shotcrete");
  ASSERT_EQ(cells.size(), 8u) << md;
  EXPECT_EQ(cells[4], "123.4") << md;
}

// References read as monitoring reads them (references.reading = "survey"):
// a shoulder on its 45 deg ray that moved (ux, uy) = (216, -134) mm reads
// 216 mm of horizontal convergence, not its 254 mm radial figure; the vault
// reads its settlement. The difference is against the survey figure, from
// the in-situ state or, with from = "support", since the support's
// installation (the report's extras carry those).
TEST(Report, survey_references_compare_the_component_monitoring_reads) {
  using namespace rockfdem::workflows;
  Scene scene = load_scene(kTestDir + "/support_pair_supported.toml");
  scene.references.survey = true;
  scene.references.mm = {{"left_shoulder", 200.0}, {"vault", 220.0}};
  RunRecord r(scene, 1);
  r.status = "completed";
  const double s = std::sqrt(0.5);
  r.monitors.key_points["left_shoulder"] = {216.0,
                                            -134.0,
                                            std::hypot(216.0, 134.0),
                                            (216.0 + 134.0) * s,
                                            -4.0,
                                            2.7,
                                            s,
                                            -s,
                                            std::nullopt,
                                            std::nullopt,
                                            std::nullopt,
                                            std::nullopt};
  r.monitors.key_points["vault"] = {0.5,          -219.0,       219.0,        219.0,
                                    0.0,          4.4,          0.0,          -1.0,
                                    std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  ReportExtras x;
  std::string md = report_markdown(scene, r, x);
  auto shoulder = row_of(md, "left_shoulder");
  ASSERT_EQ(shoulder.size(), 7u) << md;
  EXPECT_EQ(shoulder[1], "247.49");
  EXPECT_EQ(shoulder[4], "216.00 (horizontal)");
  EXPECT_EQ(shoulder[6], "16.00 (8.0%)");
  EXPECT_EQ(row_of(md, "vault")[4], "219.00 (vertical)");
  EXPECT_EQ(row_of(md, "vault")[6], "-1.00 (-0.5%)");
  // Nothing broke: no caveat that the figures are one mesh's; with cracks
  // broken, the caveat and the way to the spread.
  EXPECT_EQ(md.find("These figures are this mesh's"), std::string::npos) << md;
  r.state.broken.mode_II = 10;
  EXPECT_NE(report_markdown(scene, r, x).find("--vary mesh.size_near"), std::string::npos);

  scene.references.from_support = true;
  r.monitors.key_points["left_shoulder"].survey_since_support_mm = 40.0;
  x.since_support_mm = {{"left_shoulder", 45.0}};
  md = report_markdown(scene, r, x);
  shoulder = row_of(md, "left_shoulder");
  EXPECT_EQ(shoulder[6], "-160.00 (-80.0%)") << md;
}
