#pragma once
// What a snapshot run found, for a CI system and for a person: a JUnit XML report (one test case
// per frame, grouped by scene, as GitLab, Jenkins, GitHub's test reporters and Azure read it) and
// one self-contained HTML page (the expected, actual and difference pictures of every frame side
// by side, inside the page, with each measure against its limit; failures first).
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "io/image_compare.hpp"

namespace dinam {

enum class FrameOutcome {
  kMatched,   // within its tolerance
  kDiffers,   // past some limit
  kNoGolden,  // nothing to compare with
  kUpdated,   // written as the golden (--update)
};

struct FrameResult {
  std::string scene;  // the scene's name
  int frame = 0;
  std::string name;  // <scene>_NNNN, the golden's name without .png
  FrameOutcome outcome = FrameOutcome::kMatched;
  ImageComparison comparison;  // its figures (the difference picture for the page)
  ImageTolerance limits;       // what it was checked under
  bool has_regions = false;    // whether the tolerance file masks or weighs part of it
  double seconds = 0.0;        // drawing and comparing it
  Image actual;
  Image expected;      // empty without a golden
  std::string detail;  // the failure in words, or where the golden went
  // With --framing: the subject's span in the picture (fractions of its width and height) and
  // what is wrong with the shot ("" when it holds); a badly framed frame fails.
  bool framing_checked = false;
  float subject_width = 0.0f;
  float subject_height = 0.0f;
  float min_fill = 0.0f;
  std::string framing_problem;
};

bool failed(const FrameResult& result);

// Both write through an output file (a new temporary, renamed into place).
void write_junit_report(const std::filesystem::path& path, const std::vector<FrameResult>& results);
void write_html_report(const std::filesystem::path& path, const std::vector<FrameResult>& results);

}  // namespace dinam
