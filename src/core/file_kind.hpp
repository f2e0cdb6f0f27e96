#pragma once
// What a path names, in the words of a message, for the checks that keep dinam from writing
// through a link or into a device (outputs are written only as regular files: core/output_file.hpp)
// and from reading anything but a regular file (core/regular_file.hpp).
#include <filesystem>
#include <string>

namespace dinam {

// What a name that exists is, in the words of a message ("a symbolic link", "a FIFO", "a
// folder", "not a folder"); empty for a regular file (a folder, with `folder_wanted`) or no file.
// Never follows a link.
std::string file_kind_of(const std::filesystem::path& path, bool folder_wanted);

// The same words for a file's type bits (stat's st_mode, of a name or of a file already open);
// empty for a regular file.
std::string file_kind_of_mode(unsigned mode);

}  // namespace dinam
