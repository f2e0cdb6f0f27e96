#include "core/file_kind.hpp"

#include <sys/stat.h>

#include "core/error.hpp"

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
  if (S_ISREG(info.st_mode)) {
    return {};
  }
  if (S_ISDIR(info.st_mode)) {
    return "a folder";
  }
  if (S_ISFIFO(info.st_mode)) {
    return "a FIFO";
  }
  if (S_ISSOCK(info.st_mode)) {
    return "a socket";
  }
  return "a device or special file";
}

void require_regular_file(const std::filesystem::path& path, const std::string& what) {
  const std::string kind = file_kind_of(path, false);
  if (kind.empty()) {
    return;
  }
  throw_user_error(FileLoc{path.string()},
                   "{} is {}: dinam reads it only as a regular file of its folder, never through a "
                   "link, which could lead to any file of the machine; put the file itself there",
                   what, kind);
}

}  // namespace dinam
