#pragma once
// What a path names, for the checks that keep dinam from reading or writing through a link or
// into a device: a cache's files, goldens and tolerance files are read only as regular files, and
// outputs are written only as such (core/output_file.hpp).
#include <filesystem>
#include <string>

namespace dinam {

// What a name that exists is, in the words of a message ("a symbolic link", "a FIFO", "a
// folder", "not a folder"); empty for a regular file (a folder, with `folder_wanted`) or no file.
// Never follows a link.
std::string file_kind_of(const std::filesystem::path& path, bool folder_wanted);

// Throws UserError naming `path` where it is a symbolic link or anything but a regular file:
// `what` ("the cache's texture", "the golden image") is read only as a file of its own folder, not
// through a link that could lead to any file of the machine. A missing file passes (its reader
// says so).
void require_regular_file(const std::filesystem::path& path, const std::string& what);

}  // namespace dinam
