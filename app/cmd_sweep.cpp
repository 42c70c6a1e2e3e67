// `skinsim sweep`: many pipeline configurations on one scene, their cost and quality against a
// shared reference, results.json/csv, VTK charts and report.html. Resumable; Ctrl-C (or a
// scheduler's SIGTERM) keeps every finished configuration. `--shard K/N` computes one part
// of the sweep for a cluster job array, `--merge` writes the report from the parts.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame/frame_job.h"
#include "driver/sequence/sequence.h"
#include "driver/sequence/sequence_animation.h"
#include "driver/sweep/sweep_file.h"
#include "driver/sweep/sweep_report.h"
#include "driver/sweep/sweep_results.h"
#include "driver/sweep/sweep_run.h"
#include "driver/sweep/sweep_spec.h"
#include "driver/truth/truth_report.h"
#include "driver/truth/truth_sweep.h"
#include "gpu_model/profile_loader.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/read_file.h"
#include "io/run_directory.h"
#include "io/temp_files.h"
#include "reports/knob_verdicts.h"
#include "reports/recommendation.h"

namespace skinsim::app {

namespace {

// The signal that stopped the sweep (SIGINT or SIGTERM), or 0; the sweep starts no new
// configuration once it is set.
std::atomic<int> g_interrupted{0};
static_assert(std::atomic<int>::is_always_lock_free, "used from a signal handler");
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<bool>::is_always_lock_free, "used from a signal handler");

// SIGTERM is how Slurm and other schedulers stop a job (at its time limit, or scancel), with
// SIGKILL some seconds later: the configurations in flight may still finish and be kept.
void on_interrupt(int signal) {
  g_interrupted.store(signal);
  g_cancel.store(true);
  constexpr char kMessage[] =
      "\nskinsim sweep: interrupted: finishing the configurations in flight (Ctrl-C again to "
      "abort at once; finished results are kept)\n";
  [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  std::signal(signal, SIG_DFL);  // a second one ends the process
}

// 128 + the signal: what a shell reports for a program stopped by it (130 for Ctrl-C).
int interrupted_exit() {
  return 128 + g_interrupted.load();
}

struct SweepOptions {
  std::string sweep_file;
  std::map<std::string, std::vector<std::string>> axes;  // knob -> values, from options
  std::map<std::string, std::string> axis_flags;         // knob -> the option's name
  std::vector<std::string> fixed;                        // "knob=value"
  driver::SceneSource scene;
  std::vector<std::string> scene_flags_given;
  std::string data_dir;
  int threads = 0;
  std::string out = "out/sweep";
  bool charts = true;
  bool require_charts = false;
  double budget_ms = 0.0;  // 0 = the sweep file's or 33.3
  std::size_t max_configs = driver::kDefaultMaxConfigs;
  std::string shard;  // "K/N", or empty
  bool merge = false;
  std::string truth;                 // --truth: "cached", a file, or none
  driver::TruthChoice truth_choice;  // --truth-samples, --truth-seed
  std::string sequence;              // --sequence: every configuration plays it; empty: one frame
  int frames = 0;                    // --frames, --fps: 0 = the sequence's own
  double fps = 0.0;
};

// `--out ""` would write into the current directory, and a file there cannot hold results.
void require_out_dir(const std::string& out) {
  if (out.empty()) throw driver::SweepError("--out: empty path: give the sweep directory");
  io::check_output_directory(out, "sweep", /*listed_only=*/false);
}

driver::SweepSpec build_spec(const SweepOptions& o, const CLI::App& cmd) {
  driver::SweepSpec spec =
      o.sweep_file.empty() ? driver::default_sweep_spec() : driver::parse_sweep_file(o.sweep_file);
  for (const auto& [knob, values] : o.axes) {
    if (values.empty()) continue;
    std::vector<std::string> v = values;
    if (knob == "technique" && v == std::vector<std::string>{"all"}) {
      v = pipeline::technique_names();
    }
    driver::set_axis(spec, knob, v, o.axis_flags.at(knob));
  }
  for (const std::string& f : o.fixed) {
    const auto [knob, value] = parse_knob_assignment(f, "--set");
    spec.fixed.push_back({knob, value, "--set " + f});
    driver::require_not_swept(spec, spec.fixed.back());
  }
  // Scene options override the sweep file's only when given.
  if (o.sweep_file.empty()) {
    spec.scene = o.scene;
  } else {
    if (cmd.get_option("--scene")->count()) spec.scene.path = o.scene.path;
    if (cmd.get_option("--head-triangles")->count())
      spec.scene.head_triangles = o.scene.head_triangles;
    if (cmd.get_option("--texture-size")->count()) spec.scene.texture_size = o.scene.texture_size;
    if (cmd.get_option("--skin-materials")->count())
      spec.scene.skin_materials = o.scene.skin_materials;
    if (cmd.get_option("--units-per-mm")->count()) spec.scene.units_per_mm = o.scene.units_per_mm;
    if (cmd.get_option("--skin-albedo")->count()) spec.scene.skin_albedo = o.scene.skin_albedo;
  }
  if (o.budget_ms > 0.0) spec.budget_ms = o.budget_ms;
  return spec;
}

// What each knob did, in one sentence per knob and group, then each group's recommendation
// with its range and runner-up (the report's first two sections).
void print_recommendations(const results::SweepTable& table) {
  const std::string metric = reports::recommend_metric(table.rows);
  std::optional<std::string> group;
  for (const reports::KnobVerdict& v : reports::knob_verdicts(table, metric)) {
    if (v.group != group) {
      group = v.group;
      fmt::print("knob verdicts for {}:\n", *group);
    }
    fmt::print("  {}\n", v.sentence);
  }
  for (const reports::Recommendation& r : reports::recommend(table, metric)) {
    fmt::print("recommended for {}: {}\n", r.group, r.verdict);
    for (const std::string* note : {&r.range_note, &r.runner_up_note}) {
      if (!note->empty()) fmt::print("  {}\n", *note);
    }
  }
}

// How many render passes were replayed from identical ones (sim/pass_memo.h), when this run
// rendered any.
void print_replayed_passes(const driver::SweepRunSummary& summary) {
  const int passes = summary.passes_replayed + summary.passes_rendered;
  if (passes == 0) return;
  fmt::print("render passes: {} of {} replayed from identical ones of earlier configurations\n",
             summary.passes_replayed, passes);
}

void print_warnings(const driver::SweepRunSummary& summary) {
  for (const std::string& w : summary.warnings) {
    fmt::print(stderr, "skinsim sweep: warning: {}\n", w);
  }
}

// A shard's run: its configurations into the shared directory, no tables or report (the
// merge writes those once every shard has finished).
int finish_shard(const driver::SweepShard& shard, const driver::SweepRunSummary& summary,
                 const std::string& out) {
  fmt::print(
      "skinsim sweep: shard {}: {} of {} configurations: {} computed, {} resumed{} in "
      "{:.1f} s\n",
      driver::to_string(shard), summary.this_part, summary.total, summary.computed.size(),
      summary.resumed,
      summary.failed.empty() ? "" : fmt::format(", {} failed", summary.failed.size()),
      summary.seconds);
  print_replayed_passes(summary);
  print_warnings(summary);
  for (const driver::FailedConfig& f : summary.failed) {
    fmt::print(stderr, "skinsim sweep: configuration {} failed: {}\n", f.id, f.reason);
  }
  if (summary.cancelled) {
    fmt::print(
        "interrupted: run shard {} again to resume; finished results in {}/configs are "
        "kept\n",
        driver::to_string(shard), out);
    return interrupted_exit();
  }
  fmt::print(
      "wrote {}/configs; when every shard has finished, run the same sweep with --merge "
      "to write the report\n",
      out);
  return summary.failed.empty() ? 0 : 1;
}

// `--truth`: each configuration judged by its group's truth (driver/truth/truth_sweep.h), into the
// table's quality columns; returns results.json's "truth".
nlohmann::json judge_with_truth(const SweepOptions& o, const driver::SweepSpec& spec,
                                const std::vector<driver::SweepConfig>& configs,
                                const std::string& data_dir, results::SweepTable& table) {
  const auto truth_of = [&](const results::ConfigResult& row, int width, int height) {
    if (o.truth != driver::kCachedTruth)
      return driver::truth_file("--truth", o.truth, width, height);
    const auto config =
        std::find_if(configs.begin(), configs.end(),
                     [&row](const driver::SweepConfig& c) { return c.id == row.id; });
    const pipeline::PipelineConfig resolved = driver::resolve_config(
        config->config, gpu_model::load_device_profile(config->device, data_dir));
    const scene::Scene scene = driver::load_scene(
        spec.scene, static_cast<float>(resolved.width) / static_cast<float>(resolved.height));
    return driver::cached_truth(
        pipeline::GpuScene(scene), resolved, o.truth_choice, o.threads,
        [](const std::string& note) { fmt::print(stderr, "skinsim sweep: note: {}\n", note); });
  };
  return driver::judge_sweep_with_truth(table, o.out, truth_of);
}

// Adds the truth's verdicts to results.json, which the report wrote from the table.
void add_truth_to_results(const std::string& out, const nlohmann::json& truth) {
  const std::filesystem::path path = std::filesystem::path(out) / "results.json";
  nlohmann::json results =
      io::parse_json(io::read_regular_file(path, "results.json"), "results.json", path);
  results["truth"] = truth;
  io::write_file_atomically(path.string(), results.dump(2) + "\n");
}

// What the sweep is, checked before any work or directory: its spec, its configurations and
// the sequence each plays (none for single frames).
struct SweepPlan {
  driver::SweepSpec spec;
  std::vector<driver::SweepConfig> configs;
  std::optional<driver::Sequence> sequence;
};

SweepPlan plan_sweep(const SweepOptions& o, const CLI::App& cmd) {
  require_out_dir(o.out);
  if (!o.truth.empty()) driver::require_truth("--truth", o.truth);  // before hours of sweep
  driver::require_cached_for_choice(o.truth, o.truth_choice);
  SweepPlan plan;
  plan.spec = build_spec(o, cmd);
  plan.configs = driver::expand_sweep(plan.spec, o.max_configs);
  if (!o.sequence.empty()) {
    plan.sequence = driver::load_sequence(o.sequence, o.frames, o.fps);
    driver::attach_animation(*plan.sequence, plan.spec.scene);
    for (const driver::SweepConfig& c : plan.configs) {
      driver::check_sequence(*plan.sequence, c.config);
    }
  }
  return plan;
}

// How the driver runs it: where, with what, and which shard of it.
driver::SweepRunOptions run_options_for(const SweepOptions& o, const CLI::App& cmd,
                                        const SweepPlan& plan) {
  driver::SweepRunOptions run_options;
  run_options.out_dir = o.out;
  run_options.data_dir = o.data_dir.empty() ? default_data_dir() : o.data_dir;
  run_options.threads = o.threads;
  run_options.cancel = &g_cancel;
  run_options.compute = !o.merge;
  run_options.reference_store = driver::ReferenceStore::from_environment();
  run_options.sequence = plan.sequence ? &*plan.sequence : nullptr;
  // Given, even empty: `--shard ""` (an unset $K in a script) must not run the whole sweep.
  if (cmd.get_option("--shard")->count()) {
    run_options.shard = driver::parse_shard(o.shard, "--shard");
  }
  if (o.merge && !std::filesystem::is_directory(o.out)) {
    throw driver::SweepError(
        fmt::format("--merge: {} is not a sweep directory (run the shards into it first)", o.out));
  }
  return run_options;
}

// The configurations computed (or resumed) into the claimed directory, interruptible by
// SIGINT/SIGTERM.
driver::SweepRunSummary compute_configurations(const SweepOptions& o, const SweepPlan& plan,
                                               const driver::SweepRunOptions& run_options) {
  // Checked again now that the spec is valid, and only now created: a sweep writes into its
  // directory in place (resuming), so it must be this kind's, never a run's or a user's.
  io::claim_output_directory(o.out, "sweep");
  // Left by a sweep killed mid-write; another live process's (a shard beside this one) are kept.
  io::remove_stale_temporaries_in_tree(o.out);
  g_interrupted.store(0);
  g_cancel.store(false);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  driver::SweepRunSummary summary = driver::run_sweep(plan.spec, plan.configs, run_options);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  // The configurations' scenes, references, frames and pass memo are freed, but glibc keeps
  // their pages in its arenas, where the report's work on other threads does not reuse them:
  // its comparisons, panels and charts would add their own on top. Hand them back first.
  malloc_trim(0);
  return summary;
}

// What the configurations' run did: missing, computed, resumed, failed, replaced.
void print_sweep_summary(const SweepOptions& o, const SweepPlan& plan,
                         const driver::SweepRunSummary& summary) {
  if (!summary.left_by_shards.empty()) {
    fmt::print(stderr, "skinsim sweep: {} configurations {}:\n", summary.left_by_shards.size(),
               o.merge ? "are missing" : "have no result yet; computing them here");
    for (const driver::MissingConfig& m : summary.left_by_shards) {
      fmt::print(stderr, "  {}{}\n", m.id, m.reason.empty() ? "" : ": " + m.reason);
    }
  }
  std::size_t combinations = 1;  // saturating: a folded sweep's product can exceed 2^64
  for (const driver::SweepAxis& axis : plan.spec.axes) {
    if (__builtin_mul_overflow(combinations, axis.values.size(), &combinations)) {
      combinations = SIZE_MAX;
    }
  }
  const std::size_t skipped = combinations - plan.configs.size();
  fmt::print(
      "skinsim sweep: {} configurations on {}: {} computed, {} resumed{}{}{} in {:.1f} s{}\n",
      summary.total, plan.spec.scene.label(), summary.computed.size(), summary.resumed,
      summary.failed.empty() ? "" : fmt::format(", {} failed", summary.failed.size()),
      summary.not_run ? fmt::format(", {} not run", summary.not_run) : "",
      o.merge && !summary.left_by_shards.empty()
          ? fmt::format(", {} missing", summary.left_by_shards.size())
          : "",
      summary.seconds,
      skipped ? fmt::format(" ({} more combinations differ only in knobs their technique "
                            "does not use)",
                            skipped)
              : "");
  print_replayed_passes(summary);
  print_warnings(summary);
  for (const driver::FailedConfig& f : summary.failed) {
    fmt::print(stderr, "skinsim sweep: configuration {} failed: {}\n", f.id, f.reason);
  }
  if (summary.foreign_ignored) {
    fmt::print(stderr,
               "skinsim sweep: note: {} stored results from a different sweep ignored (another "
               "--set knob, scene or scene file content, device profile or build of skinsim "
               "wrote them into {}); this sweep replaces them as it computes those "
               "configurations\n",
               summary.foreign_ignored, o.out);
  }
}

// 0, or 1 when a configuration failed, a merge lacks some, or required charts were not drawn.
int sweep_exit_code(const SweepOptions& o, const driver::SweepRunSummary& summary,
                    const results::SweepTable& table, const driver::SweepReportOutcome& report) {
  if (!summary.failed.empty()) {
    fmt::print(stderr, "skinsim sweep: {} of {} configurations failed (reasons above)\n",
               summary.failed.size(), summary.total);
    return 1;
  }
  if (o.merge && !summary.left_by_shards.empty()) {
    fmt::print(stderr,
               "skinsim sweep: the report shows {} of {} configurations; re-run the shards "
               "named above (they resume), then --merge again\n",
               table.rows.size(), summary.total);
    return 1;
  }
  return o.charts && o.require_charts && !report.charts_drawn ? 1 : 0;
}

// results.json, results.csv, the truth's verdicts and report.html from the finished
// configurations, and the recommendations on stdout.
int write_tables_and_report(const SweepOptions& o, const SweepPlan& plan,
                            const driver::SweepRunSummary& summary, const std::string& data_dir) {
  results::SweepTable table =
      driver::assemble_sweep_table(plan.spec, plan.configs, summary.fingerprints, o.out);
  std::vector<std::string> written = {"results.json", "results.csv", "configs/"};
  if (summary.cancelled) {
    driver::finish_sweep_data(table, o.out);
    driver::remove_stale_report(o.out);
    fmt::print(
        "interrupted: {} of {} configurations finished; wrote {}/{{{}}}; run the same "
        "command again to resume\n",
        table.rows.size(), summary.total, o.out, fmt::join(written, ", "));
    return interrupted_exit();
  }
  nlohmann::json truth;
  if (!o.truth.empty()) truth = judge_with_truth(o, plan.spec, plan.configs, data_dir, table);
  const driver::ReportTruth report_truth{driver::truth_report_section(table, truth),
                                         driver::truth_report_images(truth)};
  const driver::SweepReportOutcome report =
      driver::write_sweep_report(table, o.out, o.charts, report_truth);
  if (!report.report_path.empty()) {
    written.push_back(report.charts_drawn ? "report.html + charts" : "report.html (no charts)");
  }
  if (!report.note.empty()) fmt::print(stderr, "skinsim sweep: note: {}\n", report.note);
  if (plan.sequence)
    fmt::print("recommendations hold each configuration's p95 frame time to the budget\n");
  print_recommendations(table);
  if (!truth.is_null()) {
    add_truth_to_results(o.out, truth);
    for (const std::string& line : driver::truth_sweep_lines(truth)) fmt::print("{}\n", line);
  }
  fmt::print("wrote {}/{{{}}}\n", o.out, fmt::join(written, ", "));
  const int code = sweep_exit_code(o, summary, table, report);
  if (report.display_attempt_pending) {
    // Every file is written and closed; only the exit handlers are skipped, which would tear
    // down libX11 under the attempt still waiting for the display (display_check.h).
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

int run(const SweepOptions& o, const CLI::App& cmd) {
  const SweepPlan plan = plan_sweep(o, cmd);
  const driver::SweepRunOptions run_options = run_options_for(o, cmd, plan);
  const driver::SweepRunSummary summary = compute_configurations(o, plan, run_options);
  if (run_options.shard) return finish_shard(*run_options.shard, summary, o.out);
  print_sweep_summary(o, plan, summary);
  return write_tables_and_report(o, plan, summary, run_options.data_dir);
}

void axis_option(CLI::App& cmd, SweepOptions& o, const std::string& flag, const std::string& knob,
                 const std::string& help) {
  o.axis_flags[knob] = flag;
  cmd.add_option(flag, o.axes[knob], help)->delimiter(',');
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run many pipeline configurations (default: 4 buffer scales x 4 LUT sizes on ipad4), "
      "compare each with the reference, write results.csv/json, charts and report.html");
  cmd->add_option("--sweep-file", o->sweep_file,
                  "TOML sweep file ([axes], [fixed], [scene], "
                  "[report]; see docs/sweeps.md)")
      ->check(CLI::ExistingFile);
  for (const pipeline::KnobSpec& knob : pipeline::all_knobs()) {
    if (!knob.sweep_flag.empty())
      axis_option(*cmd, *o, knob.sweep_flag, knob.name, knob.sweep_help);
  }
  axis_option(*cmd, *o, "--devices", "device",
              "Device profiles: shipped names (see `skinsim devices`) or .toml files");
  cmd->add_option("--set", o->fixed,
                  "Hold a knob fixed for every configuration: knob=value (repeatable; knobs as "
                  "in `skinsim run`, e.g. blur_width_mm=2, gamma=srgb)");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--data-dir", o->data_dir,
                  "Directory holding devices/*.toml (default: $SKINSIM_DATA_DIR or the source "
                  "tree's data/)");
  cmd->add_option("--threads", o->threads,
                  "Host worker threads; 0 = all cores (results are identical for any count)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Sweep directory (re-running into it resumes)")
      ->capture_default_str();
  cmd->add_option("--max-configs", o->max_configs,
                  "Refuse sweeps of more configurations than this (each renders frames and "
                  "writes megabytes); raise it to run a larger sweep anyway")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--budget-ms", o->budget_ms,
                  "Frame budget for the recommendation (default: the sweep file's, else 33.3)")
      ->check(positive_real(60000.0));  // a minute per frame
  cmd->add_option("--shard", o->shard,
                  "Compute only part K of N of the sweep (K/N, K from 0), e.g. one task of a "
                  "Slurm job array (scripts/slurm/sweep.sh): shards balanced by expected cost "
                  "share --out safely; no report (see --merge)");
  cmd->add_option("--truth", o->truth,
                  "Also judge every configuration against a path-traced truth (`cached`: the "
                  "truth store's for each group, rendered with Blender Cycles when missing; a "
                  "linear EXR or PNG of the view, or a `skinsim truth` directory of it) and say "
                  "per group whether the recommendation "
                  "and the visibility verdicts stay (docs/validation.md)");
  add_truth_choice_options(*cmd, o->truth_choice);
  CLI::Option* sequence =
      cmd->add_option(
             "--sequence", o->sequence,
             "Every configuration plays a sequence (push-in, head-turn, light-orbit or a "
             "sequence file); its p95 frame time is held to the budget (docs/sequences.md)")
          ->excludes("--truth");
  cmd->add_option("--frames", o->frames, "Frames of the sequence (default: the sequence's own)")
      ->check(integer_in(1, driver::kMaxSequenceFrames))
      ->needs(sequence);
  cmd->add_option("--fps", o->fps, "Frame rate of the sequence (default: the sequence's own)")
      ->check(positive_real(1000.0))
      ->needs(sequence);
  cmd->add_flag("--merge", o->merge,
                "Compute nothing: write the tables and report from the configurations in --out "
                "(after the shards), naming those missing and their shard; exit 1 if any is")
      ->excludes("--shard");
  cmd->add_flag("!--no-charts", o->charts,
                "Write report.html without the VTK charts (no X display needed)");
  cmd->add_flag("--require-charts", o->require_charts,
                "Exit 1 if the charts cannot be drawn (default: warn and write the report "
                "without them)");
  return [o, cmd] { return run(*o, *cmd); };
}

}  // namespace skinsim::app
