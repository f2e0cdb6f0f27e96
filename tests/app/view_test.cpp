// `dinam view`: the page plays the cache in a real browser. Debian's chromium, headless and with
// every network service off, loads the page from a file, and
//  - the page says (on its body) that it drew the frame asked for and that nothing went wrong
//    (an uncaught error, a rejected promise, or a console error or warning counts);
//  - a screenshot at frame 60 matches tests/golden/view_end_to_end_flag_0060.png under the
//    snapshots' tolerance (WebGL on chromium's SwiftShader, whose rasterisation and anti-aliasing
//    may differ between chromium builds);
//  - the page names nothing outside itself (no http:, https: or src=), so it works offline.
// Skipped where chromium is not installed; scripts/install-deps.sh installs it. To redraw the
// golden on purpose: DINAM_UPDATE_GOLDENS=1 build/tests/test_app --gtest_filter='View.*'.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "app/browser.hpp"
#include "app/output_checks.hpp"
#include "core/image.hpp"
#include "io/image_compare.hpp"
#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::kChromium;

std::string chromium(const test::TemporaryFolder& folder, const std::string& arguments) {
  return test::chromium_command(folder.path() / "chromium", arguments);
}

struct Viewed {
  test::TemporaryFolder folder{"view"};
  std::filesystem::path page;
};

// The end-to-end flag simulated, and its page written with `view_arguments`.
void make_page(Viewed& viewed, const std::vector<std::string>& view_arguments) {
  const auto cache = viewed.folder.path() / "cache";
  const test::CommandResult simulated =
      test::run_dinam({"simulate", (test::data_dir() / "end_to_end_flag.yaml").string(), "-o",
                       cache.string(), "--format", "pc2", "--quiet"});
  ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
  std::vector<std::string> arguments{"view", cache.string()};
  arguments.insert(arguments.end(), view_arguments.begin(), view_arguments.end());
  const test::CommandResult viewed_result = test::run_dinam(arguments);
  ASSERT_EQ(viewed_result.exit_code, 0) << viewed_result.output;
  viewed.page = viewed.folder.path() / "cache.html";
  ASSERT_TRUE(std::filesystem::is_regular_file(viewed.page)) << viewed_result.output;
}

// The page at `fragment` once loaded, as chromium's --dump-dom prints its document.
std::string loaded_dom(const Viewed& viewed, const std::string& fragment) {
  const test::CommandResult dom = test::run_command(chromium(
      viewed.folder, fmt::format("--dump-dom 'file://{}{}'", viewed.page.string(), fragment)));
  EXPECT_EQ(dom.exit_code, 0) << dom.output;
  const std::size_t at = dom.output.find("<body");
  return at == std::string::npos ? dom.output : dom.output.substr(at);
}

