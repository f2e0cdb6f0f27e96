#include "app/command_support.hpp"

#include <fmt/format.h>

#include <csignal>
#include <cstring>
#include <system_error>

#include "core/error.hpp"
#include "dynamics/contact/contact_at_rest.hpp"

namespace dinam {

namespace {

// Contact pairs that overlap at rest by more than this share of their reach are refused: a hair
// of overlap is a mesh modelled touching (a cloth laid on a table), more is a radius too large for
// the mesh or objects placed inside each other (dynamics/contact/contact_at_rest.hpp).
constexpr double kRestOverlapTolerance = 0.05;

void refuse_contact_overlap_at_rest(const SceneDescription& scene, const Model& model) {
  const std::optional<RestOverlap> overlap = contact_overlap_at_rest(model, kRestOverlapTolerance);
  if (!overlap) {
    return;
  }
  const std::string& name_a = model.objects[overlap->object_a].name;
  const std::string& name_b = model.objects[overlap->object_b].name;
  const ObjectContactDesc& own = scene.objects[overlap->object_a].contact;
  const FileLoc& loc =
      own.radius_loc.known() ? own.radius_loc : scene.objects[overlap->object_a].loc;
  const std::string where = overlap->object_a == overlap->object_b
                                ? fmt::format("within '{}'", name_a)
                                : fmt::format("between '{}' and '{}'", name_a, name_b);
  throw_user_error(
      loc,
      "{} contact pairs {} overlap in the starting positions, the deepest {:.3g} m apart where "
      "their radii reach {:.3g} m: the contact would push them apart from the first step with "
      "energy from nowhere. Give a contact radius below half the distance between parts of the "
      "mesh that no bar joins (contact: {{radius: m}}), or place the objects apart",
      overlap->pairs, where, overlap->distance, overlap->reach);
}

}  // namespace

Model build_model_telling_warnings(const SceneDescription& scene) {
  // The scene's warnings first: one may explain the error that stops the model (a y-up mesh whose
  // pins, given in the other axes, hold no node).
  for (const std::string& warning : scene.warnings) {
    fmt::print(stderr, "{}\n", warning);
  }
  Model model = build_model(scene);
  for (const std::string& warning : model.warnings) {
    fmt::print(stderr, "{}\n", warning);
  }
  refuse_contact_overlap_at_rest(scene, model);
  return model;
}

namespace {

extern "C" void ask_to_stop(int signal) {
  request_stop(signal);
  // A second signal ends the program; SA_RESETHAND (below) restores the default before this runs.
}

void handle_signal(int signal, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  // Interrupted system calls resume (a write of a frame, a wait for ffmpeg); the loops see the
  // request at their next check.
  action.sa_flags = SA_RESTART | (handler == SIG_DFL ? 0 : SA_RESETHAND);
  sigaction(signal, &action, nullptr);
}

}  // namespace

void create_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  // A file where the folder (or one above it) should be is the user's to move, not a failure.
  for (std::filesystem::path above = folder; !above.empty() && above != above.root_path();
       above = above.parent_path()) {
    if (std::filesystem::exists(above, ec) && !std::filesystem::is_directory(above, ec)) {
      throw_user_error({}, "the output folder {} cannot be made: {} is a file; give -o a folder",
                       folder.string(), above.string());
    }
  }
  std::filesystem::create_directories(folder, ec);
  if (ec == std::errc::permission_denied || ec == std::errc::read_only_file_system ||
      ec == std::errc::operation_not_permitted) {
    throw_user_error({},
                     "the output folder {} cannot be made: {}; give -o a folder you can write to",
                     folder.string(), ec.message());
  }
  if (ec) {
    throw_user_error({},
                     "the output folder {} cannot be made: {}; give -o a folder you can write to",
                     folder.string(), ec.message());
  }
}

StopOnSignals::StopOnSignals() {
  handle_signal(SIGINT, ask_to_stop);
  handle_signal(SIGTERM, ask_to_stop);
}

StopOnSignals::~StopOnSignals() {
  handle_signal(SIGINT, SIG_DFL);
  handle_signal(SIGTERM, SIG_DFL);
}

}  // namespace dinam
