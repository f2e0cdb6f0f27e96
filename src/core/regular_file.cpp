#include "core/regular_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "core/error.hpp"
#include "core/file_kind.hpp"

namespace dinam {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& what,
                         const std::string& kind) {
  throw_user_error(FileLoc{path.string()},
                   "{} is {}: dinam reads it only as a regular file of its folder, never through a "
                   "link, which could lead to any file of the machine; put the file itself there",
                   what, kind);
}

}  // namespace

int open_regular_file(const std::filesystem::path& path, const std::string& what,
                      std::uintmax_t* size) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before fstat could
  // refuse it. It changes nothing for a regular file.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ELOOP) {
      refuse(path, what, "a symbolic link");
    }
    if (errno == ENXIO) {  // what open(2) says of a socket, or a device with nothing behind it
      refuse(path, what, "a socket or special file");
    }
    return -1;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    return -1;
  }
  if (const std::string kind = file_kind_of_mode(info.st_mode); !kind.empty()) {
    ::close(fd);
    refuse(path, what, kind);
  }
  if (size != nullptr) {
    *size = static_cast<std::uintmax_t>(info.st_size);
  }
  return fd;
}

RegularFileIn::RegularFileIn(const std::filesystem::path& path, const std::string& what)
    : std::istream(nullptr) {
  const int fd = open_regular_file(path, what, &size_);
  if (fd < 0) {
    open_error_ = errno;
    setstate(std::ios::failbit);
    return;
  }
  // The buffer owns the descriptor from here and closes it.
  buffer_ = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fd, std::ios::in | std::ios::binary);
  rdbuf(buffer_.get());
  clear();
}

}  // namespace dinam
