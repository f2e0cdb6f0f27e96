#include "scene/isolated_import.hpp"

#include <assimp/scene.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "core/stop_request.hpp"
#include "scene/assimp_mesh.hpp"
#include "scene/mesh_wire.hpp"

namespace dinam {
namespace {

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// The processor time the importer may spend on a file: 2 s (or $DINAM_MESH_IMPORT_TIMEOUT) plus 2 s
// per megabyte. assimp reads a sound file at tens of megabytes a second, so this is far more than
// any needs, yet a small file that makes it loop is refused in a couple of seconds. It counts the
// child's own processor time, which another program on the machine does not lengthen; a child
// that waits without computing (a mesh path naming a pipe) meets the clock's limit instead.
// Whole seconds, as the system counts them for the limit.
long import_cpu_seconds(std::uintmax_t file_bytes) {
  const char* text = std::getenv("DINAM_MESH_IMPORT_TIMEOUT");
  const double set = text != nullptr ? std::strtod(text, nullptr) : 0.0;
  const double seconds = (set > 0.0 ? set : 2.0) + 2.0 * static_cast<double>(file_bytes) / 1e6;
  return std::max(1L, std::lround(std::min(seconds, 1e9)));
}

// The wall-clock time the parent waits for the child, whatever it does: a minute more than its
// processor time, for a machine busy with other work.
double import_wall_seconds(std::uintmax_t file_bytes) {
  return 60.0 + 2.0 * static_cast<double>(import_cpu_seconds(file_bytes));
}

// Stops the child at its processor time: SIGXCPU at the soft limit, SIGKILL a second later.
void limit_processor_time(std::uintmax_t file_bytes) {
  const auto seconds = static_cast<rlim_t>(import_cpu_seconds(file_bytes));
  const rlimit limit{seconds, seconds + 1};
  setrlimit(RLIMIT_CPU, &limit);
}

// A malformed header can make assimp reserve memory for 10⁹ vertices and then touch it page by
// page (invalid/OutOfMemory.off of assimp's test files took a minute of system time): the child
// may grow by 2 GiB plus 64 bytes per byte of the file (assimp's own structures for a sound file
// take a few times its size), and never beyond the machine's memory, so such an allocation fails
// at once and assimp reports it. Left out under the sanitizers, whose shadow memory needs
// terabytes of address space.
void limit_address_space(std::uintmax_t file_bytes) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  (void)file_bytes;
#elif defined(__has_feature) && \
    (__has_feature(address_sanitizer) || __has_feature(memory_sanitizer))
  (void)file_bytes;
#else
  const long page = sysconf(_SC_PAGESIZE);
  const long physical_pages = sysconf(_SC_PHYS_PAGES);
  unsigned long mapped_pages = 0;
  if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%lu", &mapped_pages) != 1) {
      mapped_pages = 0;
    }
    std::fclose(statm);
  }
  if (page <= 0 || physical_pages <= 0) {
    return;
  }
  const double growth = std::min(2.0 * 1024 * 1024 * 1024 + 64.0 * static_cast<double>(file_bytes),
                                 static_cast<double>(page) * static_cast<double>(physical_pages));
  const auto bytes =
      static_cast<rlim_t>(static_cast<double>(page) * static_cast<double>(mapped_pages) + growth);
  const rlimit limit{bytes, bytes};
  setrlimit(RLIMIT_AS, &limit);  // best effort: without it the time limit still holds
#endif
}

}  // namespace

