// Progress in a log: where stderr is not a terminal (a farm job, CI, this test), a line each time
// another tenth of the frames is done, saying how far, how long it has taken and what is left.
#include "run/progress.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace dinam {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) {
    lines.push_back(line);
  }
  return lines;
}

TEST(Progress, InALogTellsEveryTenthOfTheFramesWithTheTimeLeft) {
  ASSERT_EQ(isatty(STDERR_FILENO), 0) << "run it with stderr in a file or a pipe";
  testing::internal::CaptureStderr();
  {
    Progress progress(120, true, "simulate");
    for (int frame = 1; frame <= 120; ++frame) {
      progress.update(frame, fmt::format("t = {:.2f} s", frame / 20.0));
    }
  }
  const std::vector<std::string> lines = lines_of(testing::internal::GetCapturedStderr());
  // A line at 12, 24, … 120 frames; one more only if 30 s passed between two frames.
  ASSERT_GE(lines.size(), 10U);
  for (int tenth = 1; tenth <= 10; ++tenth) {
    const std::string head = fmt::format("simulate frame {}/120 ({}%), ", 12 * tenth, 10 * tenth);
    bool found = false;
    for (const std::string& line : lines) {
      found = found || line.rfind(head, 0) == 0;
    }
    EXPECT_TRUE(found) << "no line starts '" << head << "'";
  }
  EXPECT_NE(lines.front().find(" s elapsed, about "), std::string::npos) << lines.front();
  EXPECT_NE(lines.front().find(" s left; t = 0.60 s"), std::string::npos) << lines.front();
  EXPECT_NE(lines.back().find("about 0 s left"), std::string::npos) << lines.back();
  for (const std::string& line : lines) {
    EXPECT_EQ(line.find('\r'), std::string::npos);  // no redrawing in a log
  }
}

TEST(Progress, QuietSaysNothing) {
  testing::internal::CaptureStderr();
  {
    Progress progress(10, false, "draw");
    for (int frame = 1; frame <= 10; ++frame) {
      progress.update(frame, "");
    }
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace dinam
