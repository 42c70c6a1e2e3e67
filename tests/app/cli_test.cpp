// Runs the real skinsim binary as a user would and checks exit codes and messages.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/app/run_skinsim.h"
#include "tests/hung_display.h"
#include "tests/scene/gltf_fixture.h"
#include "tests/scoped_env.h"

namespace {

using skinsim::test::Result;
using skinsim::test::run;

std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("skinsim_cli_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(Cli, HelpListsSubcommandsAndExitsZero) {
  const Result r = run("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"run", "devices", "shaders", "microbench"}) {
    EXPECT_NE(r.output.find(sub), std::string::npos) << sub;
  }
  const Result run_help = run("run --help");
  EXPECT_EQ(run_help.exit_code, 0);
  for (const char* opt : {"--scale", "--lut", "--device", "--threads", "--scene", "--out"}) {
    EXPECT_NE(run_help.output.find(opt), std::string::npos) << opt;
  }
}

TEST(Cli, UnknownOptionIsExitTwo) {
  const Result r = run("run --no-such-option");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--no-such-option"), std::string::npos) << r.output;
}

TEST(Cli, OutOfRangeKnobNamesTheKnob) {
  const Result r = run("run --scale 1.5 --no-reference --out /tmp/skinsim_cli_unused");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("scale must be in (0, 1], got 1.5"), std::string::npos) << r.output;
  const Result lut = run("run --lut 30x128 --no-reference");
  EXPECT_EQ(lut.exit_code, 2);
  EXPECT_NE(lut.output.find("lut must be powers of two in [2, 1024] per axis, got 30x128"),
            std::string::npos)
      << lut.output;
  const Result threads = run("run --threads -3");
  EXPECT_EQ(threads.exit_code, 2);
  EXPECT_NE(threads.output.find("--threads"), std::string::npos) << threads.output;
}

TEST(Cli, MissingSceneFileNamesTheFile) {
  const Result r = run("run --scene /nonexistent/head.glb --no-reference");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("/nonexistent/head.glb"), std::string::npos) << r.output;
}

TEST(Cli, TruncatedGlbIsExitTwo) {
  const auto dir = temp_dir("truncated");
  const auto path = dir / "truncated.glb";
  std::ofstream(path, std::ios::binary) << "glTF\x02";
  const Result r =
      run("run --scene " + path.string() + " --no-reference --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(path.string()), std::string::npos) << r.output;
}

std::set<std::string> names_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.insert(e.path().filename().string());
  }
  return names;
}

// A failed run leaves the previous run's directory as it was: no new images beside an old
// result.json, and no staging directory left behind.
TEST(Cli, FailedRunLeavesThePreviousRunUntouched) {
  const auto dir = temp_dir("swap");
  const std::string out = (dir / "out").string();
  const std::string small = " --resolution 96x64 --texture-size 64 --no-reference --out " + out;
  ASSERT_EQ(run("run" + small).exit_code, 0);
  const auto before = names_in(out);
  const auto written = std::filesystem::last_write_time(dir / "out" / "result.json");
  const Result r = run("run --scene /nonexistent/head.glb" + small);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(names_in(out), before);
  EXPECT_EQ(std::filesystem::last_write_time(dir / "out" / "result.json"), written);
  EXPECT_EQ(names_in(dir), std::set<std::string>{"out"});
}

TEST(Cli, RunRefusesToReplaceAForeignDirectory) {
  const auto dir = temp_dir("foreign");
  std::ofstream(dir / "notes.txt") << "mine";
  const Result r =
      run("run --resolution 96x64 --texture-size 64 --no-reference --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a skinsim run directory"), std::string::npos) << r.output;
  EXPECT_EQ(names_in(dir), std::set<std::string>{"notes.txt"});
}

TEST(Cli, UnknownDeviceIsExitTwo) {
  const Result r = run("run --device nosuchphone --no-reference");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nosuchphone"), std::string::npos) << r.output;
}

TEST(Cli, UnknownSimdChoiceIsExitTwoNamingTheVariable) {
  const Result r = [] {
    const skinsim::test::ScopedEnv simd("SKINSIM_SIMD", "avx9");
    return run("devices");
  }();
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("SKINSIM_SIMD is 'avx9'"), std::string::npos) << r.output;
}