TEST(View, ThePagePlaysTheCacheInABrowserAsItsGolden) {
  if (!std::filesystem::exists(kChromium)) {
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
  }
  Viewed viewed;
  make_page(viewed, {});
  std::ifstream in(viewed.page);
  const std::string page{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  for (const char* outside : {"http:", "https:", "src="}) {
    EXPECT_EQ(page.find(outside), std::string::npos) << outside;
  }

  const std::string dom = loaded_dom(viewed, "#frame=60");
  test::expect_contains(dom, {"data-status=\"ready\"", "data-errors=\"0\"", "data-frame=\"60\"",
                              "<span id=\"label\">frame 60 / 120 · 2.95 s</span>"});

  // The picture without the bar of controls, whose text is drawn in whatever fonts the machine
  // has.
  const auto shot = viewed.folder.path() / "frame60.png";
  const test::CommandResult taken = test::run_command(
      chromium(viewed.folder, fmt::format("--screenshot='{}' 'file://{}#frame=60&controls=no'",
                                          shot.string(), viewed.page.string())));
  ASSERT_TRUE(std::filesystem::exists(shot)) << taken.output;
  const auto golden = test::data_dir().parent_path() / "golden" / "view_end_to_end_flag_0060.png";
  if (std::getenv("DINAM_UPDATE_GOLDENS") != nullptr) {
    std::filesystem::copy_file(shot, golden, std::filesystem::copy_options::overwrite_existing);
  }
  const ImageTolerance tolerance;
  const ImageComparison comparison = compare_images(read_png(shot), read_png(golden), tolerance);
  EXPECT_TRUE(comparison.matches(tolerance))
      << comparison.differing_fraction * 100 << " % of pixels differ, mean error "
      << comparison.mean_error << "; the screenshot: " << shot;
  if (!comparison.matches(tolerance)) {
    std::filesystem::copy_file(shot, std::filesystem::temp_directory_path() / "view_actual.png",
                               std::filesystem::copy_options::overwrite_existing);
  }
}

// A textured surface (the shipped flag's tricolour, from the cache's copy of its texture) and its
// ropes: the page holds the picture and draws it, the frame asked for, with no error.
TEST(View, ATexturedFlagIsDrawnWithItsTexture) {
  if (!std::filesystem::exists(kChromium)) {
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
  }
  Viewed viewed;
  const auto source = test::data_dir().parent_path().parent_path();
  std::filesystem::create_directories(viewed.folder.path() / "scenes");
  std::filesystem::create_directory_symlink(source / "assets", viewed.folder.path() / "assets");
  std::ifstream in(source / "scenes" / "flag.yaml");
  std::string scene{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  scene.replace(scene.find("duration: 6.0"), 13, "duration: 0.5");
  const auto scene_path = viewed.folder.path() / "scenes" / "flag.yaml";
  std::ofstream(scene_path) << scene;
  const auto cache = viewed.folder.path() / "cache";
  const test::CommandResult simulated = test::run_dinam(
      {"simulate", scene_path.string(), "-o", cache.string(), "--format", "pc2", "--quiet"});
  ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
  EXPECT_TRUE(std::filesystem::exists(cache / "flag_texture.png"));
  const test::CommandResult result = test::run_dinam({"view", cache.string(), "--quiet"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  viewed.page = viewed.folder.path() / "cache.html";
  test::expect_contains(loaded_dom(viewed, "#frame=8"),
                        {"data-status=\"ready\"", "data-errors=\"0\"", "data-frame=\"8\""});
}

// --every keeps frames 1, 1 + N, …: the page holds fewer, and a frame asked for shows the nearest.
TEST(View, EveryNthFrameMakesASmallerPage) {
  if (!std::filesystem::exists(kChromium)) {
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
  }
  Viewed all;
  make_page(all, {});
  Viewed tenth;
  make_page(tenth, {"--every", "10"});
  // Most of the small page is three.js (about 230 kB deflated), the same in both.
  EXPECT_LT(std::filesystem::file_size(tenth.page) + 20'000, std::filesystem::file_size(all.page));
  test::expect_contains(loaded_dom(tenth, "#frame=60"),
                        {"data-status=\"ready\"", "data-errors=\"0\"", "data-frame=\"61\""});
}

// -o naming a page in folders that do not exist yet: they are made, and the page written there.
TEST(View, APageIntoAFolderThatDoesNotExistIsWrittenThere) {
  const test::TemporaryFolder folder("view");
  const std::filesystem::path scene = folder.path() / "rope.yaml";
  std::ofstream(scene) << test::rope_scene();
  const test::CommandResult simulated = test::run_dinam(
      {"simulate", scene.string(), "-o", (folder.path() / "cache").string(), "--quiet"});
  ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
  const std::filesystem::path page = folder.path() / "pages" / "today" / "rope.html";
  const test::CommandResult viewed =
      test::run_dinam({"view", (folder.path() / "cache").string(), "-o", page.string()});
  EXPECT_EQ(viewed.exit_code, 0) << viewed.output;
  EXPECT_GT(std::filesystem::file_size(page), 100'000U);
}

TEST(View, AFolderThatIsNotACacheIsRefusedAndNoPageWritten) {
  const test::TemporaryFolder folder("view");
  std::filesystem::create_directory(folder.path() / "notacache");
  const test::CommandResult result =
      test::run_dinam({"view", (folder.path() / "notacache").string()});
  EXPECT_EQ(result.exit_code, 2) << result.output;
  test::expect_contains(result.output, {"manifest.json"});
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "notacache.html"));
}

}  // namespace
}  // namespace dinam
