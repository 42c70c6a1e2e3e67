// Tiny sweeps on the built-in scene (256x192, small mesh and texture): the files a sweep
// writes, resume, cancellation and thread-count invariance.
#include "driver/sweep/sweep_run.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "driver/frame/frame_quality.h"
#include "driver/frame/images.h"
#include "driver/frame/skin_diagnosis.h"
#include "driver/sweep/sweep_results.h"
#include "driver/sweep/sweep_spec.h"
#include "results/sweep_table.h"
#include "sweep_test_support.h"
#include "tests/test_paths.h"
#include "util/build_identity.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;
using test::options;
using test::out_dir;
using test::read_file;

SweepSpec tiny_spec() {
  SweepSpec spec;
  set_axis(spec, "scale", {"0.5", "0.25"}, "test");
  spec.fixed.push_back({"resolution", "256x192", "test"});
  spec.scene.head_triangles = 2000;
  spec.scene.texture_size = 64;
  return spec;
}

// Runs the sweep and writes results.json/csv; returns the table.
results::SweepTable run_and_write(const SweepSpec& spec, const SweepRunOptions& o,
                                  SweepRunSummary* summary = nullptr) {
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  const SweepRunSummary s = run_sweep(spec, configs, o);
  if (summary) *summary = s;
  results::SweepTable table = assemble_sweep_table(spec, configs, s.fingerprints, o.out_dir);
  write_sweep_data(table, o.out_dir);
  return table;
}

TEST(SweepRun, WritesOneRowPerConfigurationWithCostAndQuality) {
  const fs::path dir = out_dir("rows");
  SweepRunSummary summary;
  const results::SweepTable table = run_and_write(tiny_spec(), options(dir, 2), &summary);
  EXPECT_EQ(summary.total, 2);
  EXPECT_EQ(summary.computed.size(), 2u);
  EXPECT_EQ(summary.references_rendered, 1);  // one reference shared by both

  const results::SweepTable read = results::read_sweep_json((dir / "results.json").string());
  ASSERT_EQ(read.rows.size(), 2u);
  EXPECT_EQ(read.rows[0].id, "scale0.5");
  EXPECT_EQ(read.rows[1].id, "scale0.25");
  EXPECT_EQ(read.resolution, "256x192");
  EXPECT_EQ(read.device, "ipad4");
  for (const results::ConfigResult& r : read.rows) {
    EXPECT_GT(r.frame_ms, 0.0);
    EXPECT_NEAR(r.fps, 1000.0 / r.frame_ms, 1e-6 * r.fps);
    EXPECT_GT(r.dram_bytes, 0.0);
    EXPECT_GT(r.energy_mj, 0.0);  // the frame's dynamic energy and its range
    EXPECT_LT(r.energy_mj_low, r.energy_mj);
    EXPECT_GT(r.energy_mj_high, r.energy_mj);
    EXPECT_EQ(results::knob_value(r, "technique"), "mobile");
    EXPECT_EQ(results::knob_value(r, "lut"), "32x128");
    ASSERT_FALSE(r.passes.empty());
    for (const char* m :
         {"psnr_skin", "ssim_skin", "flip_skin", "psnr_frame", "ssim_frame", "flip_frame"}) {
      ASSERT_TRUE(r.quality.count(m)) << m;
    }
    EXPECT_GT(r.quality.at("ssim_skin"), 0.5);  // the pipeline approximates the reference
    EXPECT_LT(r.quality.at("flip_skin"), 0.5);
    EXPECT_TRUE(fs::exists(dir / r.frame_image)) << r.frame_image;
    EXPECT_TRUE(fs::exists(dir / r.error_image)) << r.error_image;
  }
  // A quarter-size integration buffer stores fewer tiles than a half-size one.
  ASSERT_EQ(read.rows[0].passes.at(0).name, "shadow");
  ASSERT_EQ(read.rows[0].passes.at(1).name, "irradiance");
  EXPECT_LT(read.rows[1].passes.at(1).dram_bytes_by_cause.at("color_store"),
            read.rows[0].passes.at(1).dram_bytes_by_cause.at("color_store"));
  for (const results::ConfigResult& r : read.rows) {
    // A pass's ms is its share of the frame: with the DRAM wait, if any, they add up to it.
    double sum = 0.0;
    for (const results::PassCost& p : r.passes) {
      sum += p.ms;
      EXPECT_LE(p.ta_start_ms, p.ta_end_ms) << r.id << " " << p.name;
      EXPECT_LE(p.render_end_ms, r.frame_ms * (1.0 + 1e-12)) << r.id << " " << p.name;
    }
    EXPECT_NEAR(sum, r.frame_ms, 1e-9 * r.frame_ms) << r.id;
  }
  ASSERT_TRUE(read.heatmap.has_value());
  EXPECT_EQ(read.heatmap->pass_name, "skin");
  EXPECT_EQ(read.heatmap->tiles_x, 8);
  EXPECT_EQ(read.heatmap->tiles_y, 6);
  EXPECT_FALSE(read.assumptions.empty());

  const std::string csv = read_file(dir / "results.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* column :
       {"id", "scale", "lut", "device", "frame_ms", "fps", "dram_bytes", "energy_mj_low", "skin.ms",
        "skin.bottleneck", "flip_skin", "psnr_skin"}) {
    EXPECT_NE(header.find(column), std::string::npos) << column << " in " << header;
  }
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);  // header + 2 rows
}

