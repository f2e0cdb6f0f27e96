#pragma once
// The program's command line. Each command registers its own subcommand and options (in its
// *_command.cpp) and says how it runs once they are parsed; main.cpp lists the commands, parses
// and runs the one named.
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "core/cpu_share.hpp"

namespace dinam {

struct Command {
  CLI::App* subcommand = nullptr;  // parsed() once the command line names it
  // Runs the command with the options as parsed, on the threads chosen (--threads, else the
  // process's share of the machine).
  std::function<int(const ThreadChoice&)> run;
};

// --threads, on the commands that simulate: stored in `threads`, which outlives the parse.
void add_threads_option(CLI::App& command, std::optional<int>& threads);

// An option that, given a value that is not empty, sets `value` (an empty one, `-o ''`, leaves
// the default). `value` outlives the parse (a field of options the command's run holds).
template <typename T>
CLI::Option* add_optional_option(CLI::App& command, const std::string& name,
                                 std::optional<T>& value, const std::string& description) {
  return command.add_option_function<std::string>(
      name,
      [&value](const std::string& text) {
        if (!text.empty()) {
          value = T(text);
        }
      },
      description);
}

Command add_render_command(CLI::App& app, std::optional<int>& threads);
Command add_simulate_command(CLI::App& app, std::optional<int>& threads);
Command add_movie_command(CLI::App& app);
Command add_snapshot_command(CLI::App& app, std::optional<int>& threads);
Command add_modes_command(CLI::App& app, std::optional<int>& threads);
Command add_view_command(CLI::App& app);
Command add_info_command(CLI::App& app, std::optional<int>& threads);

}  // namespace dinam