TEST(Cli, DevicesAndShadersPrintTables) {
  const Result d = run("devices");
  EXPECT_EQ(d.exit_code, 0);
  for (const char* dev : {"ipad4", "ipad3", "iphone5"})
    EXPECT_NE(d.output.find(dev), std::string::npos);
  const Result s = run("shaders --json");
  EXPECT_EQ(s.exit_code, 0);
  EXPECT_NE(s.output.find("\"texture_reads_dependent\""), std::string::npos);
}

// One broken profile does not hide the others: all good ones are listed, the broken one is
// named with its problem, and the exit status says something was wrong.
TEST(Cli, DevicesListsGoodProfilesAndNamesBrokenOnes) {
  const auto dir = temp_dir("devices");
  std::filesystem::create_directories(dir / "devices");
  for (const char* name : {"ipad3", "ipad4"}) {
    std::filesystem::copy_file(
        std::string(skinsim::test_paths::kDataDir) + "/devices/" + name + ".toml",
        dir / "devices" / (std::string(name) + ".toml"));
  }
  std::ifstream in(std::string(skinsim::test_paths::kDataDir) + "/devices/ipad4.toml");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  profile.replace(profile.find("value = 300.0"), 13, "value = 1e-300");
  std::ofstream(dir / "devices" / "broken.toml") << profile;
  const Result r = run("devices --data-dir " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const char* dev : {"ipad3", "ipad4"}) {
    EXPECT_NE(r.output.find(dev), std::string::npos) << r.output;
  }
  EXPECT_NE(r.output.find("skinsim devices: error: " + (dir / "devices" / "broken.toml").string()),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("'gpu.clock_mhz.value': must be a number in [1, 10000] MHz, got 1e-300"),
            std::string::npos)
      << r.output;
}

double frame_ms_of(const std::filesystem::path& result_json) {
  std::ifstream in(result_json);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto key = text.find("\"frame_ms\"");
  EXPECT_NE(key, std::string::npos);
  return std::stod(text.substr(text.find(':', key) + 1));
}

// A what-if profile: the shipped iPad 4 profile with a higher clock (and its range widened
// to contain it) runs the same frame faster, by at most the clock ratio.
TEST(Cli, UserProfileWithHigherClockRunsFaster) {
  const auto dir = temp_dir("whatif");
  std::ifstream in(std::string(skinsim::test_paths::kDataDir) + "/devices/ipad4.toml");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "value = 300.0\nrange = [280.0, 300.0]";
  ASSERT_NE(profile.find(from), std::string::npos);
  profile.replace(profile.find(from), from.size(), "value = 450.0\nrange = [280.0, 450.0]");
  std::ofstream(dir / "fast.toml") << profile;
  const std::string common =
      " --resolution 512x384 --head-triangles 6000 --texture-size 128 --no-reference";
  ASSERT_EQ(run("run --device ipad4 --out " + (dir / "base").string() + common).exit_code, 0);
  const Result fast = run("run --device " + (dir / "fast.toml").string() + " --out " +
                          (dir / "fast").string() + common);
  ASSERT_EQ(fast.exit_code, 0) << fast.output;
  const double base_ms = frame_ms_of(dir / "base" / "result.json");
  const double fast_ms = frame_ms_of(dir / "fast" / "result.json");
  EXPECT_LT(fast_ms, base_ms);
  EXPECT_GE(fast_ms, base_ms * 300.0 / 450.0 - 1e-9);
}