TEST(SweepRun, TechniquesRunOncePerKnobTheyUseAndRowsOmitTheRest) {
  const fs::path dir = out_dir("techniques");
  SweepSpec spec = tiny_spec();
  set_axis(spec, "technique", {"mobile", "wrap"}, "test");
  SweepRunSummary summary;
  const results::SweepTable table = run_and_write(spec, options(dir, 2), &summary);
  EXPECT_EQ(summary.total, 3);  // wrap ignores the scale axis
  ASSERT_EQ(table.rows.size(), 3u);
  for (const results::ConfigResult& r : table.rows) {
    const bool wrap = results::knob_value(r, "technique") == "wrap";
    EXPECT_EQ(results::knob_value(r, "scale").empty(), wrap) << r.id;
    EXPECT_EQ(results::knob_value(r, "wrap").empty(), !wrap) << r.id;
    EXPECT_EQ(results::knob_value(r, "lut"), "32x128") << r.id;
  }
  // The CSV leaves the knob a technique does not use empty.
  const std::string csv = read_file(dir / "results.csv");
  EXPECT_NE(csv.find("\nscale0.5_wrap,"), std::string::npos) << csv;

  SweepRunSummary again;
  run_and_write(spec, options(dir, 2), &again);
  EXPECT_EQ(again.resumed, 3);
  EXPECT_EQ(read_file(dir / "results.csv"), csv);
}

// A sweep into another directory takes the reference from the user's store (reference_store.h)
// instead of rendering it, with the same results and the same refs/ files byte for byte.
TEST(SweepRun, AnotherDirectoryTakesTheReferenceFromTheStore) {
  const fs::path store = out_dir("store_references");
  const SweepSpec spec = tiny_spec();
  const auto run_into = [&](const fs::path& dir) {
    SweepRunOptions o = options(dir, 2);
    o.reference_store = ReferenceStore(store);
    SweepRunSummary summary;
    run_and_write(spec, o, &summary);
    return summary;
  };
  const fs::path first = out_dir("store_first");
  const SweepRunSummary rendered = run_into(first);
  EXPECT_EQ(rendered.references_rendered, 1);
  EXPECT_EQ(rendered.references_from_store, 0);
  const fs::path second = out_dir("store_second");
  const SweepRunSummary reused = run_into(second);
  EXPECT_EQ(reused.references_rendered, 0);
  EXPECT_EQ(reused.references_from_store, 1);
  EXPECT_EQ(read_file(second / "results.csv"), read_file(first / "results.csv"));
  int compared = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(first / "refs")) {
    if (e.path().extension() == ".lock") continue;
    EXPECT_EQ(read_file(second / "refs" / e.path().filename()), read_file(e.path()))
        << e.path().filename();
    ++compared;
  }
  EXPECT_EQ(compared, 3);  // the image, its skin mask, the marker
}

