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
#include <map>
#include <numbers>

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

// A 24-sided cylinder 0.6 m across and 0.8 m tall with one n-gon for each cap, as Blender's
// default cylinder is made: its sides meet at 15°, its caps meet its sides at 90°.
void write_cylinder(const std::filesystem::path& path) {
  constexpr int kSides = 24;
  std::ofstream obj(path);
  for (const double z : {0.1, 0.9}) {
    for (int k = 0; k < kSides; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kSides;
      obj << fmt::format("v {} {} {}\n", 0.3 * std::cos(a), 0.3 * std::sin(a), z);
    }
  }
  for (int k = 0; k < kSides; ++k) {
    const int next = (k + 1) % kSides;
    obj << fmt::format("f {} {} {} {}\n", k + 1, next + 1, next + 1 + kSides, k + 1 + kSides);
  }
  std::string bottom = "f";
  std::string top = "f";
  for (int k = 0; k < kSides; ++k) {
    bottom += fmt::format(" {}", kSides - k);
    top += fmt::format(" {}", kSides + k + 1);
  }
  obj << bottom << "\n" << top << "\n";
}

// The share of two pictures' pixels that differ by more than 2 of 255 in a channel. Both are drawn
// by the same browser on the same machine, so pictures of the same shading are equal (0); a
// facet's shade against a smooth gradient differs by a few levels, more than any rounding.
double share_differing(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  std::size_t differing = 0;
  for (std::size_t p = 0; p + 3 < std::min(a.rgba.size(), b.rgba.size()); p += 4) {
    bool differs = false;
    for (std::size_t c = 0; c < 3; ++c) {
      differs = differs || std::abs(int{a.rgba[p + c]} - int{b.rgba[p + c]}) > 2;
    }
    differing += differs ? 1 : 0;
  }
  return 4.0 * static_cast<double>(differing) / static_cast<double>(a.rgba.size());
}

// The cylinder covers about a fifth of the 480 × 300 picture: a change of its sides' shading
// reaches most of that, one of its top's a tenth of it.
constexpr double kShadingDiffers = 0.01;

// The page shades a surface as the scene says: a cylinder's picture shaded flat differs from the
// smooth one across its faceted sides; with sharp edges (`auto`, at 30°) it differs from the
// smooth one at its caps, whose normals no longer blend with the sides', and from the flat one on
// its sides, which stay smooth. (A page that drew every surface smooth drew all three alike.)
TEST(View, ThePageShadesASurfaceAsTheSceneSays) {
  if (!std::filesystem::exists(kChromium)) {
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
  }
  const test::TemporaryFolder folder("view");
  write_cylinder(folder.path() / "drum.obj");
  std::map<std::string, Image> shots;
  for (const std::string shading : {"smooth", "flat", "auto"}) {
    const std::filesystem::path scene = folder.path() / (shading + ".yaml");
    std::ofstream(scene) << fmt::format(R"(version: 1
duration: 0.1
fps: 20
ground: {{contact: false}}
objects:
  - name: drum
    mesh: {{file: drum.obj}}
    role: collider
    color: [0.8, 0.3, 0.2]
    shading: {}
)",
                                        shading);
    const std::filesystem::path cache = folder.path() / shading;
    const test::CommandResult simulated =
        test::run_dinam({"simulate", scene.string(), "-o", cache.string(), "--quiet"});
    ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
    const test::CommandResult viewed = test::run_dinam({"view", cache.string(), "--quiet"});
    ASSERT_EQ(viewed.exit_code, 0) << viewed.output;
    const std::filesystem::path page = folder.path() / (shading + ".html");
    const std::filesystem::path shot = folder.path() / (shading + ".png");
    const test::CommandResult taken = test::run_command(test::chromium_command(
        folder.path() / "chromium", fmt::format("--screenshot='{}' 'file://{}#frame=1&controls=no'",
                                                shot.string(), page.string())));
    ASSERT_TRUE(std::filesystem::exists(shot)) << taken.output;
    shots[shading] = read_png(shot);
  }
  const auto differing = [&](const std::string& a, const std::string& b) {
    return share_differing(shots.at(a), shots.at(b));
  };
  // Measured: 14 %, 13 % and 4.6 %.
  EXPECT_GT(differing("flat", "smooth"), kShadingDiffers) << "flat against smooth";
  EXPECT_GT(differing("auto", "smooth"), kShadingDiffers) << "auto against smooth";
  EXPECT_GT(differing("auto", "flat"), kShadingDiffers) << "auto against flat";
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
