// The bad-input corpus: hostile and careless input, each case asserting the exit code, the
// message (file:line:column where a line is to blame) and that nothing is left under a final name.
//  - tests/bad_input/scenes/*.yaml: one case a file, its expectations in its first comment lines
//    (`# expect-exit: N`, `# expect: TEXT` for each fragment the message must hold, `# command:`
//    when not `render {scene} -o {out}`; {name} is the file's name, {scene} its path and {out}
//    an empty folder of the test's). The meshes and textures they name are in bad_input/files/.
//  - Below them, the cases that need a file system condition set up: an output path that is a
//    file, a read-only or full file system (a small tmpfs, where the test may mount one), names
//    with spaces, quotes, unicode and a leading dash.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/output_checks.hpp"
#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::expect_message;
using test::files_under;
using test::joined;
using test::read_text;
using test::rope_scene;

const std::filesystem::path kCorpus = std::filesystem::path(DINAM_SOURCE_DIR) / "tests/bad_input";

std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// ---------------------------------------------------------------------------------------------
// The scene corpus.

struct SceneCase {
  std::filesystem::path scene;
  int exit_code = 2;
  std::vector<std::string> fragments;
  std::string command = "render {scene} -o {out}";
};

SceneCase read_case(const std::filesystem::path& scene) {
  SceneCase c;
  c.scene = scene;
  std::ifstream in(scene);
  std::string line;
  while (std::getline(in, line) && line.rfind("#", 0) == 0) {
    const auto value = [&](const std::string& key) { return line.substr(key.size()); };
    if (line.rfind("# expect-exit: ", 0) == 0) {
      c.exit_code = std::stoi(value("# expect-exit: "));
    } else if (line.rfind("# expect: ", 0) == 0) {
      c.fragments.push_back(value("# expect: "));
    } else if (line.rfind("# command: ", 0) == 0) {
      c.command = value("# command: ");
    }
  }
  return c;
}

