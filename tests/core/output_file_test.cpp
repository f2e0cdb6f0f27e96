#include "core/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "test_support.hpp"

namespace dinam {
namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(OutputFile, AFinishedFileIsRenamedIntoPlaceAndNothingElseIsLeft) {
  const test::TemporaryFolder folder("output-file");
  const std::filesystem::path path = folder.path() / "energy.csv";
  write_output_file(path, "a,b\n1,2\n");
  EXPECT_EQ(contents(path), "a,b\n1,2\n");
  EXPECT_EQ(test::folder_entries(folder.path()), std::vector<std::string>{"energy.csv"});
  // An older regular file of that name is replaced.
  write_output_file(path, "new\n");
  EXPECT_EQ(contents(path), "new\n");
  EXPECT_EQ(test::folder_entries(folder.path()), std::vector<std::string>{"energy.csv"});
}

TEST(OutputFile, AnUnfinishedFileLeavesNothing) {
  const test::TemporaryFolder folder("output-file");
  {
    OutputFile file(folder.path() / "frame.png");
    std::fputs("half a frame", file.stream());
  }  // an error elsewhere: never committed
  EXPECT_TRUE(test::folder_entries(folder.path()).empty());
}

// Links planted under every name a careless writer would use: the old fixed temporary names
// ("NAME.tmp", "NAME.part"), and the final name itself.
TEST(OutputFile, NeverWritesThroughALinkPlantedUnderATemporaryName) {
  const test::TemporaryFolder folder("output-file");
  const std::filesystem::path victim = folder.path() / "victim.txt";
  test::write_text(victim, "precious");
  const std::filesystem::path out = folder.path() / "out";
  std::filesystem::create_directory(out);
  for (const char* name : {"frame.png.tmp", "frame.png.part", "frame.png.tmp-1"}) {
    std::filesystem::create_symlink(victim, out / name);
  }
  write_output_file(out / "frame.png", "pixels");
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_EQ(contents(out / "frame.png"), "pixels");
  EXPECT_FALSE(std::filesystem::is_symlink(out / "frame.png"));
  for (const char* name : {"frame.png.tmp", "frame.png.part", "frame.png.tmp-1"}) {
    EXPECT_TRUE(std::filesystem::is_symlink(out / name)) << name << " was replaced";
  }
}

TEST(OutputFile, AFinalNameThatIsALinkOrASpecialFileIsRefusedNeverFollowed) {
  const test::TemporaryFolder folder("output-file");
  const std::filesystem::path victim = folder.path() / "victim.txt";
  test::write_text(victim, "precious");
  const std::filesystem::path link = folder.path() / "movie.mp4";
  std::filesystem::create_symlink(victim, link);
  test::expect_user_error([&] { write_output_file(link, "movie"); }, 0,
                          {"movie.mp4 exists and is a symbolic link", "remove it"});
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_TRUE(std::filesystem::is_symlink(link));

  // A FIFO would block a plain open for ever; a folder cannot take a file.
  const std::filesystem::path fifo = folder.path() / "energy.csv";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::expect_user_error([&] { write_output_file(fifo, "rows"); }, 0, {"is a FIFO"});
  std::filesystem::create_directory(folder.path() / "frame_0001.png");
  test::expect_user_error([&] { write_output_file(folder.path() / "frame_0001.png", "x"); }, 0,
                          {"is a folder"});
  EXPECT_EQ(test::folder_entries(folder.path()),
            (std::vector<std::string>{"energy.csv", "frame_0001.png", "movie.mp4", "victim.txt"}));
}

TEST(OutputFile, AFinalNameMadeALinkWhileWritingIsRefusedAtTheRename) {
  const test::TemporaryFolder folder("output-file");
  const std::filesystem::path victim = folder.path() / "victim.txt";
  test::write_text(victim, "precious");
  const std::filesystem::path path = folder.path() / "manifest.json";
  OutputFile file(path);
  std::fputs("{}", file.stream());
  std::filesystem::create_symlink(victim, path);  // another user, between the start and the end
  test::expect_user_error([&] { file.commit(); }, 0, {"is a symbolic link"});
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_EQ(test::folder_entries(folder.path()),
            (std::vector<std::string>{"manifest.json", "victim.txt"}));
}

TEST(OutputFile, AFolderThatIsALinkIsRefusedForACache) {
  const test::TemporaryFolder folder("output-file");
  std::filesystem::create_directory(folder.path() / "elsewhere");
  std::filesystem::create_directory_symlink(folder.path() / "elsewhere", folder.path() / "cache");
  test::expect_user_error([&] { check_output_folder_name(folder.path() / "cache"); }, 0,
                          {"cache exists and is a symbolic link"});
  check_output_folder_name(folder.path() / "elsewhere");  // a real folder is fine
  check_output_folder_name(folder.path() / "new");        // and so is none
}

}  // namespace
}  // namespace dinam