TEST(Cli, InvalidProfileNamesTheField) {
  const auto dir = temp_dir("badprofile");
  std::ifstream in(std::string(skinsim::test_paths::kDataDir) + "/devices/ipad4.toml");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  profile.replace(profile.find("value = 300.0"), 13, "value = -3.0");
  std::ofstream(dir / "bad.toml") << profile;
  const Result r = run("run --no-reference --device " + (dir / "bad.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("gpu.clock_mhz"), std::string::npos) << r.output;
}

TEST(Cli, RunsTheRealHeadScanAndWritesResults) {
  if (!std::filesystem::exists(skinsim::test_paths::kLeePerrySmith))
    GTEST_SKIP() << "asset not present";
  const auto dir = temp_dir("lee");
  const Result r =
      run(std::string("run --scene ") + skinsim::test_paths::kLeePerrySmith +
          " --skin-materials all --units-per-mm 0.035 --resolution 512x384 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"frame.png", "reference.png", "result.json", "irradiance.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  EXPECT_NE(r.output.find("skin PSNR"), std::string::npos);
}

// A skin quad exactly filling an orthographic camera's view (ymag 1; the 4:3 render aspect
// sets the width): the frame and the reference render, and the camera is the file's.
TEST(Cli, OrthographicCameraRendersWithReference) {
  skinsim::scene::testing::GltfFixture f("cli_ortho");
  f.add_quad_mesh(true, true);
  f.json()["nodes"][0]["scale"] = {8.0 / 3.0, 2.0, 1.0};
  f.json()["nodes"][0]["translation"] = {-4.0 / 3.0, -1.0, -1.0};
  f.json()["materials"] = {{{"name", "skin"}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  f.json()["cameras"] = {
      {{"type", "orthographic"},
       {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.01}, {"zfar", 10.0}}}}};
  f.json()["nodes"].push_back({{"camera", 0}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  const std::string scene = f.write_gltf("quad");
  for (const char* technique : {"mobile", "burley"}) {
    const auto dir = f.dir() / technique;
    const Result r = run("run --scene " + scene + " --technique " + technique +
                         " --resolution 64x48 --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("orthographic"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("skin PSNR"), std::string::npos) << r.output;
    for (const char* file : {"frame.png", "reference.png", "result.json"}) {
      EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    }
  }
}

// Without --units-per-mm the scan (a bust 7.95 units tall, its head about 4.4 crown to chin)
// is sized from its head: the run says so and records the scale in result.json. With a wrong
// --units-per-mm it warns, suggests the head's value, says why the LOD shader was chosen, and
// records the warnings; the untextured skin's warning points at --skin-albedo.
TEST(Cli, ScanIsSizedFromItsHeadAndWrongUnitsWarn) {
  if (!std::filesystem::exists(skinsim::test_paths::kLeePerrySmith))
    GTEST_SKIP() << "asset not present";
  const std::string scan = std::string("run --scene ") + skinsim::test_paths::kLeePerrySmith +
                           " --skin-materials all --no-reference --resolution 256x192 --out ";
  const auto read = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };

  const auto sized_dir = temp_dir("lee_sized");
  const Result sized = run(scan + sized_dir.string());
  ASSERT_EQ(sized.exit_code, 0) << sized.output;
  for (const char* expected :
       {"the head is 4.", "units from crown to chin", "sized as a life-size head instead: 0.019",
        "scene scale: 0.019", "units/mm (head height)", "--skin-albedo r,g,b"}) {
    EXPECT_NE(sized.output.find(expected), std::string::npos) << expected << "\n" << sized.output;
  }
  EXPECT_EQ(sized.output.find("LOD shader was chosen"), std::string::npos) << sized.output;
  const std::string sized_json = read(sized_dir / "result.json");
  EXPECT_NE(sized_json.find("\"scene_scale\""), std::string::npos);
  EXPECT_NE(sized_json.find("\"source\": \"head height\""), std::string::npos) << sized_json;
  EXPECT_NE(sized_json.find("\"height_units\": 4."), std::string::npos) << sized_json;

  const auto metres_dir = temp_dir("lee_units");
  const Result metres = run(scan + metres_dir.string() + " --units-per-mm 0.001");
  ASSERT_EQ(metres.exit_code, 0) << metres.output;
  for (const char* expected :
       {"skinsim run: warning: ", "from crown to chin", "at --units-per-mm 0.001",
        "pass --units-per-mm 0.019", "LOD shader was chosen: camera distance",
        "> lod_distance_m 2 m", "has no textures"}) {
    EXPECT_NE(metres.output.find(expected), std::string::npos) << expected << "\n" << metres.output;
  }
  const std::string json = read(metres_dir / "result.json");
  EXPECT_NE(json.find("\"warnings\""), std::string::npos);
  EXPECT_NE(json.find("LOD shader was chosen"), std::string::npos);
  EXPECT_NE(json.find("\"source\": \"--units-per-mm\""), std::string::npos) << json;
}

// --skin-albedo refused before any work, naming the option: a colour out of range, a file
// that is no image, and the built-in head (which has its own painted albedo).
TEST(Cli, SkinAlbedoRefusesBadInput) {
  const auto dir = temp_dir("skin_albedo");
  std::ofstream(dir / "not_an_image.png") << "text";
  std::vector<std::string> cases = {"--skin-albedo 1,2,3 --out " + (dir / "a").string()};
  if (std::filesystem::exists(skinsim::test_paths::kLeePerrySmith)) {
    const std::string scan = std::string("--scene ") + skinsim::test_paths::kLeePerrySmith +
                             " --skin-materials all --out " + (dir / "b").string();
    cases.push_back(scan + " --skin-albedo 256,0,0");
    cases.push_back(scan + " --skin-albedo " + (dir / "not_an_image.png").string());
  }
  for (const std::string& args : cases) {
    const Result r = run("run --no-reference --resolution 64x48 " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("--skin-albedo"), std::string::npos) << args << "\n" << r.output;
  }
}

// Sweep inputs refused before any work: exit 2 with the option or file, line and key named.
TEST(Cli, SweepRefusesBadOutHugeSweepsAndOutOfRangeIntegers) {
  const auto dir = temp_dir("sweep_inputs");
  const Result empty_out = run("sweep --out \"\" --no-charts");
  EXPECT_EQ(empty_out.exit_code, 2);
  EXPECT_NE(empty_out.output.find("--out: empty path"), std::string::npos) << empty_out.output;
  std::ofstream(dir / "file") << "x";
  const Result file_out = run("sweep --no-charts --out " + (dir / "file").string());
  EXPECT_EQ(file_out.exit_code, 2);
  EXPECT_NE(file_out.output.find("is not a directory"), std::string::npos) << file_out.output;

  std::string
      scales;  // 1000 scales x 8 blur iterations x 2 LUT formats x the default sweep's 4 LUT sizes
  for (int i = 1; i <= 1000; ++i) scales += (i > 1 ? "," : "") + std::to_string(i / 1000.0);
  const std::string huge = "sweep --no-charts --techniques mobile --scales " + scales +
                           " --blur-iterations 1,2,3,4,5,6,7,8 --lut-formats rgba8,rgba16f --out " +
                           (dir / "huge").string();
  const Result refused = run(huge);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("64000 configurations, over the limit of 10000"), std::string::npos)
      << refused.output;
  EXPECT_NE(refused.output.find("--max-configs 64000"), std::string::npos) << refused.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "huge"));

  std::ofstream(dir / "big.toml") << "[axes]\nscale = [1]\n[scene]\nhead_triangles = 4294968296\n";
  const Result big = run("sweep --no-charts --sweep-file " + (dir / "big.toml").string());
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_NE(big.output.find("big.toml:4: scene.head_triangles: 4294968296 is out of range"),
            std::string::npos)
      << big.output;

  // A device path in a sweep file is relative to the file, not to the working directory.
  std::ofstream(dir / "dev.toml") << "[axes]\nscale = [1]\n[fixed]\ndevice = \"mine.toml\"\n";
  const Result dev = run("sweep --no-charts --out " + (dir / "dev").string() + " --sweep-file " +
                         (dir / "dev.toml").string());
  EXPECT_EQ(dev.exit_code, 2);
  EXPECT_NE(dev.output.find((dir / "mine.toml").string()), std::string::npos) << dev.output;
}

// A DISPLAY that takes the connection and never answers: the sweep gives up on the charts
// after the display check's deadline, writes everything else and the report, says why, and
// exits 0. The check's attempt is then still waiting inside Xlib, so the process ends without
// its exit handlers (display_check.h); its output must still be complete.
TEST(Cli, SweepWithAHungDisplayWritesTheReportWithoutCharts) {
  skinsim::test::HungDisplay hung;
  ASSERT_FALSE(hung.name().empty()) << "no free port in 6200-6399";
  const auto dir = temp_dir("sweep_hung_display");
  const Result r = [&] {
    const skinsim::test::ScopedEnv display("DISPLAY", hung.name());
    return run(
        "sweep --scales 0.5 --luts 8x32 --resolutions 128x96 --head-triangles 2000 "
        "--texture-size 64 --out " +
        dir.string());
  }();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("X display '" + hung.name() + "' did not answer within"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("report.html (no charts)"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "report.html"));
  EXPECT_TRUE(std::filesystem::exists(dir / "results.json"));
}

// The sweep prints what each swept knob did and the recommendation's range and runner-up,
// the same sentences results.json keeps under "findings".
TEST(Cli, SweepPrintsEachKnobsVerdictAndTheRunnerUp) {
  const auto dir = temp_dir("sweep_verdicts");
  const Result r = run(
      "sweep --no-charts --scales 1,0.25 --luts 8x32 --resolutions 128x96 --head-triangles 2000 "
      "--texture-size 64 --out " +
      dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "results.json");
  const nlohmann::json findings = nlohmann::json::parse(in).at("findings");
  ASSERT_EQ(findings.at("knob_verdicts").size(), 1u) << findings.dump(1);  // the scale
  const std::string verdict = findings["knob_verdicts"][0]["sentence"];
  EXPECT_EQ(verdict.rfind("scale (mobile): ", 0), 0u) << verdict;
  EXPECT_NE(r.output.find("knob verdicts for ipad4, 128x96:\n  " + verdict + "\n"),
            std::string::npos)
      << r.output;
  const nlohmann::json& rec = findings.at("recommendations").at(0);
  for (const char* note : {"range_note", "runner_up_note"}) {
    const std::string text = rec.at(note);
    ASSERT_FALSE(text.empty()) << note;
    EXPECT_NE(r.output.find("  " + text + "\n"), std::string::npos) << r.output;
  }
}

// A scene whose skin materials match nothing: every configuration is still rendered and
// measured over the whole frame, the sweep says once why there are no skin metrics and what to
// pass, and recommends by FLIP over the frame.
TEST(Cli, SweepWithoutSkinComparesWholeFrames) {
  if (!std::filesystem::exists(skinsim::test_paths::kLeePerrySmith))
    GTEST_SKIP() << "asset not present";
  const auto dir = temp_dir("sweep_noskin");
  const Result r =
      run(std::string("sweep --no-charts --scene ") + skinsim::test_paths::kLeePerrySmith +
          " --skin-materials nosuch --units-per-mm 0.04 --scales 0.5,0.25 --luts "
          "8x32 --resolutions 128x96 --out " +
          dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: 128x96: no skin in the frame"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no skin in the frame: --skin-materials nosuch match no material of "
                          "the scene (its materials: "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("pass the skin materials' names, or 'all'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("2 computed, 0 resumed in"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FLIP over the frame"), std::string::npos) << r.output;
}

// `run` on a scene without skin renders and writes everything, warns why, and leaves the skin
// metrics out of result.json (saying why) while the frame metrics are there.
// A run into the directory of an earlier run reuses that run's reference when nothing the
// reference depends on changed (result.json's "reference" marker): the same files and metrics
// as rendering it, in a fraction of the time; any other reference, or damaged files, render.
// A run small enough for a test, reference and metrics included.
constexpr const char* kTinyRun = "run --resolution 128x96 --head-triangles 2000 --texture-size 64 ";

std::string bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A run directory's result.json "quality".
nlohmann::json quality(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "result.json");
  return nlohmann::json::parse(in).at("quality");
}

TEST(Cli, RunReusesTheReferenceOfTheRunItReplaces) {
  const auto dir = temp_dir("reuse_reference");
  const std::string base = kTinyRun;
  const char* kReused = "reference: reused";

  const Result first = run(base + "--out " + dir.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_EQ(first.output.find(kReused), std::string::npos) << first.output;
  const std::string reference = bytes(dir / "reference.png");
  const std::string mask = bytes(dir / "reference_skin.png");
  ASSERT_FALSE(reference.empty());
  ASSERT_FALSE(mask.empty());

  // Another buffer scale: a frame knob, not a reference one.
  const Result second = run(base + "--scale 0.25 --out " + dir.string());
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_NE(second.output.find(kReused), std::string::npos) << second.output;
  EXPECT_EQ(bytes(dir / "reference.png"), reference);
  EXPECT_EQ(bytes(dir / "reference_skin.png"), mask);
  const auto fresh = temp_dir("reuse_reference_fresh");
  const Result rendered = run(base + "--scale 0.25 --out " + fresh.string());
  ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
  EXPECT_EQ(quality(dir), quality(fresh));
  EXPECT_EQ(bytes(dir / "error_flip.png"), bytes(fresh / "error_flip.png"));

  // The key light is a reference knob: rendered again.
  const Result relit = run(base + "--light-azimuth 30 --out " + dir.string());
  ASSERT_EQ(relit.exit_code, 0) << relit.output;
  EXPECT_EQ(relit.output.find(kReused), std::string::npos) << relit.output;
  EXPECT_NE(bytes(dir / "reference.png"), reference);

  // A damaged image with a matching marker: rendered again, not an error.
  ASSERT_EQ(run(base + "--out " + dir.string()).exit_code, 0);
  std::ofstream(dir / "reference.png", std::ios::binary | std::ios::trunc) << "not a png";
  const Result repaired = run(base + "--out " + dir.string());
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_EQ(repaired.output.find(kReused), std::string::npos) << repaired.output;
  EXPECT_EQ(bytes(dir / "reference.png"), reference);
}

// The user's reference store (SKINSIM_CACHE_DIR) serves a run into any directory: the same
// reference, mask, FLIP map and metrics as rendering it; "off" renders it; a cache "directory"
// that is a file is a bad input.
TEST(Cli, RunTakesTheReferenceFromTheStoreInAnyDirectory) {
  const auto store = temp_dir("store_cache");
  const std::string base = kTinyRun;
  const char* kFromStore = "reference: reused from the reference store";
  const auto run_with = [&](const std::string& cache, const std::filesystem::path& out) {
    const skinsim::test::ScopedEnv env("SKINSIM_CACHE_DIR", cache);
    return run(base + "--out " + out.string());
  };

  const auto first = temp_dir("store_first");
  const Result rendered = run_with(store.string(), first);
  ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
  EXPECT_EQ(rendered.output.find("reference: reused"), std::string::npos) << rendered.output;
  const auto second = temp_dir("store_second");
  const Result reused = run_with(store.string(), second);
  ASSERT_EQ(reused.exit_code, 0) << reused.output;
  EXPECT_NE(reused.output.find(kFromStore), std::string::npos) << reused.output;
  for (const char* file : {"reference.png", "reference_skin.png", "error_flip.png"}) {
    EXPECT_EQ(bytes(second / file), bytes(first / file)) << file;
  }
  EXPECT_EQ(quality(second), quality(first));

  const auto off = temp_dir("store_off");
  const Result without = run_with("off", off);
  ASSERT_EQ(without.exit_code, 0) << without.output;
  EXPECT_EQ(without.output.find("reference: reused"), std::string::npos) << without.output;

  const auto not_a_directory = temp_dir("store_file") / "cache";
  std::ofstream(not_a_directory) << "x";
  const Result bad = run_with(not_a_directory.string(), temp_dir("store_bad"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("SKINSIM_CACHE_DIR"), std::string::npos) << bad.output;
}

// A card (one material, not named skin and not shaped like a head, so not taken as skin).
TEST(Cli, RunWithoutSkinWritesFrameMetricsAndSaysWhy) {
  skinsim::scene::testing::GltfFixture f("cli_noskin");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"name", "card"}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  const auto dir = temp_dir("run_noskin");
  const Result r =
      run("run --scene " + f.write_gltf("card") + " --resolution 128x96 --out " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no material is skin by its extras.skinsim.kind"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("skin metrics not available"), std::string::npos) << r.output;
  std::ifstream in(dir / "result.json");
  const nlohmann::json result = nlohmann::json::parse(in);
  const nlohmann::json& q = result.at("quality");
  EXPECT_FALSE(q.contains("flip_skin")) << q;
  EXPECT_TRUE(q.at("flip_frame").is_number()) << q;
  EXPECT_NE(q.at("skin_metrics_unavailable").get<std::string>().find("--skin-materials"),
            std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "error_flip.png"));
}

}  // namespace