TEST(SweepRun, ResumeComputesOnlyWhatIsMissing) {
  const fs::path dir = out_dir("resume");
  const SweepSpec spec = tiny_spec();
  run_and_write(spec, options(dir, 2));
  const std::string results_before = read_file(dir / "results.json");

  SweepRunSummary again;
  run_and_write(spec, options(dir, 2), &again);
  EXPECT_EQ(again.resumed, 2);
  EXPECT_TRUE(again.computed.empty());
  EXPECT_EQ(again.references_rendered, 0);  // loaded from refs/

  fs::remove(dir / config_json_path("scale0.25"));
  SweepRunSummary partial;
  run_and_write(spec, options(dir, 2), &partial);
  EXPECT_EQ(partial.resumed, 1);
  EXPECT_EQ(partial.computed, std::vector<std::string>{"scale0.25"});
  EXPECT_EQ(partial.references_rendered, 0);
  // The cached reference gives the same metrics as the freshly rendered one.
  EXPECT_EQ(read_file(dir / "results.json"), results_before);

  // A changed knob invalidates the stored result of the same id.
  SweepSpec changed = spec;
  changed.fixed.push_back({"blur_iterations", "2", "test"});
  SweepRunSummary recomputed;
  run_and_write(changed, options(dir, 2), &recomputed);
  EXPECT_EQ(recomputed.resumed, 0);
  EXPECT_EQ(recomputed.computed.size(), 2u);
}

TEST(SweepRun, CancellationLeavesOnlyCompleteFiles) {
  const fs::path dir = out_dir("cancel");
  SweepSpec spec = tiny_spec();
  set_axis(spec, "lut", {"8x32", "32x128"}, "test");  // 4 configurations
  std::atomic<bool> cancel{false};
  SweepRunOptions o = options(dir, 1);
  o.cancel = &cancel;
  o.on_finished = [&](const std::string&) { cancel = true; };  // "Ctrl-C" after the first
  SweepRunSummary summary;
  const results::SweepTable table = run_and_write(spec, o, &summary);
  EXPECT_TRUE(summary.cancelled);
  EXPECT_EQ(summary.computed.size(), 1u);
  EXPECT_EQ(summary.not_run, 3);
  EXPECT_EQ(table.rows.size(), 1u);

  // Every file in configs/ belongs to a finished configuration; no temporary files remain.
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir / "configs")) {
    files.insert(e.path().filename().string());
  }
  const std::string id = summary.computed.front();
  EXPECT_EQ(files, (std::set<std::string>{id + ".json", id + "_frame.png", id + "_flip.png"}));

  // Resuming finishes the rest.
  cancel = false;
  o.on_finished = nullptr;
  SweepRunSummary resumed;
  run_and_write(spec, o, &resumed);
  EXPECT_EQ(resumed.resumed, 1);
  EXPECT_EQ(resumed.computed.size(), 3u);
  EXPECT_FALSE(resumed.cancelled);
}

TEST(SweepRun, AnInterruptedSweepShowsOnlyItsOwnRows) {
  // Two sweeps into one directory that differ only in a --set knob: the same ids, another
  // fingerprint. The second is interrupted after its first configuration.
  const fs::path dir = out_dir("foreign");
  const SweepSpec first = tiny_spec();
  run_and_write(first, options(dir, 1));
  SweepSpec second = tiny_spec();
  second.fixed.push_back({"blur_iterations", "3", "--set blur_iterations=3"});
  std::atomic<bool> cancel{false};
  SweepRunOptions o = options(dir, 1);
  o.cancel = &cancel;
  o.on_finished = [&](const std::string&) { cancel = true; };
  SweepRunSummary summary;
  const results::SweepTable table = run_and_write(second, o, &summary);
  EXPECT_TRUE(summary.cancelled);
  EXPECT_EQ(summary.resumed, 0);  // the first sweep's results are not this one's
  ASSERT_EQ(summary.computed.size(), 1u);
  EXPECT_EQ(summary.foreign_ignored, 1);  // the other id still holds the first sweep's result
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0].id, summary.computed[0]);
  EXPECT_EQ(results::knob_value(table.rows[0], "blur_iterations"), "3");
}

