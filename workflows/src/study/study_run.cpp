#include "study/study_run.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>

#include "commands/commands.hpp"
#include "record/output_dir.hpp"
#include "record/small_file.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "run/interrupt.hpp"
#include "study/study_figures.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows::study {
namespace {

constexpr const char* kRecord = "variant.json";

// A variant's record and its run's summary: each a few KiB as written. A
// torn file, one that is not a regular file (a FIFO is not waited on), one
// larger than any written record or nested deeper reads as discarded, and
// the variant runs again.
constexpr std::size_t kMaxRecordBytes = 16 << 20;
constexpr int kMaxRecordDepth = 32;

nlohmann::json read_json(const std::string& path) {
  const SmallFile file = read_small_file(path, kMaxRecordBytes);
  if (file.kind != SmallFile::Kind::kText) return nullptr;
  return parse_shallow_json(file.text, kMaxRecordDepth);
}

bool finished(const std::string& status) {
  return status == "completed" || status == "not_at_equilibrium" || status == "unstable" ||
         status == "failed" || status == "refused";
}

// The earlier result in `dir`, when it is a finished run of the same identity.
bool reuse(const std::string& dir, const nlohmann::json& id, VariantResult* r) {
  const nlohmann::json record = read_json(output_path(dir, kRecord));
  if (!record.is_object() || record.value("identity", nlohmann::json()) != id) return false;
  try {
    *r = VariantResult::from_json(record.at("result"));
  } catch (const nlohmann::json::exception&) {
    return false;  // not a record this program wrote: the variant runs again
  }
  r->reused = true;
  return finished(r->status);
}

}  // namespace

void stop_study_if_interrupted(const CommandLine& study, const std::string& when) {
  throw_if_interrupted(when + "; the finished variants are kept in " +
                       output_path(study.output_dir, "variants") +
                       " and the same command resumes the study");
}

nlohmann::json VariantResult::to_json() const {
  return {{"name", name},          {"status", status}, {"message", message},
          {"wall_time_s", wall_s}, {"reused", reused}, {"figures", figures}};
}

VariantResult VariantResult::from_json(const nlohmann::json& j) {
  VariantResult r;
  r.name = j.at("name").get<std::string>();
  r.status = j.at("status").get<std::string>();
  r.message = j.at("message").get<std::string>();
  r.wall_s = j.at("wall_time_s").get<double>();
  r.reused = j.at("reused").get<bool>();
  r.figures = j.at("figures");
  return r;
}

std::string variant_dir(const CommandLine& study, const Variant& v) {
  return output_path(output_path(study.output_dir, "variants"), v.name);
}

nlohmann::json variant_identity(const Scene& scene, const Variant& v) {
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(fs::absolute(scene.source, ec), ec);
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016zx", std::hash<std::string>{}(scene.results_key));
  return {{"scene", file.string()}, {"scene_hash", hash}, {"settings", v.overrides()}};
}

std::optional<VariantResult> recorded_result(const CommandLine& study, const Variant& v,
                                             const nlohmann::json& id) {
  VariantResult r;
  const std::string dir = variant_dir(study, v);
  if (!fs::exists(output_path(dir, kRecord)) || !reuse(dir, id, &r)) return std::nullopt;
  return r;
}

VariantResult run_variant(const CommandLine& study, const Variant& v) {
  std::vector<std::string> overrides = study.overrides;
  for (const std::string& o : v.overrides()) overrides.push_back(o);
  const Scene scene = load_scene(study.scene, overrides);  // checked before the study began
  RunContext ctx = run_context(study);
  ctx.output_dir = variant_dir(study, v);
  ctx.quiet = ctx.force = true;
  const nlohmann::json id = variant_identity(scene, v);
  signal_point("variant-start");
  stop_study_if_interrupted(study, "before variant " + v.name);
  VariantResult r;
  if (reuse(ctx.output_dir, id, &r)) return r;
  r = VariantResult{};
  r.name = v.name;
  fs::remove(output_path(ctx.output_dir, kRecord));  // until this run has finished
  const auto start = std::chrono::steady_clock::now();
  try {
    refuse_if_too_large(scene);
    signal_point("variant-run");  // after the check above: the run's own checks see it
    command_run(scene, ctx);
    const nlohmann::json summary = read_json(output_path(ctx.output_dir, "summary.json"));
    if (!summary.is_object()) throw std::runtime_error(ctx.output_dir + ": no summary.json");
    r.status = summary.value("status", "");
    r.message = summary.value("status_reason", "");
    r.figures = key_figures(summary);
  } catch (const NumericalError& e) {
    r.status = "failed";
    r.message = e.what();
    r.figures = key_figures(read_json(output_path(ctx.output_dir, "summary.json")));
  } catch (const InputError& e) {
    r.status = "refused";
    r.message = e.what();
  }
  signal_point("variant-end");
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fs::create_directories(ctx.output_dir);
  coupling::atomic_write_text(output_path(ctx.output_dir, kRecord),
                              nlohmann::json{{"identity", id}, {"result", r.to_json()}}.dump(1));
  signal_point("variant-recorded");  // the next variant, or the study's end, stops
  return r;
}

}  // namespace rockfdem::workflows::study
