#include "core/regular_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

std::string message_of_open(const std::filesystem::path& path) {
  try {
    RegularFileIn in(path, "the cache's manifest");
  } catch (const UserError& e) {
    return e.message();
  }
  return {};
}

TEST(RegularFile, AFileOfItsOwnIsReadWithItsSize) {
  const test::TemporaryFolder folder("regular-file");
  test::write_text(folder.path() / "manifest.json", "{\"frames\": 3}\n");
  RegularFileIn in(folder.path() / "manifest.json", "the cache's manifest");
  ASSERT_TRUE(in);
  EXPECT_EQ(in.size(), 14U);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "{\"frames\": 3}\n");
}

TEST(RegularFile, AMissingFileFailsAsAStreamWithItsErrno) {
  const test::TemporaryFolder folder("regular-file");
  RegularFileIn in(folder.path() / "missing.json", "the cache's manifest");
  EXPECT_FALSE(in);
  EXPECT_EQ(in.open_error(), ENOENT);
}

TEST(RegularFile, ALinkAFolderAndAFifoAreRefusedNamingWhatTheyAre) {
  const test::TemporaryFolder folder("regular-file");
  test::write_text(folder.path() / "secret", "the machine's own file");
  std::filesystem::create_symlink(folder.path() / "secret", folder.path() / "link.json");
  EXPECT_NE(message_of_open(folder.path() / "link.json").find("is a symbolic link"),
            std::string::npos);
  std::filesystem::create_directory(folder.path() / "folder.json");
  EXPECT_NE(message_of_open(folder.path() / "folder.json").find("is a folder"), std::string::npos);
  // A FIFO with no writer: an ordinary open would wait for one for ever.
  ASSERT_EQ(::mkfifo((folder.path() / "fifo.json").c_str(), 0600), 0);
  EXPECT_NE(message_of_open(folder.path() / "fifo.json").find("is a FIFO"), std::string::npos);
}

// The name is swapped between a file of the cache and a link to another file of the machine as
// fast as a second thread can, while the first opens it again and again: a check of the name
// followed by an ordinary open read the linked file's bytes in some of these 5000 opens (in each of
// five tries, 1 to 10 times); an open that refuses links itself never does.
TEST(RegularFile, ANameSwappedForALinkWhileItIsOpenedIsNeverFollowed) {
  const test::TemporaryFolder folder("regular-file");
  const std::filesystem::path secret = folder.path() / "secret";
  test::write_text(secret, "secret");
  const std::filesystem::path name = folder.path() / "texture.png";
  const std::filesystem::path real = folder.path() / "real";
  const std::filesystem::path link = folder.path() / "link";
  test::write_text(real, "pixels");
  std::filesystem::create_symlink(secret, link);
  std::filesystem::copy_file(real, name);

  std::atomic<bool> done{false};
  std::thread swapper([&] {
    const std::filesystem::path spare_real = folder.path() / "spare-real";
    const std::filesystem::path spare_link = folder.path() / "spare-link";
    for (int i = 0; !done.load(); ++i) {
      // rename(2) puts one or the other under the name at once: there is never a gap.
      if (i % 2 == 0) {
        std::filesystem::copy_file(real, spare_real,
                                   std::filesystem::copy_options::overwrite_existing);
        std::filesystem::rename(spare_real, name);
      } else {
        std::filesystem::remove(spare_link);
        std::filesystem::create_symlink(secret, spare_link);
        std::filesystem::rename(spare_link, name);
      }
    }
  });
  int read_real = 0;
  int refused = 0;
  int read_secret = 0;
  // 5 000 opens, and more until both sides of the swap have been met, however the two threads
  // happen to be scheduled.
  for (int i = 0; i < 5000 || ((read_real == 0 || refused == 0) && i < 1'000'000); ++i) {
    try {
      RegularFileIn in(name, "the cache's texture");
      std::string text;
      in >> text;
      read_real += text == "pixels" ? 1 : 0;
      read_secret += text == "secret" ? 1 : 0;
    } catch (const UserError&) {
      ++refused;
    }
  }
  done = true;
  swapper.join();
  EXPECT_EQ(read_secret, 0);
  // Both sides of the swap were met, so the race was run.
  EXPECT_GT(read_real, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace dinam
