#include "core/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/error.hpp"
#include "core/file_kind.hpp"

namespace dinam {
namespace {

std::string random_suffix() {
  std::array<unsigned char, 6> bytes{};
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = getrandom(bytes.data() + got, bytes.size() - got, 0);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      throw RuntimeError(fmt::format("cannot draw a random name: {}", std::strerror(errno)));
    }
    got += static_cast<std::size_t>(n);
  }
  std::string text;
  for (const unsigned char b : bytes) {
    text += fmt::format("{:02x}", b);
  }
  return text;
}

}  // namespace

void check_output_name(const std::filesystem::path& path) {
  const std::string kind = file_kind_of(path, false);
  if (!kind.empty()) {
    throw_user_error({},
                     "{} exists and is {}; dinam writes only new or regular files and never "
                     "through a link, so remove it or choose another output folder",
                     path.string(), kind);
  }
}

void check_output_folder_name(const std::filesystem::path& folder) {
  const std::string kind = file_kind_of(folder, true);
  if (!kind.empty()) {
    throw_user_error({},
                     "{} exists and is {}; dinam writes this folder only where it is a real "
                     "folder, never through a link, so remove it or choose another -o folder",
                     folder.string(), kind);
  }
}

void check_output_place(const std::filesystem::path& path, OutputPlace place, const char* what) {
  std::filesystem::path existing = place == OutputPlace::kInside ? path : path.parent_path();
  std::error_code ec;
  while (!existing.empty() && !std::filesystem::exists(existing, ec)) {
    existing = existing.parent_path();
  }
  if (existing.empty()) {
    existing = ".";
  }
  // The option to change: the one named, else -o (a default place is changed with -o).
  const std::string option = what[0] == '-' ? what : "-o";
  if (!std::filesystem::is_directory(existing, ec)) {
    throw_user_error({}, "{} {} cannot be written: {} is a file, not a folder; give {} {}", what,
                     path.string(), existing.string(), option,
                     place == OutputPlace::kInside ? "a folder" : "a path in a folder");
  }
  // Whether the folder is writable, on a writable file system, to this user (root included), as
  // the real outputs will be made: a file made there. An unnamed one (O_TMPFILE) leaves nothing
  // behind whatever stops the program; where the file system has none, a named one, made and
  // removed at once.
  int fd = open(existing.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  const bool unnamed = fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL);
  const std::filesystem::path probe =
      existing / fmt::format(".dinam-write-test.{}", random_suffix());
  if (!unnamed) {
    fd = open(probe.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  }
  if (fd < 0) {
    throw_user_error({},
                     "{} {} cannot be written: dinam cannot create files in {} ({}); give {} a "
                     "folder you can write to",
                     what, path.string(), existing.string(), std::strerror(errno), option);
  }
  close(fd);
  if (!unnamed) {
    unlink(probe.c_str());
  }
}

void make_parent_folder(const std::filesystem::path& path, const char* what) {
  const std::filesystem::path parent = path.parent_path();
  std::error_code ec;
  if (parent.empty() || std::filesystem::is_directory(parent, ec)) {
    return;
  }
  std::filesystem::create_directories(parent, ec);
  if (ec) {
    throw_user_error({}, "{} {} cannot be written: the folder {} cannot be made ({})", what,
                     path.string(), parent.string(), ec.message());
  }
}

int create_exclusive_file(const std::filesystem::path& stem, std::filesystem::path& created) {
  // 48 random bits: a clash with a planted name is all but impossible, and harmless (O_EXCL
  // fails and the next name is tried).
  constexpr int kTries = 16;
  for (int t = 0; t < kTries; ++t) {
    std::filesystem::path name = stem;
    name += fmt::format(".{}", random_suffix());
    const int fd = open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) {
      created = std::move(name);
      return fd;
    }
    if (errno != EEXIST && errno != ELOOP) {
      throw WriteError(fmt::format("cannot create {}: {}", name.string(), std::strerror(errno)));
    }
  }
  throw RuntimeError(
      fmt::format("cannot create a new file beside {}: every name tried exists", stem.string()));
}

OutputFile::OutputFile(std::filesystem::path path) : path_(std::move(path)) {
  check_output_name(path_);
  std::filesystem::path stem = path_;
  stem += ".tmp";
  const int fd = create_exclusive_file(stem, temporary_);
  stream_ = fdopen(fd, "wb");
  if (stream_ == nullptr) {
    const int error = errno;
    close(fd);
    discard();
    throw WriteError(fmt::format("cannot write {}: {}", path_.string(), std::strerror(error)));
  }
}

int OutputFile::descriptor() const {
  DINAM_CHECK(stream_ != nullptr);
  return fileno(stream_);
}

void OutputFile::commit() {
  DINAM_CHECK(stream_ != nullptr);
  errno = 0;
  bool ok = std::fflush(stream_) == 0 && std::ferror(stream_) == 0;
  int error = errno;
  if (std::fclose(stream_) != 0 && ok) {  // a late write error (NFS, a quota) shows at close
    ok = false;
    error = errno;
  }
  stream_ = nullptr;
  if (!ok) {
    discard();
    throw WriteError(fmt::format("cannot write {}: {}", path_.string(),
                                 error != 0 ? std::strerror(error) : "disk full or not writable"));
  }
  try {
    check_output_name(path_);  // made a link since the start? refuse it still
  } catch (...) {
    discard();
    throw;
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    error = errno;
    discard();
    throw RuntimeError(fmt::format("cannot rename {} to {}: {}", temporary_.string(),
                                   path_.string(), std::strerror(error)));
  }
  temporary_.clear();
}

OutputFile::~OutputFile() {
  discard();
}

void OutputFile::discard() {
  if (stream_ != nullptr) {
    std::fclose(stream_);
    stream_ = nullptr;
  }
  if (!temporary_.empty()) {
    unlink(temporary_.c_str());
    temporary_.clear();
  }
}

void write_output_file(const std::filesystem::path& path, std::string_view bytes,
                       const char* what) {
  OutputFile file(path);
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size()) {
    const int error = errno;
    throw WriteError(
        fmt::format("cannot write {} {}: {}", what, path.string(), std::strerror(error)));
  }
  file.commit();
}

}  // namespace dinam
