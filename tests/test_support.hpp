#pragma once
// Helpers shared by the tests: where the data lives, inline scenes, and checks on user errors.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam::test {

inline std::filesystem::path data_dir() {
  return DINAM_TEST_DATA_DIR;
}

// A scene from inline YAML, as if it were the file data/inline.yaml (so mesh paths resolve
// against tests/data).
inline SceneDescription scene_from_yaml(const std::string& yaml) {
  return read_scene_text(yaml, data_dir() / "inline.yaml");
}

// A fresh empty folder under the system's temporary folder, removed by the destructor.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& name) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / ("dinam-test-" + name + "-XXXXXX")).string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot create a temporary folder from " + pattern);
    }
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Expects `action` to throw a UserError at `line` (1-based; 0 to skip) whose message contains
// every one of `fragments`.
inline void expect_user_error(const std::function<void()>& action, int line,
                              std::initializer_list<std::string> fragments) {
  try {
    action();
  } catch (const UserError& e) {
    if (line > 0) {
      EXPECT_EQ(e.loc().line, line) << e.what();
      EXPECT_GT(e.loc().column, 0) << e.what();
    }
    for (const std::string& fragment : fragments) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "message lacks '" << fragment << "': " << e.what();
    }
    return;
  }
  ADD_FAILURE() << "expected a UserError";
}

// Expects `text` (a warning, a printed line) to contain every one of `fragments`.
inline void expect_contains(const std::string& text, std::initializer_list<std::string> fragments) {
  for (const std::string& fragment : fragments) {
    EXPECT_NE(text.find(fragment), std::string::npos) << "lacks '" << fragment << "': " << text;
  }
}

// Writes `text` as the whole of the file `path`.
inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The names of everything directly in `folder`, sorted.
inline std::vector<std::string> folder_entries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The names in `folder` that are temporary files of dinam's (core/output_file.hpp makes them
// NAME.tmp.RANDOM, the movie NAME.part.RANDOM): none may be left after a run, finished or not.
inline std::vector<std::string> temporary_files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp") != std::string::npos || name.find(".part") != std::string::npos) {
      names.push_back(name);
    }
  }
  return names;
}

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// A path quoted for a shell command line (it holds no quote itself).
inline std::string shell_quoted(const std::filesystem::path& path) {
  std::string text = "'";  // built in steps: "'" + … trips GCC 12's false -Wrestrict (PR 105329)
  text += path.string();
  text += '\'';
  return text;
}

// The shell command line that runs the dinam program with `arguments`.
inline std::string dinam_command(const std::string& arguments) {
  return shell_quoted(DINAM_PROGRAM) + " " + arguments;
}

// Runs a shell command line and collects what it prints.
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    return result;
  }
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
    result.output += buffer.data();
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// The argument vector of dinam with `arguments`: the strings and the null-terminated pointers
// into them, for posix_spawn. It stays where it was made, so the pointers stay valid.
class DinamArgv {
 public:
  explicit DinamArgv(const std::vector<std::string>& arguments) : strings_{DINAM_PROGRAM} {
    strings_.insert(strings_.end(), arguments.begin(), arguments.end());
    for (std::string& s : strings_) {
      pointers_.push_back(s.data());
    }
    pointers_.push_back(nullptr);
  }
  DinamArgv(const DinamArgv&) = delete;
  DinamArgv& operator=(const DinamArgv&) = delete;
  char* const* data() const { return pointers_.data(); }

 private:
  std::vector<std::string> strings_;
  std::vector<char*> pointers_;
};

// Starts dinam with `arguments` in the background, its stderr written to `log`; returns its
// process id (0 when it could not start), for a test that signals it and waits.
inline pid_t spawn_dinam(const std::vector<std::string>& arguments,
                         const std::filesystem::path& log) {
  const DinamArgv argv(arguments);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, DINAM_PROGRAM, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : 0;
}

// Runs dinam with `arguments`, each passed as it is (no shell: names with spaces, quotes or a
// leading dash arrive unchanged), with `environment` entries ("NAME=value") added, and collects
// what it prints on both streams.
inline CommandResult run_dinam(const std::vector<std::string>& arguments,
                               const std::vector<std::string>& environment = {}) {
  const DinamArgv argv(arguments);
  std::vector<std::string> env_text(environment);
  for (char** e = environ; *e != nullptr; ++e) {
    env_text.emplace_back(*e);
  }
  std::vector<char*> envp;
  for (std::string& e : env_text) {
    envp.push_back(e.data());
  }
  envp.push_back(nullptr);
  int pipe_ends[2] = {-1, -1};
  CommandResult result;
  if (pipe(pipe_ends) != 0) {
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, DINAM_PROGRAM, &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  std::array<char, 4096> buffer{};
  ssize_t got = 0;
  while ((got = read(pipe_ends[0], buffer.data(), buffer.size())) > 0) {
    result.output.append(buffer.data(), static_cast<std::size_t>(got));
  }
  close(pipe_ends[0]);
  if (spawned == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return result;
}

// The model's object of that name (a shipped scene's objects may be reordered or added to); a
// test failure, and the first object, when there is none.
inline const ModelObject& object_named(const Model& model, const std::string& name) {
  for (const ModelObject& object : model.objects) {
    if (object.name == name) {
      return object;
    }
  }
  ADD_FAILURE() << "no object '" << name << "'";
  return model.objects.front();
}

// `text` with the first `from` replaced by `to`; a test failure when there is none.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "no '" << from << "' to replace";
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The acceleration a of the least-squares fit s = s0 + v0 t + ½ a t² to the samples (t, s) with
// t ≥ from: how fast a body slides, after its landing transient.
inline double fitted_acceleration(const std::vector<std::pair<double, double>>& track,
                                  double from) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const auto& [t, s] : track) {
    if (t >= from) {
      const Eigen::Vector3d basis(1.0, t, 0.5 * t * t);
      normal += basis * basis.transpose();
      rhs += basis * s;
    }
  }
  return normal.ldlt().solve(rhs)[2];
}

}  // namespace dinam::test
