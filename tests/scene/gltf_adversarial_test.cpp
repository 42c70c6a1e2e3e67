// Hostile and malformed glTF inputs, each generated here: every one must end in a SceneError
// that starts with the file's path and names the problem, within a time and memory bound.
// Each load runs in a forked child under RLIMIT_AS and alarm(), so a regression to a huge
// allocation, a stack overflow or a hang fails the case instead of taking the machine down.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "io/json_input.h"
#include "scene/error.h"
#include "scene/gltf_loader.h"
#include "tests/scene/gltf_fixture.h"

namespace skinsim::scene {
namespace {

using testing::GltfFixture;

// Address-space limit for one load. A sanitizer reserves terabytes of shadow memory, so
// the limit only applies to plain builds.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kLimitMemory = false;
#else
constexpr bool kLimitMemory = true;
#endif
constexpr rlim_t kMaxAddressSpace = rlim_t{1} << 30;
constexpr unsigned kMaxSeconds = 20;

// Builds the hostile file inside the fixture's directory; returns its path.
using Generator = std::function<std::string(GltfFixture&)>;

struct Case {
  const char* name;
  Generator make;
  const char* expected;  // substring of the error message
};

std::string nested(char open, char close, int depth) {
  return std::string(static_cast<std::size_t>(depth), open) +
         std::string(static_cast<std::size_t>(depth), close);
}

// A GLB from explicit header/chunk fields, so lengths can lie.
std::string glb_bytes(std::uint32_t total, const std::string& json, std::uint32_t json_length,
                      const std::string& bin, std::uint32_t bin_length, bool with_bin) {
  std::string out;
  auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(0x46546C67);
  u32(2);
  u32(total);
  u32(json_length);
  u32(0x4E4F534A);
  out += json;
  if (with_bin) {
    u32(bin_length);
    u32(0x004E4942);
    out += bin;
  }
  return out;
}

std::string quad_json(GltfFixture& f) {
  f.add_quad_mesh(true, true);
  f.json()["buffers"][0].erase("uri");
  std::string json = f.json().dump();
  while (json.size() % 4) json += ' ';
  return json;
}

// A PNG signature and IHDR chunk claiming width x height: enough for a header reader.
std::vector<unsigned char> png_header(std::uint32_t width, std::uint32_t height) {
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                    0,    0,   0,   13,  'I',  'H',  'D',  'R'};
  for (std::uint32_t v : {width, height}) {
    for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<unsigned char>(v >> s));
  }
  for (unsigned char b : {8, 6, 0, 0, 0}) png.push_back(b);  // 8-bit RGBA, no interlace
  for (int i = 0; i < 4; ++i) png.push_back(0);              // CRC (not checked by readers)
  for (int i = 0; i < 64; ++i) png.push_back(0);
  return png;
}

// Uses the image as the quad's base colour texture, so the loader must decode it.
void texture_quad(GltfFixture& f, nlohmann::json image) {
  f.add_quad_mesh(true, true);
  f.json()["images"] = {image};
  f.json()["textures"] = {{{"source", 0}}};
  f.json()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
}

std::string with_buffer_uri(GltfFixture& f, const std::string& uri) {
  f.add_quad_mesh(true, true);
  const std::string path = f.write_gltf("scene");
  f.json()["buffers"][0]["uri"] = uri;
  std::ofstream(path) << f.json().dump();
  return path;
}

