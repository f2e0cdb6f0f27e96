#pragma once
// Every file dinam writes is made the same way, so that an output folder shared with others (a
// farm's scratch space, a colleague's download) cannot turn a write against the user:
//  - the bytes go to a new temporary file beside the final name, created with O_CREAT | O_EXCL |
//    O_NOFOLLOW under a name no one can guess beforehand, so a symbolic link planted under a
//    temporary name is never followed (the open fails and another name is tried);
//  - the finished file is renamed into place; rename(2) replaces a name, it never writes through
//    it. A final name that already exists as a symbolic link, a folder or a special file (a FIFO,
//    a device) is refused with a UserError (exit 2) before anything is written, and again at the
//    rename, never followed;
//  - an unfinished file is removed, so nothing half-written is ever left under a final name.
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace dinam {

// Throws UserError when `path` exists as anything but a regular file (a symbolic link, even to a
// regular file; a folder; a FIFO, a socket or a device). A missing path is fine.
void check_output_name(const std::filesystem::path& path);

// Throws UserError when `folder` exists as a symbolic link or as anything but a folder.
void check_output_folder_name(const std::filesystem::path& folder);

// Where an output goes, for check_output_place: written inside `path` (a folder of frames), or
// made beside it and renamed to it (a file, or a cache folder replaced whole).
enum class OutputPlace { kInside, kBeside };

// Checks, before any work, that the output the user named (`-o`) can be written: the nearest
// folder that exists on its way must be a folder (not a file) in which dinam can create a file
// (tried with a file made and removed at once). Throws UserError (exit 2) naming `path` as the
// user gave it, after `what` ("-o", or "the output folder" for a default), with what is wrong and
// what to do.
void check_output_place(const std::filesystem::path& path, OutputPlace place, const char* what);

// Makes the folder that the file `path` is to go into, and those on its way, before any work
// (check_output_place has found them writable): a report or a page named in a folder that does not
// exist yet is written there, not lost at the end. Throws UserError naming `what` where it cannot.
void make_parent_folder(const std::filesystem::path& path, const char* what);

// A file being written: a new temporary beside the final name until commit() renames it there.
class OutputFile {
 public:
  // Checks the final name (check_output_name) and creates the temporary. Throws RuntimeError
  // naming `path` when the folder cannot be written.
  explicit OutputFile(std::filesystem::path path);

  // The open temporary file, for writing (stdio, buffered).
  std::FILE* stream() const { return stream_; }
  // The file descriptor under stream(); valid until commit() or destruction.
  int descriptor() const;
  const std::filesystem::path& temporary_path() const { return temporary_; }
  const std::filesystem::path& path() const { return path_; }

  // Flushes and closes the file, checks the final name again and renames the file into place.
  // Throws RuntimeError (a write error: the disk is full) or UserError (the final name became a
  // link meanwhile); either way the temporary is removed.
  void commit();

  // Not committed: closes and removes the temporary.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

 private:
  void discard();

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* stream_ = nullptr;
};

// Writes `bytes` to `path` through an OutputFile. `what` names the file in messages ("the
// manifest", "the rest mesh").
void write_output_file(const std::filesystem::path& path, std::string_view bytes,
                       const char* what = "the file");

// Opens a new file, to read and write, at a name made from `stem` plus a random suffix, with
// O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC (a name that exists, a link included, is never
// opened: another is tried). Returns the descriptor and sets `created` to the name. Throws
// WriteError.
int create_exclusive_file(const std::filesystem::path& stem, std::filesystem::path& created);

}  // namespace dinam
