// dinam: scene file → simulated motion → rendered frames → movie.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/cpu_share.hpp"
#include "core/error.hpp"
#include "core/thread_governor.hpp"
#include "core/version.hpp"

namespace {

// A file whose name starts with a dash reads as an option; when the command line did not parse,
// say so for each argument that is such a file, and how to name it.
void explain_dash_led_files(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    std::error_code ec;
    if (argument.size() > 1 && argument[0] == '-' && argument != "--" &&
        std::filesystem::exists(argument, ec)) {
      fmt::print(stderr,
                 "dinam: '{0}' is a file, but a name that starts with '-' reads as an option; "
                 "write it as ./{0}\n",
                 argument);
    }
  }
}

int run(int argc, char** argv) {
  using namespace dinam;
  CLI::App app{
      "dinam: movies of flexible structures that move as real ones do (cloth, ropes, cables, "
      "wire) from a scene file: a rigid bar spring model of real materials, stepped by central "
      "differences or implicit steps as long as a frame, with wind, contact, friction, plasticity "
      "and tearing; frames drawn off-screen with OpenGL, the movie by ffmpeg, the motion as "
      "caches for Blender, Houdini and USD. First: 'dinam render scenes/flag.yaml'; every key of "
      "a scene is in docs/scene-format.md, the commands in docs/commands.md"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dinam ") + kVersion);
  // The commands that simulate take the thread count; without it, DINAM_THREADS, else the CPUs
  // the process is given (core/cpu_share.hpp).
  std::optional<int> threads;
  const std::vector<Command> commands = {
      add_render_command(app, threads), add_simulate_command(app, threads),
      add_movie_command(app),           add_snapshot_command(app, threads),
      add_modes_command(app, threads),  add_view_command(app),
      add_info_command(app, threads),
  };

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
    explain_dash_led_files(argc, argv);
    return kExitBadInput;
  }

  try {
    const ThreadChoice thread_choice = choose_threads(threads);
    set_thread_policy(thread_choice);
    // OSMesa's llvmpipe draws on as many threads as the machine has CPUs unless told otherwise:
    // the same share as the simulation's, unless the user has set it.
    setenv("LP_NUM_THREADS", std::to_string(thread_choice.threads).c_str(), 0);
    for (const Command& command : commands) {
      if (command.subcommand->parsed()) {
        return command.run(thread_choice);
      }
    }
    return kExitBadInput;  // CLI11 requires a subcommand: not reached
  } catch (const Interrupted& e) {
    fmt::print(stderr, "dinam: {}\n", e.what());
    return 128 + e.signal();
  } catch (const UserError& e) {
    fmt::print(stderr, "{}: error: {}\n", e.loc().known() ? e.loc().to_string() : "dinam",
               e.message());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    // Every reader checks what a file claims before it allocates; what is left is a run larger
    // than the machine, told with what it was given to read.
    std::string given;
    for (int k = 1; k < argc; ++k) {
      given += std::string(" ") + argv[k];
    }
    fmt::print(stderr,
               "dinam: error: out of memory: an allocation failed in 'dinam{}'; 'dinam info "
               "SCENE' estimates what a scene needs and what the machine has (DINAM_MEMORY_LIMIT "
               "sets the limit it holds to)\n",
               given);
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
