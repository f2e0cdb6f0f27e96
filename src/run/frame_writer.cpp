#include "run/frame_writer.hpp"

#include <fmt/format.h>

#include "io/png_file.hpp"

namespace dinam {

FrameWriter::FrameWriter(std::filesystem::path folder, int digits, MovieEncoder* movie)
    : folder_(std::move(folder)), digits_(digits), movie_(movie), thread_([this] { run(); }) {}

FrameWriter::~FrameWriter() {
  {
    const std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FrameWriter::write(int frame, const Image& image) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return waiting_.size() < kMaxWaiting || error_; });
  rethrow_error();
  Image copy;
  if (!spare_.empty()) {
    copy = std::move(spare_.back());
    spare_.pop_back();
  }
  copy.width = image.width;
  copy.height = image.height;
  copy.rgba.assign(image.rgba.begin(), image.rgba.end());
  waiting_.emplace_back(frame, std::move(copy));
  lock.unlock();
  changed_.notify_all();
}

void FrameWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (waiting_.empty() && !writing_) || error_; });
  rethrow_error();
}

int FrameWriter::frames_written() {
  const std::lock_guard lock(mutex_);
  return written_;
}

void FrameWriter::rethrow_error() {
  if (error_) {
    std::rethrow_exception(error_);
  }
}

void FrameWriter::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return !waiting_.empty() || closing_; });
    if (waiting_.empty() || error_) {
      if (closing_) {
        return;
      }
      waiting_.clear();  // after an error the rest is dropped; write() reports the error
      continue;
    }
    auto [frame, image] = std::move(waiting_.front());
    waiting_.pop_front();
    writing_ = true;
    lock.unlock();
    std::exception_ptr error;
    try {
      write_png(folder_ / fmt::format("frame_{:0{}}.png", frame, digits_), image);
      if (movie_ != nullptr) {
        movie_->add_frame(image);
      }
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    writing_ = false;
    written_ += error ? 0 : 1;
    spare_.push_back(std::move(image));
    if (error && !error_) {
      error_ = error;
    }
    changed_.notify_all();
  }
}

}  // namespace dinam
