#pragma once
// A one-line progress report, redrawn in place, only when stderr is a terminal.
#include <chrono>
#include <string>

namespace dinam {

class Progress {
 public:
  // `stage` names what is counted ("simulate", "draw").
  Progress(int total, bool enabled, std::string stage);
  ~Progress();
  void update(int done, const std::string& detail);
  // Ends the line, so that what is printed next starts on its own; called by the destructor too.
  void finish();

 private:
  int total_;
  bool enabled_;
  std::string stage_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace dinam
