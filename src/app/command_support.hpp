#pragma once
// Small things every command needs: the model with its warnings told, output folders, and
// stopping cleanly on SIGINT or SIGTERM (and, through their headers, wall time and the movie's
// format).
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/stop_request.hpp"
#include "core/wall_clock.hpp"
#include "model/model.hpp"
#include "run/movie_format.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// The scene's model, its warnings (a mesh's degenerate faces, dropped) printed to stderr.
Model build_model_telling_warnings(const SceneDescription& scene);

// Creates a folder and its parents; throws RuntimeError naming it when that fails.
void create_folder(const std::filesystem::path& folder);

// While one exists, SIGINT and SIGTERM only ask the command to stop (core/stop_request.hpp;
// the first one; a second ends the program at once, as without it).
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
};

}  // namespace dinam
