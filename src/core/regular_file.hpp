#pragma once
// Files read only as regular files of their own folder: a cache's files, golden images and
// tolerance files. Each is opened with O_NOFOLLOW, so a symbolic link in the file's place is
// refused by the open itself, and what was opened is checked with fstat, so a FIFO, a device or a
// folder is refused too. A check of the name before an ordinary open would leave a gap: a file
// swapped for a link between the two would be followed to any file of the machine.
#include <ext/stdio_filebuf.h>

#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <string>

namespace dinam {

// The file descriptor of `path` opened for reading, or -1 with errno set where the file is missing
// or unreadable (its reader says so in its own words). Throws UserError naming `path` where it is
// a symbolic link or anything but a regular file; `what` ("the cache's texture", "the golden
// image") says which file the message is about. `size`, where given, is set to the size of the
// file opened.
int open_regular_file(const std::filesystem::path& path, const std::string& what,
                      std::uintmax_t* size = nullptr);

// The same open as an input stream. `open_error()` is the errno of an open that failed (the stream
// is then in its failed state, as std::ifstream would be); `size()` is the size of the file
// opened, from the open file itself rather than its name.
class RegularFileIn : public std::istream {
 public:
  RegularFileIn(const std::filesystem::path& path, const std::string& what);

  int open_error() const { return open_error_; }
  std::uintmax_t size() const { return size_; }

 private:
  std::unique_ptr<__gnu_cxx::stdio_filebuf<char>> buffer_;
  int open_error_ = 0;
  std::uintmax_t size_ = 0;
};

}  // namespace dinam
