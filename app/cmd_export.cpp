// `skinsim export`: a technique's frame as GLSL ES shaders and a frame description
// (driver/frame/frame_export.h), to run on a device or feed to an offline shader compiler.
#include <fmt/format.h>

#include <filesystem>

#include "app/cli_options.h"
#include "app/commands.h"
#include "driver/frame/frame_export.h"
#include "io/atomic_file.h"
#include "io/free_space.h"
#include "io/run_directory.h"

namespace skinsim::app {

namespace {

struct ExportOptions {
  DeviceOptions device;
  driver::SceneSource scene;
  pipeline::PipelineConfig config;
  std::string glsl = "es100";
  std::string out = "export";
  bool data = false;
};

int run_export(const ExportOptions& o) {
  const sim::sl::GlslDialect dialect = driver::parse_glsl_dialect(o.glsl);
  const gpu_model::DeviceProfile device = load_device(o.device);
  const pipeline::PipelineConfig config = driver::resolve_config(o.config, device);
  io::RunDirectory run_directory(o.out, "export");

  driver::FrameJob job;
  job.device = &device;
  job.config = config;
  job.scene = o.scene;
  job.scene.warn = [](const std::string& message) {
    fmt::print(stderr, "skinsim export: warning: {}\n", message);
  };
  job.threads = o.device.threads;
  driver::ExportedFrame frame = driver::export_frame(job, dialect, o.data);
  frame.description["scene"] = o.scene.label();
  const std::string description = frame.description.dump(2) + "\n";
  std::uintmax_t bytes = description.size();
  for (const auto& entry : frame.files) bytes += entry.second.size();
  const std::filesystem::path& out = run_directory.staging();
  io::require_free_space(out, bytes, "skinsim export --out " + o.out);
  std::filesystem::create_directories(out / "shaders");
  if (o.data) std::filesystem::create_directories(out / "data");
  for (const auto& [path, source_text] : frame.files) {
    io::write_file_atomically((out / path).string(), source_text);
  }
  io::write_file_atomically((out / "frame.json").string(), description);
  run_directory.commit();
  fmt::print("skinsim export: {} on {}, {}x{}: {} passes, {} files (GLSL {}), {} in {}/\n",
             config.technique, device.name, config.width, config.height,
             frame.description["passes"].size(), frame.files.size(), o.glsl, io::megabytes(bytes),
             o.out);
  return 0;
}

}  // namespace

Command add_export_command(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write a technique's frame as GLSL ES shaders and frame.json (passes, targets, "
      "bindings, state), emitted from the shaders the emulator runs");
  add_device_options(*cmd, options->device);
  add_scene_options(*cmd, options->scene);
  add_pipeline_options(*cmd, options->config);
  cmd->add_option("--glsl", options->glsl,
                  "GLSL ES version: es100 (OpenGL ES 2.0 with the extensions the SGX has) or "
                  "es300 (OpenGL ES 3.0)")
      ->capture_default_str();
  cmd->add_flag("--data", options->data,
                "Also write the vertex data, textures and every pass's targets as the emulator "
                "rendered them (data/*.bin), for replaying and comparing the frame elsewhere");
  cmd->add_option("--out", options->out, "Output directory")->capture_default_str();
  return [options] { return run_export(*options); };
}

}  // namespace skinsim::app
