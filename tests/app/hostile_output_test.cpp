// Outputs that cannot be turned against the user. A scene file is input from anyone and output
// folders are often shared, so each case here is one a hostile scene or neighbour could set up:
// symbolic links planted where dinam writes, output names that ffmpeg would read as a protocol or
// an option, an ffmpeg that never reads, a cache holding a NaN. Each asserts the exit code, the
// message, and that nothing outside the output folder changed.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "app/output_checks.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::expect_message;
using test::files_under;
using test::joined;
using test::read_text;
using test::rope_scene;

class HostileOutput : public ::testing::Test {
 protected:
  std::filesystem::path path(const std::string& name) const { return folder_.path() / name; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories(path(name).parent_path());
    std::ofstream(path(name)) << text;
    return path(name);
  }
  // A file outside the output folder that a planted link points at.
  std::filesystem::path victim() const { return path("victim.txt"); }
  void SetUp() override { write("victim.txt", "the user's own file\n"); }
  void expect_victim_untouched() const { EXPECT_EQ(read_text(victim()), "the user's own file\n"); }
  // Runs dinam in the test's folder, so relative output names land there.
  test::CommandResult run_here(const std::string& arguments,
                               const std::string& environment = "") const {
    return test::run_command("cd '" + folder_.path().string() + "' && " + environment + " '" +
                             DINAM_PROGRAM + "' " + arguments);
  }
  test::TemporaryFolder folder_{"hostile-output"};
};

TEST_F(HostileOutput, LinksPlantedUnderTemporaryNamesAreNeverFollowed) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  const std::filesystem::path out = path("out");
  std::filesystem::create_directories(out);
  const std::vector<std::string> planted = {"frame_0001.png.tmp", "rope.mp4.part",
                                            "rope.mp4.ffmpeg-log", "energy.csv.tmp",
                                            "frames.json.tmp"};
  for (const std::string& name : planted) {
    std::filesystem::create_symlink(victim(), out / name);
  }
  const test::CommandResult run =
      test::run_dinam({"render", scene.string(), "-o", out.string(), "--energy", "-q"});
  EXPECT_EQ(run.exit_code, 0) << run.output;
  expect_victim_untouched();
  for (const std::string& name : planted) {
    EXPECT_TRUE(std::filesystem::is_symlink(out / name)) << name << " was replaced";
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::symlink_status(out / "rope.mp4")));
  EXPECT_TRUE(
      std::filesystem::is_regular_file(std::filesystem::symlink_status(out / "energy.csv")));
}

TEST_F(HostileOutput, AFinalNameThatIsALinkIsRefusedBeforeTheRun) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  for (const std::string name : {"rope.mp4", "energy.csv", "frame_0001.png"}) {
    const std::filesystem::path out = path("out-" + name);
    std::filesystem::create_directories(out);
    std::filesystem::create_symlink(victim(), out / name);
    const test::CommandResult run =
        test::run_dinam({"render", scene.string(), "-o", out.string(), "--energy", "-q"});
    EXPECT_EQ(run.exit_code, 2) << name << ":\n" << run.output;
    expect_message(run, {(out / name).string() + " exists and is a symbolic link", "remove it"});
    expect_victim_untouched();
  }
  // The movie's name is checked before a frame is drawn.
  EXPECT_EQ(joined(files_under(path("out-rope.mp4"))), "rope.mp4");
  // A cache folder that is a link to another folder is neither written into nor replaced.
  std::filesystem::create_directories(path("elsewhere"));
  std::filesystem::create_directory_symlink(path("elsewhere"), path("cache"));
  const test::CommandResult simulate =
      test::run_dinam({"simulate", scene.string(), "-o", path("cache").string(), "-q"});
  EXPECT_EQ(simulate.exit_code, 2) << simulate.output;
  expect_message(simulate, {"cache exists and is a symbolic link"});
  EXPECT_TRUE(std::filesystem::is_empty(path("elsewhere")));
}

// A listening socket of the test's own: if ffmpeg were given "tcp://127.0.0.1:PORT/…" as a
// protocol, it would connect here.
class ListeningSocket {
 public:
  ListeningSocket() {
    fd_ = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof(address);
    if (fd_ < 0 || bind(fd_, reinterpret_cast<sockaddr*>(&address), size) != 0 ||
        listen(fd_, 4) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
      return;
    }
    port_ = ntohs(address.sin_port);
  }
  ~ListeningSocket() {
    if (fd_ >= 0) {
      close(fd_);
    }
  }
  ListeningSocket(const ListeningSocket&) = delete;
  ListeningSocket& operator=(const ListeningSocket&) = delete;
  int port() const { return port_; }
  // Whether anyone has connected since the socket was opened (the backlog keeps them).
  bool connected() const {
    const int client = accept(fd_, nullptr, nullptr);
    if (client >= 0) {
      close(client);
      return true;
    }
    return false;
  }

 private:
  int fd_ = -1;
  int port_ = 0;
};