std::string fifo(GltfFixture& f) {
  const std::string p = (f.dir() / "pipe").string();
  EXPECT_EQ(mkfifo(p.c_str(), 0600), 0);
  return "pipe";
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"BadJson", [](GltfFixture& f) { return f.write_raw("bad.gltf", "{\"asset\": ["); },
       "cannot parse"},
      {"DeepExtrasGltf",
       [](GltfFixture& f) {
         return f.write_raw("deep.gltf", "{\"asset\":{\"version\":\"2.0\"},\"extras\":" +
                                             nested('[', ']', 15000) + "}");
       },
       "nests deeper than 64 levels"},
      {"DeepObjectsGltf",
       [](GltfFixture& f) {
         std::string s;
         for (int i = 0; i < 15000; ++i) s += "{\"a\":";
         return f.write_raw("deep_obj.gltf", s + "1" + std::string(15000, '}'));
       },
       "nests deeper than 64 levels"},
      {"DeepExtrasGlb",
       [](GltfFixture& f) {
         std::string json =
             "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + nested('[', ']', 15000) + "}";
         while (json.size() % 4) json += ' ';
         const auto n = static_cast<std::uint32_t>(json.size());
         return f.write_raw("deep.glb", glb_bytes(20 + n, json, n, "", 0, false));
       },
       "nests deeper than 64 levels"},
      {"AccessorCountWithoutBuffer",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         auto& a = f.json()["accessors"][0];
         a.erase("bufferView");
         a["count"] = (1u << 28) - 1;
         return f.write_gltf("scene");
       },
       "without a bufferView exceeds"},
      {"AccessorCountBeyondView",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         f.json()["accessors"][0]["count"] = 4294967295u;
         return f.write_glb("scene");
       },
       "do not fit bufferViews"},
      {"SparseCountBeyondView",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         f.json()["accessors"][0]["sparse"] = {
             {"count", 1000000000},
             {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
             {"values", {{"bufferView", 0}}}};
         return f.write_glb("scene");
       },
       "sparse.count"},
      {"BufferUriFifo", [](GltfFixture& f) { return with_buffer_uri(f, fifo(f)); },
       "buffers[0].uri 'pipe'"},
      {"BufferUriDirectory",
       [](GltfFixture& f) {
         std::filesystem::create_directory(f.dir() / "sub");
         return with_buffer_uri(f, "sub");
       },
       "buffers[0].uri 'sub'"},
      {"BufferUriDevZero", [](GltfFixture& f) { return with_buffer_uri(f, "/dev/zero"); },
       "buffers[0].uri '/dev/zero'"},
      {"BufferUriMissing", [](GltfFixture& f) { return with_buffer_uri(f, "gone.bin"); },
       "buffers[0].uri 'gone.bin'"},
      {"BufferUriShellExpansion",
       [](GltfFixture& f) { return with_buffer_uri(f, "$(touch pwned).bin"); },
       "buffers[0].uri '$(touch pwned).bin'"},
      {"ImageUriFifo",
       [](GltfFixture& f) {
         texture_quad(f, {{"uri", fifo(f)}});
         return f.write_gltf("scene");
       },
       "images[0].uri 'pipe'"},
      {"ImageUriDevZero",
       [](GltfFixture& f) {
         texture_quad(f, {{"uri", "/dev/zero"}});
         return f.write_gltf("scene");
       },
       "images[0].uri '/dev/zero'"},
      {"HugeImageFile",
       [](GltfFixture& f) {
         const auto png = png_header(23000, 23000);
         std::ofstream((f.dir() / "big.png").string(), std::ios::binary)
             .write(reinterpret_cast<const char*>(png.data()), static_cast<long>(png.size()));
         texture_quad(f, {{"uri", "big.png"}});
         return f.write_gltf("scene");
       },
       "23000 x 23000 pixels is larger than skinsim's limit of 8192 x 8192"},
      {"HugeImageInBufferView",
       [](GltfFixture& f) {
         const auto png = png_header(9000, 100);
         texture_quad(
             f, {{"bufferView", f.add_view(png.data(), png.size())}, {"mimeType", "image/png"}});
         return f.write_glb("scene");
       },
       "9000 x 100 pixels is larger"},
      {"ManyNodes",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         auto& nodes = f.json()["nodes"];
         auto& roots = f.json()["scenes"][0]["nodes"];
         for (int i = 1; i < 100000; ++i) {
           nodes.push_back({{"mesh", 0}});
           roots.push_back(i);
         }
         return f.write_glb("scene");
       },
       "100000 nodes; skinsim reads at most 4096"},
      {"GlbLengthLies",
       [](GltfFixture& f) {
         const std::string json = quad_json(f);
         const auto n = static_cast<std::uint32_t>(json.size());
         return f.write_raw("s.glb", glb_bytes(1u << 31, json, n, "", 0, false));
       },
       "GLB header says"},
      {"GlbJsonChunkTooLong",
       [](GltfFixture& f) {
         const std::string json = quad_json(f);
         const auto n = static_cast<std::uint32_t>(json.size());
         return f.write_raw("s.glb", glb_bytes(20 + n, json, 0xFFFFFFF0u, "", 0, false));
       },
       "JSON chunk length"},
      {"GlbBinChunkTooLong",
       [](GltfFixture& f) {
         const std::string json = quad_json(f);
         const std::string bin(reinterpret_cast<const char*>(f.bin().data()), f.bin().size());
         const auto n = static_cast<std::uint32_t>(json.size());
         const auto total = static_cast<std::uint32_t>(28 + n + bin.size());
         return f.write_raw("s.glb", glb_bytes(total, json, n, bin, 0x7FFFFFFF, true));
       },
       "BIN chunk length"},
      {"GlbTruncatedChunkHeader",
       [](GltfFixture& f) {
         const std::string json = quad_json(f);
         const auto n = static_cast<std::uint32_t>(json.size());
         return f.write_raw("s.glb", glb_bytes(24 + n, json, n, "", 0, false) + "abcd");
       },
       "inside a chunk header"},
      {"NegativeMeshIndex",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         f.json()["nodes"][0]["mesh"] = -5;
         f.json()["nodes"][0]["camera"] = -2147483648LL;
         return f.write_glb("scene");
       },
       "contains no triangles"},  // tinygltf reads a negative index as "none"
      {"HugeByteOffset",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         f.json()["accessors"][0]["byteOffset"] = 4294967295u;
         return f.write_glb("scene");
       },
       "accessors[0]"},
      {"NegativeChildIndex",
       [](GltfFixture& f) {
         f.add_quad_mesh(false, false);
         f.json()["nodes"].push_back({{"children", {-1}}});
         f.json()["scenes"][0]["nodes"].push_back(1);
         return f.write_glb("scene");
       },
       "node index -1 out of range"},
  };
  return all;
}