RawMesh import_in_child(const std::filesystem::path& path, const FileLoc& where) {
  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw RuntimeError(
        fmt::format("cannot make a pipe to import {}: {}", path.string(), std::strerror(errno)));
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(ends[0]);
    close(ends[1]);
    throw RuntimeError(
        fmt::format("cannot fork to import {}: {}", path.string(), std::strerror(errno)));
  }
  if (pid == 0) {
    // The child is a copy of dinam, so nothing may return from here into dinam's own code (an
    // exception thrown by the import would have run the rest of the command a second time,
    // beside the parent): every path ends in _exit. It also ends with the parent, whatever
    // stops that (a signal's default action leaves no one to read the reply).
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) {
      _exit(1);
    }
    close(ends[0]);
    bool sent = false;
    try {
      std::error_code size_error;
      const std::uintmax_t bytes = std::filesystem::file_size(path, size_error);
      limit_address_space(size_error ? 0 : bytes);
      limit_processor_time(size_error ? 0 : bytes);
      Assimp::Importer importer;
      // No post-processing at all: triangulating would add diagonals that are not edges of the
      // model, and model/ welds coincident vertices itself. Node transforms are applied here.
      const aiScene* scene = importer.ReadFile(path.string(), 0);
      sent =
          scene == nullptr
              ? write_all(ends[1], 'E' + std::string(importer.GetErrorString()))
              : write_all(ends[1], 'M' + encode_mesh(mesh_from_scene(*scene, path.parent_path())));
    } catch (const std::exception& e) {
      sent = write_all(ends[1], 'E' + std::string(e.what()));
    } catch (...) {
      sent = write_all(ends[1], std::string("Eunknown failure"));
    }
    _exit(sent ? 0 : 1);
  }
  close(ends[1]);
  // A malformed file can also make assimp loop for ever (fuzzing found PLY files that do); the
  // child gets a time that no sound file of this size needs, then it is stopped.
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  const auto cpu_limit = static_cast<double>(import_cpu_seconds(ec ? 0 : file_bytes));
  const double limit = import_wall_seconds(ec ? 0 : file_bytes);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit);
  std::string reply;
  std::array<char, 65536> buffer{};
  bool timed_out = false;
  int stopped_by = 0;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    // Woken every 100 ms to see whether a signal asked to stop (core/stop_request.hpp).
    pollfd readable{ends[0], POLLIN, 0};
    const int ready =
        left.count() > 0
            ? poll(&readable, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 100)))
            : 0;
    if (stop_signal() != 0) {
      stopped_by = stop_signal();
      kill(pid, SIGKILL);
      break;
    }
    if (ready < 0 && errno == EINTR) {
      continue;
    }
    if (ready == 0 && left.count() > 100) {
      continue;
    }
    if (ready == 0) {
      timed_out = true;
      kill(pid, SIGKILL);
      break;
    }
    const ssize_t n = read(ends[0], buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      break;
    }
    reply.append(buffer.data(), static_cast<std::size_t>(n));
  }
  close(ends[0]);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (stopped_by != 0) {
    throw Interrupted(stopped_by, "the scene was still being read, so nothing was written");
  }
  const double cpu_used =
      static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  // SIGXCPU at the soft limit, or SIGKILL at the hard one (a SIGKILL before it is another cause:
  // the system out of memory).
  const bool out_of_time =
      WIFSIGNALED(status) &&
      (WTERMSIG(status) == SIGXCPU || (WTERMSIG(status) == SIGKILL && cpu_used >= cpu_limit));
  if (timed_out || out_of_time) {
    throw_user_error(where,
                     "the mesh importer (assimp) did not finish reading '{}' in {:.0f} s of "
                     "processor time, which a sound file of its size never needs (a malformed "
                     "file can make it loop); only this file is refused: mend it or convert it "
                     "to OBJ",
                     path.string(), timed_out ? limit : cpu_limit);
  }
  if (WIFSIGNALED(status)) {
    throw_user_error(where,
                     "the mesh importer (assimp) crashed reading '{}' ({}); dinam imports meshes "
                     "apart, so only this file is refused: convert it to OBJ or PLY, or mend it",
                     path.string(), strsignal(WTERMSIG(status)));
  }
  if (!reply.empty() && reply.front() == 'E') {
    const std::string error = reply.substr(1);
    throw_user_error(where, "cannot read mesh file '{}': {}{}", path.string(), error,
                     error.find("bad_alloc") != std::string::npos
                         ? " (the file asks for far more memory than its size needs: its counts "
                           "of vertices or faces are wrong; mend it or convert it to OBJ)"
                         : "");
  }
  std::optional<RawMesh> mesh;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !reply.empty() && reply.front() == 'M') {
    mesh = decode_mesh(std::string_view(reply).substr(1));
  }
  if (!mesh) {
    throw RuntimeError(fmt::format("importing {} in a child process failed", path.string()));
  }
  return std::move(*mesh);
}

}  // namespace dinam