std::vector<std::filesystem::path> corpus_scenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(kCorpus / "scenes")) {
    if (entry.path().extension() == ".yaml") {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

class BadScene : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(BadScene, ExitsWithItsCodeAndMessageAndWritesNothing) {
  const SceneCase c = read_case(GetParam());
  ASSERT_FALSE(c.fragments.empty()) << c.scene << " states no '# expect:' line";
  const test::TemporaryFolder folder("bad-scene");
  const std::filesystem::path out = folder.path() / "out";
  const auto filled = [&](const std::string& text) {
    return replaced_all(
        replaced_all(replaced_all(text, "{scene}", c.scene.string()), "{out}", out.string()),
        "{name}", c.scene.filename().string());
  };
  std::vector<std::string> arguments;
  std::istringstream words(c.command);
  for (std::string word; words >> word;) {
    arguments.push_back(filled(word));
  }
  std::vector<std::string> fragments;
  for (const std::string& fragment : c.fragments) {
    fragments.push_back(filled(fragment));
  }
  const std::vector<std::string> corpus_before = files_under(kCorpus);

  const test::CommandResult run = test::run_dinam(arguments);
  EXPECT_EQ(run.exit_code, c.exit_code) << run.output;
  expect_message(run, fragments);
  EXPECT_EQ(joined(files_under(out)), "") << "left behind in the output folder";
  EXPECT_EQ(joined(files_under(kCorpus)), joined(corpus_before)) << "written beside the scene";
}

std::string case_name(const ::testing::TestParamInfo<std::filesystem::path>& info) {
  std::string name = info.param.stem().string();
  std::replace_if(
      name.begin(), name.end(),
      [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) == 0; }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadScene, ::testing::ValuesIn(corpus_scenes()), case_name);

TEST(BadSceneCorpus, HoldsAtLeastFortyCases) {
  EXPECT_GE(corpus_scenes().size(), 40u);
}

// A thread count that is not one: DINAM_THREADS named with the fix, --threads out of range; exit 2.
TEST(BadThreads, AThreadCountThatIsNotOneIsRefusedWithTheFix) {
  const std::string scene = std::string(DINAM_SOURCE_DIR) + "/scenes/rope.yaml";
  const test::CommandResult variable = test::run_command(
      "DINAM_THREADS=two '" + std::string(DINAM_PROGRAM) + "' info '" + scene + "'");
  EXPECT_EQ(variable.exit_code, 2) << variable.output;
  EXPECT_NE(variable.output.find("DINAM_THREADS is 'two'"), std::string::npos) << variable.output;
  EXPECT_NE(variable.output.find("DINAM_THREADS=2"), std::string::npos) << variable.output;
  const test::CommandResult option =
      test::run_command("'" + std::string(DINAM_PROGRAM) + "' info '" + scene + "' --threads 0");
  EXPECT_EQ(option.exit_code, 2) << option.output;
  EXPECT_NE(option.output.find("--threads"), std::string::npos) << option.output;
  // And a good one is said, with its reason.
  const test::CommandResult good = test::run_command(
      "DINAM_THREADS=3 '" + std::string(DINAM_PROGRAM) + "' info '" + scene + "'");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_NE(good.output.find("threads          3 (DINAM_THREADS=3)"), std::string::npos)
      << good.output;
}

// ---------------------------------------------------------------------------------------------
// File system conditions.

// A cloth of 101 × 101 nodes: its cache (2.4 MB) does not fit a 256 kB file system.
std::string cloth_scene() {
  return "version: 1\n"
         "name: cloth\n"
         "duration: 0.1\n"
         "fps: 200\n"
         "gravity: [0, 0, -9.81]\n"
         "objects:\n"
         "  - name: cloth\n"
         "    mesh:\n"
         "      grid: {width: 1.0, height: 1.0, columns: 100, rows: 100}\n"
         "    material: {density: 1000, youngs_modulus: 1.0e4, radius: 0.001}\n"
         "    pinned: {indices: [0, 100]}\n";
}

// A tmpfs mounted for the test and unmounted at its end; `mounted()` is false where the test may
// not mount one (not root, or a container without the capability), and `why` says so.
class SmallFileSystem {
 public:
  SmallFileSystem(const std::filesystem::path& where, const std::string& options) : where_(where) {
    std::filesystem::create_directories(where_);
    if (mount("tmpfs", where_.c_str(), "tmpfs", options.find("ro") == 0 ? MS_RDONLY : 0,
              options.c_str()) == 0) {
      mounted_ = true;
    } else {
      why_ = std::string("cannot mount a tmpfs here (") + std::strerror(errno) + ")";
    }
  }
  ~SmallFileSystem() {
    if (mounted_) {
      umount2(where_.c_str(), MNT_DETACH);
    }
  }
  SmallFileSystem(const SmallFileSystem&) = delete;
  SmallFileSystem& operator=(const SmallFileSystem&) = delete;
  bool mounted() const { return mounted_; }
  const std::string& why() const { return why_; }

 private:
  std::filesystem::path where_;
  bool mounted_ = false;
  std::string why_;
};

class BadPlace : public ::testing::Test {
 protected:
  std::filesystem::path path(const std::string& name) const { return folder_.path() / name; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories(path(name).parent_path());
    std::ofstream(path(name)) << text;
    return path(name);
  }
  test::TemporaryFolder folder_{"bad-place"};
};

TEST_F(BadPlace, OutputPathThatIsAFileIsNamedAndLeftAlone) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  const std::filesystem::path file = write("taken", "a file of the user's\n");
  for (const std::filesystem::path& out : {file, file / "below"}) {
    const test::CommandResult run = test::run_dinam({"render", scene.string(), "-o", out.string()});
    EXPECT_EQ(run.exit_code, 2) << run.output;
    expect_message(run, {file.string() + " is a file", "give -o a folder"});
  }
  const test::CommandResult simulate =
      test::run_dinam({"simulate", scene.string(), "-o", file.string()});
  EXPECT_EQ(simulate.exit_code, 2) << simulate.output;
  expect_message(simulate, {file.string() + " is a file"});
  EXPECT_EQ(read_text(file), "a file of the user's\n");
  EXPECT_EQ(joined(files_under(folder_.path())), "rope.yaml, taken");
}

// A run larger than the memory it is given (an address-space limit of 700 MB, --force past the
// estimate's refusal) ends with what ran out and what was given to read, exit 2: never a raw
// std::bad_alloc. A sanitizer build reserves terabytes of address space for its shadow, so the
// limit cannot be set there.
TEST_F(BadPlace, AnAllocationThatFailsIsToldWithTheCommandAndExits2) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizer's shadow memory needs more address space than the limit";
#endif
  const std::filesystem::path scene = write("big.yaml", R"(version: 1
duration: 0.05
fps: 20
objects:
  - name: cloth
    mesh: {grid: {width: 10, height: 10, columns: 1500, rows: 1500}}
    material: {preset: cotton}
    pinned: {indices: [0]}
)");
  const test::CommandResult run = test::run_command(
      "ulimit -v 700000 && " + test::dinam_command("simulate " + test::shell_quoted(scene) +
                                                   " -o " + test::shell_quoted(path("cache")) +
                                                   " --force --quiet"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  expect_message(run, {"out of memory", "big.yaml", "dinam info SCENE"});
  EXPECT_EQ(run.output.find("bad_alloc"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(path("cache") / "manifest.json"));
}

TEST_F(BadPlace, SceneThatIsAFolderOrMissingIsNamed) {
  std::filesystem::create_directories(path("scenes"));
  const test::CommandResult folder = test::run_dinam({"render", path("scenes").string()});
  EXPECT_EQ(folder.exit_code, 2) << folder.output;
  expect_message(folder, {path("scenes").string() + ": error: this is a folder, not a scene file"});
  const test::CommandResult missing = test::run_dinam({"info", path("nowhere.yaml").string()});
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  expect_message(missing, {path("nowhere.yaml").string() + ": error: there is no such scene file"});
}

TEST_F(BadPlace, FolderThatIsNotACacheOrHoldsNoFramesIsNamed) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  write("stuff/notes.txt", "not a cache\n");
  const test::CommandResult cache = test::run_dinam(
      {"render", scene.string(), "--cache", path("stuff").string(), "-o", path("out").string()});
  EXPECT_EQ(cache.exit_code, 2) << cache.output;
  expect_message(cache, {"manifest.json", "not a complete motion cache", "dinam simulate"});
  EXPECT_FALSE(std::filesystem::exists(path("out")));
  const test::CommandResult movie = test::run_dinam({"movie", path("stuff").string()});
  EXPECT_EQ(movie.exit_code, 2) << movie.output;
  expect_message(movie, {"frames.json", "dinam render"});
  EXPECT_EQ(joined(files_under(path("stuff"))), "notes.txt");
}

TEST_F(BadPlace, NamesWithSpacesQuotesUnicodeAndALeadingDashWork) {
  // A folder and a scene named with everything a shell or a format string could trip on.
  const std::string awkward = "a b 'c' \"d\" ünïcødé {} %s $HOME";
  const std::filesystem::path scene = write(awkward + "/-rope scene.yaml", rope_scene());
  const std::filesystem::path out = path(awkward + "/out 'here'");
  const test::CommandResult render =
      test::run_dinam({"render", scene.string(), "-o", out.string(), "--movie", "gif", "-q"});
  EXPECT_EQ(render.exit_code, 0) << render.output;
  EXPECT_EQ(files_under(out).size(), 22u) << joined(files_under(out));  // 20 frames, json, gif
  EXPECT_NO_THROW(read_png(out / "frame_0020.png"));
  EXPECT_TRUE(std::filesystem::exists(out / "rope.gif"));

  const std::filesystem::path cache = path(awkward + "/cache ü");
  const test::CommandResult simulate =
      test::run_dinam({"simulate", scene.string(), "-o", cache.string(), "-q"});
  EXPECT_EQ(simulate.exit_code, 0) << simulate.output;
  const test::CommandResult cached =
      test::run_dinam({"render", scene.string(), "--cache", cache.string(), "-o", out.string(),
                       "-q", "--frames", "3-4", "--movie", "none"});
  EXPECT_EQ(cached.exit_code, 0) << cached.output;

  // An error names the file exactly as it is.
  const std::filesystem::path broken =
      write(awkward + "/-broken.yaml", test::replaced(rope_scene(), "fps: 20", "fps: zero"));
  const test::CommandResult error = test::run_dinam({"info", broken.string()});
  EXPECT_EQ(error.exit_code, 2) << error.output;
  expect_message(error, {broken.string() + ":4:6: error: 'fps' must be a number"});

  // Given bare, a name that starts with a dash reads as an option; dinam says how to name it.
  const std::string bare = "-rope scene.yaml";
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(scene.parent_path());
  const test::CommandResult dashed = test::run_dinam({"info", bare});
  std::filesystem::current_path(here);
  EXPECT_EQ(dashed.exit_code, 2) << dashed.output;
  expect_message(dashed, {"'-rope scene.yaml' is a file", "write it as ./-rope scene.yaml"});
}

TEST_F(BadPlace, ReadOnlyFolderIsRefusedBeforeAnythingRuns) {
  const std::filesystem::path scene = write("rope.yaml", rope_scene());
  const SmallFileSystem read_only(path("read-only"), "ro,size=64k");
  if (!read_only.mounted()) {
    GTEST_SKIP() << read_only.why();
  }
  const test::CommandResult run =
      test::run_dinam({"render", scene.string(), "-o", path("read-only/out").string()});
  EXPECT_EQ(run.exit_code, 2) << run.output;
  expect_message(run, {"-o " + path("read-only/out").string() + " cannot be written",
                       "(Read-only file system)", "give -o a folder you can write to"});
}

TEST_F(BadPlace, FullDiskKeepsWholeFramesOnlyAndSaysWhatIsLeft) {
  const std::filesystem::path rope = write("rope.yaml", rope_scene());
  const std::filesystem::path cloth = write("cloth.yaml", cloth_scene());
  const SmallFileSystem disk(path("disk"), "size=256k");
  if (!disk.mounted()) {
    GTEST_SKIP() << disk.why();
  }
  // Frames of 1280×720 (about 40 kB each here) fill 256 kB after a few.
  const std::filesystem::path out = path("disk/out");
  const test::CommandResult render =
      test::run_dinam({"render", rope.string(), "-o", out.string(), "--size", "1280x720", "-q"});
  EXPECT_EQ(render.exit_code, 1) << render.output;
  expect_message(render, {"No space left on device", "frames were written to " + out.string(),
                          "no movie was made", "Free some space"});
  std::vector<std::string> left = files_under(out);
  ASSERT_FALSE(left.empty());
  ASSERT_LT(left.size(), 20u);
  for (const std::string& name : left) {
    EXPECT_EQ(name.rfind("frame_", 0), 0u) << "not a frame: " << name;
    EXPECT_EQ(std::filesystem::path(name).extension(), ".png") << name;
    EXPECT_NO_THROW(read_png(out / name)) << name << " is not whole";
  }
  std::filesystem::remove_all(out);

  const test::CommandResult simulate =
      test::run_dinam({"simulate", cloth.string(), "-o", path("disk/cache").string(), "-q"});
  EXPECT_EQ(simulate.exit_code, 1) << simulate.output;
  expect_message(simulate, {"No space left on device", "no cache was written"});
  EXPECT_EQ(joined(files_under(path("disk"))), "") << "a partial cache was left";
  EXPECT_TRUE(std::filesystem::is_empty(path("disk")));
}

}  // namespace
}  // namespace dinam
