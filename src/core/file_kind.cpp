#include "core/file_kind.hpp"

#include <sys/stat.h>

namespace dinam {

// What a name that exists is, in the words of a message; empty for a regular file or no file.
std::string file_kind_of(const std::filesystem::path& path, bool folder_wanted) {
  struct stat info {};
  if (lstat(path.c_str(), &info) != 0) {
    return {};  // missing (or unreadable: the write will say so)
  }
  if (S_ISLNK(info.st_mode)) {
    return "a symbolic link";
  }
  if (folder_wanted) {
    return S_ISDIR(info.st_mode) ? std::string() : std::string("not a folder");
  }
  return file_kind_of_mode(info.st_mode);
}

std::string file_kind_of_mode(unsigned mode) {
  if (S_ISREG(mode)) {
    return {};
  }
  if (S_ISDIR(mode)) {
    return "a folder";
  }
  if (S_ISFIFO(mode)) {
    return "a FIFO";
  }
  if (S_ISSOCK(mode)) {
    return "a socket";
  }
  if (S_ISLNK(mode)) {
    return "a symbolic link";
  }
  return "a device or special file";
}

}  // namespace dinam