// A device profile edited between two runs of the same sweep: the stored results were made
// with other figures, so they are recomputed rather than resumed.
TEST(SweepRun, AnEditedDeviceProfileIsAnotherSweep) {
  const fs::path dir = out_dir("edited_profile");
  fs::create_directories(dir);
  const fs::path profile = dir / "mine.toml";
  fs::copy_file(fs::path(test_paths::kDataDir) / "devices" / "ipad4.toml", profile);
  SweepSpec spec = tiny_spec();
  spec.fixed.push_back({"device", profile.string(), "test"});
  const fs::path results = dir / "sweep";
  run_and_write(spec, options(results, 1));

  SweepRunSummary unchanged;
  run_and_write(spec, options(results, 1), &unchanged);
  EXPECT_EQ(unchanged.resumed, 2);

  std::ofstream(profile, std::ios::app) << "\n# an edit: another profile file\n";
  SweepRunSummary edited;
  run_and_write(spec, options(results, 1), &edited);
  EXPECT_EQ(edited.resumed, 0);
  EXPECT_EQ(edited.computed.size(), 2u);
}

// Rewrites the "build" field of a stored JSON file (at `pointer`), as an older or newer
// skinsim would have written it.
void stamp_other_build(const fs::path& file, const nlohmann::json::json_pointer& pointer) {
  nlohmann::json j = nlohmann::json::parse(read_file(file));
  ASSERT_EQ(j.at(pointer), std::string(build_identity()));
  j[pointer] = "sha256:0123456789abcdef";
  std::ofstream(file) << j.dump(1);
}

// Results and the cached reference written by another build of skinsim (changed sources or
// compiler) are not resumed: that build may compute other figures and images.
TEST(SweepRun, ResultsOfAnotherBuildAreRecomputed) {
  const fs::path dir = out_dir("other_build");
  const SweepSpec spec = tiny_spec();
  run_and_write(spec, options(dir, 1));
  const std::string results_before = read_file(dir / "results.json");

  stamp_other_build(dir / config_json_path("scale0.5"), "/fingerprint/build"_json_pointer);
  SweepRunSummary one;
  run_and_write(spec, options(dir, 1), &one);
  EXPECT_EQ(one.resumed, 1);
  EXPECT_EQ(one.computed, std::vector<std::string>{"scale0.5"});
  EXPECT_EQ(one.references_rendered, 0);

  std::vector<fs::path> markers;
  for (const auto& e : fs::directory_iterator(dir / "refs")) {
    if (e.path().extension() == ".json") markers.push_back(e.path());
  }
  ASSERT_EQ(markers.size(), 1u);
  stamp_other_build(markers[0], "/build"_json_pointer);
  fs::remove(dir / config_json_path("scale0.25"));
  SweepRunSummary reference;
  run_and_write(spec, options(dir, 1), &reference);
  EXPECT_EQ(reference.references_rendered, 1);
  EXPECT_EQ(read_file(dir / "results.json"), results_before);  // this build, the same figures
}

TEST(FrameQuality, AReferenceWithoutSkinGivesFrameMetricsOnly) {
  ReferenceImages reference;
  reference.image.width = reference.skin.width = 4;
  reference.image.height = reference.skin.height = 2;
  reference.image.rgb.assign(8, glm::vec3(0.5f));
  reference.skin.values.assign(8, 0);  // no skin pixel
  const sim::RenderTarget frame("frame", 4, 2, sim::TexelFormat::kRGBA8);
  const FrameQuality q = evaluate_quality(to_image(frame), reference);
  EXPECT_FALSE(q.has_skin_metrics());
  EXPECT_EQ(q.metrics.count("psnr_skin") + q.metrics.count("ssim_skin"), 0u);
  for (const char* m : {"psnr_frame", "ssim_frame", "flip_frame"}) {
    ASSERT_EQ(q.metrics.count(m), 1u) << m;
    EXPECT_TRUE(std::isfinite(q.metrics.at(m))) << m;
  }
  EXPECT_GT(q.metrics.at("flip_frame"), 0.0);  // a black frame against mid grey
  EXPECT_EQ(q.error_map.width, 4);
}