// Runs the load in a child; returns "" when it threw SceneError starting with `path` and
// containing `expected`, else what went wrong.
std::string load_in_child(const std::string& path, const std::string& expected) {
  int fds[2];
  if (pipe(fds) != 0) return "pipe() failed";
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    if (kLimitMemory) {
      const rlimit limit{kMaxAddressSpace, kMaxAddressSpace};
      setrlimit(RLIMIT_AS, &limit);
    }
    alarm(kMaxSeconds);
    std::string verdict;
    try {
      LoadOptions o;
      o.warn = [](const std::string&) {};
      o.environment_size = 2;
      load_gltf(path, o);
      verdict = "loaded without an error";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      if (msg.rfind(path, 0) != 0 || msg.find(expected) == std::string::npos) {
        verdict = "unexpected message: " + msg;
      }
    } catch (const std::exception& e) {
      verdict = std::string("not a SceneError: ") + e.what();
    }
    if (!verdict.empty()) (void)!write(fds[1], verdict.data(), verdict.size());
    _exit(verdict.empty() ? 0 : 1);
  }
  close(fds[1]);
  std::string verdict;
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;)
    verdict.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    return "child killed by signal " + std::to_string(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGALRM ? " (time limit)" : "");
  }
  return verdict;
}

class AdversarialGltf : public ::testing::TestWithParam<Case> {};

TEST_P(AdversarialGltf, FailsCleanlyWithinBounds) {
  GltfFixture f(std::string("adversarial_") + GetParam().name);
  const std::string path = GetParam().make(f);
  EXPECT_EQ(load_in_child(path, GetParam().expected), "") << path;
}

INSTANTIATE_TEST_SUITE_P(Inputs, AdversarialGltf, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(JsonDepth, CountsOnlyBracketsOutsideStrings) {
  using io::find_nesting_beyond;
  EXPECT_FALSE(find_nesting_beyond("[[1]]", 2));
  EXPECT_EQ(find_nesting_beyond("[[[1]]]", 2), 2u);
  EXPECT_EQ(find_nesting_beyond("{\"a\":{\"b\":[", 2), 10u);
  EXPECT_FALSE(find_nesting_beyond("[\"[[[[{{{{\"]", 1));
  EXPECT_FALSE(find_nesting_beyond("[\"\\\"[[[\"]", 1));    // escaped quote stays in the string
  EXPECT_EQ(find_nesting_beyond("[\"\\\\\"[[]]]", 2), 6u);  // "\\" ends the string
  EXPECT_FALSE(find_nesting_beyond("[][][][][]", 1));
}

// Brackets inside strings are not nesting: a valid file with such a string still loads.
TEST(JsonDepth, BracketsInStringsDoNotCount) {
  GltfFixture f("depth_in_string");
  f.add_quad_mesh(true, true);
  f.json()["asset"]["extras"] = {{"note", std::string(500, '[')}};
  LoadOptions o;
  o.warn = [](const std::string&) {};
  o.environment_size = 2;
  EXPECT_EQ(load_gltf(f.write_gltf("scene"), o).meshes.size(), 1u);
}

}  // namespace
}  // namespace skinsim::scene
