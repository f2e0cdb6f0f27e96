// dinam: scene file → simulated motion → rendered frames → movie.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "app/commands.hpp"
#include "core/error.hpp"

namespace {

int run(int argc, char** argv) {
  using namespace dinam;
  CLI::App app{
      "dinam: physically simulated animation of flexible structures (rigid bar spring "
      "model, explicit central differences, off-screen OpenGL)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "dinam 0.1.0");

  RenderOptions render;
  std::string output;
  CLI::App* render_command =
      app.add_subcommand("render", "Simulate a scene and write its frames (PNG) and movie (mp4)");
  render_command->add_option("scene", render.scene, "Scene file (YAML)")->required();
  render_command->add_option("-o,--output", output,
                             "Output folder (default: the scene's 'output', else out/<name>)");
  render_command->add_option("--frames", render.frames,
                             "Frames to write, A-B (1-based, inclusive); the motion before A is "
                             "still simulated");
  render_command->add_option("--size", render.size, "Image size WxH, e.g. 640x360");
  bool no_video = false;
  render_command->add_flag("--no-video", no_video, "Write the PNG frames only, no movie");
  render_command->add_flag("-q,--quiet", render.quiet, "Print nothing but errors");
  render_command->add_flag("--energy", render.energy_csv,
                           "Also write DIR/energy.csv: kinetic, elastic, gravitational and contact "
                           "energy, and what damping, plasticity, friction, wind and fields did, "
                           "one row per frame");

  std::filesystem::path info_scene;
  CLI::App* info_command =
      app.add_subcommand("info",
                         "Print the model summary of a scene: nodes, bars, springs, "
                         "mass, time step");
  info_command->add_option("scene", info_scene, "Scene file (YAML)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (*render_command) {
      if (!output.empty()) {
        render.output = output;
      }
      render.video = !no_video;
      return run_render(render);
    }
    return run_info(info_scene);
  } catch (const UserError& e) {
    fmt::print(stderr, "{}: error: {}\n", e.loc().known() ? e.loc().to_string() : "dinam",
               e.message());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "dinam: error: {}\n", e.what());
    return dinam::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Nothing may escape: even a failure to print the message exits with the failure code.
  try {
    return run(argc, argv);
  } catch (...) {
    return dinam::kExitFailure;
  }
}
