// Runs the real skinsim binary as a user would and checks exit codes and messages.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct Result {
  int exit_code;
  std::string output;  // stdout + stderr
};

Result run(const std::string& args) {
  const std::string command = std::string(SKINSIM_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

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
  EXPECT_NE(r.output.find("buffer_scale"), std::string::npos) << r.output;
  const Result lut = run("run --lut 30x128 --no-reference");
  EXPECT_EQ(lut.exit_code, 2);
  EXPECT_NE(lut.output.find("lut width"), std::string::npos) << lut.output;
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
  const Result r = run("run --scene " + path.string() + " --no-reference --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(path.string()), std::string::npos) << r.output;
}

TEST(Cli, UnknownDeviceIsExitTwo) {
  const Result r = run("run --device nosuchphone --no-reference");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nosuchphone"), std::string::npos) << r.output;
}

TEST(Cli, DevicesAndShadersPrintTables) {
  const Result d = run("devices");
  EXPECT_EQ(d.exit_code, 0);
  for (const char* dev : {"ipad4", "ipad3", "iphone5"}) EXPECT_NE(d.output.find(dev), std::string::npos);
  const Result s = run("shaders --json");
  EXPECT_EQ(s.exit_code, 0);
  EXPECT_NE(s.output.find("\"texture_reads_dependent\""), std::string::npos);
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
  std::ifstream in(std::string(SKINSIM_DATA_DIR) + "/devices/ipad4.toml");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "value = 300.0\nrange = [280.0, 300.0]";
  ASSERT_NE(profile.find(from), std::string::npos);
  profile.replace(profile.find(from), from.size(), "value = 450.0\nrange = [280.0, 450.0]");
  std::ofstream(dir / "fast.toml") << profile;
  const std::string common = " --resolution 512x384 --head-triangles 6000 --texture-size 128 --no-reference";
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
  std::ifstream in(std::string(SKINSIM_DATA_DIR) + "/devices/ipad4.toml");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  profile.replace(profile.find("value = 300.0"), 13, "value = -3.0");
  std::ofstream(dir / "bad.toml") << profile;
  const Result r = run("run --no-reference --device " + (dir / "bad.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("gpu.clock_mhz"), std::string::npos) << r.output;
}

TEST(Cli, RunsTheRealHeadScanAndWritesResults) {
  if (!std::filesystem::exists(SKINSIM_TEST_LEE)) GTEST_SKIP() << "asset not present";
  const auto dir = temp_dir("lee");
  const Result r = run(std::string("run --scene ") + SKINSIM_TEST_LEE +
                       " --skin-materials all --units-per-mm 0.04 --resolution 512x384 --out " +
                       dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"frame.png", "reference.png", "result.json", "irradiance.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  EXPECT_NE(r.output.find("skin PSNR"), std::string::npos);
}

}  // namespace