// Which rule found no skin, and what to pass, for each way a frame can end up without skin.
TEST(SkinDiagnosis, NamesTheRuleThatFoundNoSkin) {
  scene::Scene scene;
  scene.materials.resize(2);
  scene.materials[0].name = "Face";
  scene.materials[1].name = "Hair";
  const struct {
    const char* what;
    std::vector<std::string> skin_materials;
    bool face_is_skin;
    std::string expected;
  } cases[] = {
      {"mistyped name",
       {"Face", "Fcae"},
       true,
       "--skin-materials Fcae match no material of the scene (its materials: Face, Hair)"},
      {"no rule marks skin",
       {},
       false,
       "no material is skin by its extras.skinsim.kind or by a name containing \"skin\" (its "
       "materials: Face, Hair); pass --skin-materials"},
      {"skin out of view",
       {"Face"},
       true,
       "the skin materials (Face) are not visible from the camera"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    scene.materials[0].kind =
        c.face_is_skin ? scene::MaterialKind::kSkin : scene::MaterialKind::kOther;
    const std::string reason = no_skin_reason(scene, c.skin_materials);
    EXPECT_NE(reason.find(c.expected), std::string::npos) << reason;
  }
}

TEST(SweepRun, ResultsDoNotDependOnThreadCount) {
  const fs::path one = out_dir("threads1");
  const fs::path two = out_dir("threads2");
  run_and_write(tiny_spec(), options(one, 1));
  run_and_write(tiny_spec(), options(two, 2));
  EXPECT_EQ(read_file(one / "results.json"), read_file(two / "results.json"));
  EXPECT_EQ(read_file(one / "results.csv"), read_file(two / "results.csv"));
  for (const char* id : {"scale0.5", "scale0.25"}) {
    EXPECT_EQ(read_file(one / config_frame_path(id)), read_file(two / config_frame_path(id)));
    EXPECT_EQ(read_file(one / config_error_path(id)), read_file(two / config_error_path(id)));
  }
}

// Across LUT sizes at one buffer scale the shadow map, irradiance and blurs are the same
// passes: the second configuration replays them (sim/pass_memo.h), and its files are those of
// the same configuration rendered alone.
TEST(SweepRun, ReplayedPassesGiveWhatRenderingGives) {
  SweepSpec both = tiny_spec();
  set_axis(both, "scale", {"0.5"}, "test");
  set_axis(both, "lut", {"8x32", "32x128"}, "test");
  SweepSpec alone = both;
  set_axis(alone, "lut", {"32x128"}, "test");

  const fs::path shared = out_dir("replayed");
  const fs::path rendered = out_dir("rendered");
  SweepRunSummary summary;
  run_and_write(both, options(shared, 2), &summary);
  EXPECT_EQ(summary.passes_replayed, 4);  // shadow, irradiance, blur_h, blur_v
  EXPECT_EQ(summary.passes_rendered, 6);
  run_and_write(alone, options(rendered, 2), &summary);
  EXPECT_EQ(summary.passes_replayed, 0);

  const std::string id = "scale0.5_lut32x128";
  for (const std::string& file :
       {config_json_path(id), config_frame_path(id), config_error_path(id)}) {
    EXPECT_EQ(read_file(shared / file), read_file(rendered / file)) << file;
  }
}

TEST(SweepRun, UnknownDeviceFailsBeforeAnyWork) {
  const fs::path dir = out_dir("bad_device");
  SweepSpec spec = tiny_spec();
  set_axis(spec, "device", {"ipad4", "no_such_device"}, "test");
  const std::vector<SweepConfig> configs = expand_sweep(spec);
  EXPECT_ANY_THROW(run_sweep(spec, configs, options(dir, 1)));
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace skinsim::driver
