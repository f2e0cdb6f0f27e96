#pragma once
// Progress of a run's frames on stderr. On a terminal, one line redrawn in place; in a log (a farm
// job, CI, a file), a line each time another tenth of the frames is done, or after 30 s without
// one, with the time taken and an estimate of the time left, so that a long run says how it goes
// before it ends.
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
  void update_terminal(int done, const std::string& detail);
  void update_log(int done, const std::string& detail);

  int total_;
  bool enabled_;
  bool terminal_;
  std::string stage_;
  bool drawn_ = false;
  int tenths_logged_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace dinam
