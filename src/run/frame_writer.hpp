#pragma once
// Writes the drawn frames on a thread of its own, so that the next frame is drawn meanwhile: the
// PNG file of each frame (encoded there), and the frame to the movie encoder when one runs.
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "io/movie_encoder.hpp"

namespace dinam {

class FrameWriter {
 public:
  // Frames go to folder/frame_NNNN.png with `digits` digits; `movie` may be null.
  FrameWriter(std::filesystem::path folder, int digits, MovieEncoder* movie);
  ~FrameWriter();  // waits for the frames already handed over
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Hands a copy of the frame to the writing thread; waits while kMaxWaiting frames are queued.
  // Rethrows the first error the writing thread met.
  void write(int frame, const Image& image);

  // Waits until every frame handed over is written; rethrows the writing thread's error.
  void finish();

  // Frames written so far, whole.
  int frames_written();

 private:
  // A few frames may wait: enough to smooth out uneven drawing and encoding times, few enough
  // that a 4K frame queue stays under 200 MB.
  static constexpr std::size_t kMaxWaiting = 4;

  void run();
  void rethrow_error();

  std::filesystem::path folder_;
  int digits_;
  MovieEncoder* movie_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<int, Image>> waiting_;
  std::vector<Image> spare_;  // written frames' buffers, reused so that a run allocates a few
  bool writing_ = false;      // the thread holds a frame it has taken off the queue
  bool closing_ = false;
  int written_ = 0;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace dinam