TEST_F(HostileOutput, ProtocolNamesGiveLocalFoldersAndNoConnection) {
  const ListeningSocket listener;
  ASSERT_GT(listener.port(), 0) << "cannot listen on the loopback interface";
  const std::string url = "tcp://127.0.0.1:" + std::to_string(listener.port());
  write("rope.yaml", rope_scene());
  // On the command line, and in the scene's `output`.
  const test::CommandResult option = run_here("render rope.yaml -o '" + url + "' --movie gif -q");
  EXPECT_EQ(option.exit_code, 0) << option.output;
  write("net.yaml", test::replaced(rope_scene(), "name: rope\n",
                                   "name: rope\noutput: \"" + url + "/scene\"\n"));
  const test::CommandResult scene = run_here("render net.yaml -q");
  EXPECT_EQ(scene.exit_code, 0) << scene.output;
  EXPECT_FALSE(listener.connected()) << "dinam or ffmpeg connected to " << url;
  // The names were folders here (the file system folds "//" into "/").
  const std::string local = "tcp:/127.0.0.1:" + std::to_string(listener.port());
  EXPECT_TRUE(std::filesystem::is_regular_file(path(local) / "rope.gif"));
  EXPECT_TRUE(std::filesystem::is_regular_file(path(local) / "scene/rope.mp4"));
  expect_victim_untouched();
}

TEST_F(HostileOutput, NamesThatLookLikeOptionsAreFolders) {
  write("rope.yaml", rope_scene());
  write("dash.yaml", test::replaced(rope_scene(), "name: rope\n", "name: rope\noutput: \"-y\"\n"));
  const test::CommandResult scene = run_here("render dash.yaml -q");
  EXPECT_EQ(scene.exit_code, 0) << scene.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(path("-y/rope.mp4")));
  const test::CommandResult option = run_here("render rope.yaml -o '-out dir' -q");
  EXPECT_EQ(option.exit_code, 0) << option.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(path("-out dir/rope.mp4")));
}

TEST_F(HostileOutput, AnOutputThatCannotBeWrittenIsAUsageErrorNamingTheUsersPath) {
  write("rope.yaml", rope_scene());
  ASSERT_EQ(run_here("simulate rope.yaml -o cache -q").exit_code, 0);
  write("a_file", "in the way\n");
  // Each command with -o, before any work: a path under a file, and one in a folder where no
  // file can be made (/proc refuses new files to root too). Each was exit 1 and named a
  // temporary name of dinam's own ("cache.part-…", "page.tmp.…"), or was found only after the
  // simulation.
  for (const std::string command : {"simulate rope.yaml", "render rope.yaml", "modes rope.yaml",
                                    "view cache", "snapshot rope.yaml --golden goldens"}) {
    for (const std::string place : {"a_file/out", "/proc/dinam_out"}) {
      const test::CommandResult run = run_here(command + " -o " + place);
      EXPECT_EQ(run.exit_code, 2) << command << " -o " << place << "\n" << run.output;
      expect_message(run, {"-o " + place + " cannot be written",
                           place == "a_file/out" ? "a_file is a file" : "in /proc"});
      EXPECT_EQ(run.output.find(".part"), std::string::npos) << run.output;
      EXPECT_EQ(run.output.find(".tmp"), std::string::npos) << run.output;
    }
  }
  EXPECT_EQ(read_text(path("a_file")), "in the way\n");
}

TEST_F(HostileOutput, AnFfmpegThatNeverReadsIsStoppedAndTheFramesAreKept) {
  write("rope.yaml", rope_scene());
  const std::filesystem::path stand_in = write("tools/ffmpeg", "#!/bin/sh\nexec sleep 600\n");
  std::filesystem::permissions(stand_in, std::filesystem::perms::owner_all);
  const test::CommandResult run =
      run_here("render rope.yaml -o out -q",
               "DINAM_FFMPEG='" + stand_in.string() + "' DINAM_FFMPEG_TIMEOUT=1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  expect_message(run, {"took no frame data and used no CPU", "DINAM_FFMPEG_TIMEOUT",
                       "frames were written to out and are kept", "no movie was made"});
  // Whole frames only, no movie, nothing partial: 64 × 36 RGBA frames fill a pipe in seven.
  const std::vector<std::string> left = files_under(path("out"));
  EXPECT_FALSE(left.empty());
  for (const std::string& name : left) {
    EXPECT_EQ(name.rfind("frame_", 0), 0u) << name;
    EXPECT_EQ(std::filesystem::path(name).extension(), ".png") << name;
  }
}

TEST_F(HostileOutput, ACacheHoldingANaNIsRefusedWithItsFileAndFrame) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  const test::CommandResult simulate =
      test::run_dinam({"simulate", scene.string(), "-o", path("cache").string(), "-q"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.output;
  // Frame 7's third point's z: header 32 bytes, 5 points of 12 bytes a sample.
  {
    std::fstream pc2(path("cache/rope.pc2"), std::ios::in | std::ios::out | std::ios::binary);
    pc2.seekp(32 + 6 * 5 * 12 + 2 * 12 + 8);
    const float nan = std::nanf("");
    pc2.write(reinterpret_cast<const char*>(&nan), sizeof(nan));
  }
  const test::CommandResult render = test::run_dinam(
      {"render", scene.string(), "--cache", path("cache").string(), "-o", path("out").string()});
  EXPECT_EQ(render.exit_code, 2) << render.output;
  expect_message(render, {"rope.pc2", "point 2 of sample 6 (frame 7) is not a finite position"});
  EXPECT_TRUE(files_under(path("out")).empty());
}

}  // namespace
}  // namespace dinam
