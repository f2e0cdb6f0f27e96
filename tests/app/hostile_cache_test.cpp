// A motion cache read as untrusted input (cache/manifest.cpp, app/view_command.cpp): a cache of
// no frame, a rest mesh whose indices are not the object's points, a manifest that names a file
// outside the cache, and names that would break the page `dinam view` writes. Each is refused with
// exit 2 naming the file (and line), writes nothing, or, for names, plays in a real browser.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "app/browser.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using Json = nlohmann::json;

// A wire of 4 bars in 2 frames, simulated into `folder`/cache (its scene `folder`/tiny.yaml),
// objects named as given.
struct TinyCache {
  explicit TinyCache(const std::string& scene_name = "tiny",
                     const std::string& object_name = "wire") {
    std::ofstream(scene) << "version: 1\nname: " << Json(scene_name).dump()
                         << "\nduration: 0.2\nfps: 10\nobjects:\n  - name: "
                         << Json(object_name).dump() << R"(
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.005}
    pinned: {indices: [0]}
)";
    const test::CommandResult made =
        test::run_dinam({"simulate", scene.string(), "-o", cache.string(), "--quiet"});
    EXPECT_EQ(made.exit_code, 0) << made.output;
  }
  Json manifest() const {
    std::ifstream in(cache / "manifest.json");
    return Json::parse(in);
  }
  void write_manifest(const Json& json) const {
    std::ofstream(cache / "manifest.json") << json.dump(1);
  }
  std::filesystem::path obj() const { return cache / manifest()["objects"][0]["files"]["obj"]; }
  test::CommandResult view() const {
    return test::run_dinam({"view", cache.string(), "-o", page.string()});
  }

  test::TemporaryFolder folder{"hostile-cache"};
  std::filesystem::path scene = folder.path() / "tiny.yaml";
  std::filesystem::path cache = folder.path() / "cache";
  std::filesystem::path page = folder.path() / "page.html";
};

TEST(HostileCache, ACacheOfNoFrameIsRefusedByViewAndRender) {
  const TinyCache tiny;
  Json manifest = tiny.manifest();
  manifest["frame_count"] = 0;
  manifest["frame_bounds"] = Json::array();
  tiny.write_manifest(manifest);
  const test::CommandResult viewed = tiny.view();
  EXPECT_EQ(viewed.exit_code, 2) << viewed.output;
  test::expect_contains(viewed.output, {"manifest.json", "holds 0 frames"});
  EXPECT_FALSE(std::filesystem::exists(tiny.page));
  const test::CommandResult rendered =
      test::run_dinam({"render", tiny.scene.string(), "--cache", tiny.cache.string(), "-o",
                       (tiny.folder.path() / "frames").string(), "--movie", "none", "--quiet"});
  EXPECT_EQ(rendered.exit_code, 2) << rendered.output;
  test::expect_contains(rendered.output, {"manifest.json", "holds 0 frames"});
}

TEST(HostileCache, ARestMeshIndexThatIsNoPointIsRefusedAtItsLine) {
  for (const char* bad : {"l 1 x 3", "l 1 99", "l 0 2", "f 1 2"}) {
    const TinyCache tiny;
    std::ifstream in(tiny.obj());
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    in.close();
    const std::size_t at = text.find("l 2 3");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, 5, bad);
    std::ofstream(tiny.obj()) << text;
    // The line's number: the comment, `o`, five `v`, then l 1 2 and this one.
    const test::CommandResult viewed = tiny.view();
    EXPECT_EQ(viewed.exit_code, 2) << bad << ": " << viewed.output;
    test::expect_contains(viewed.output,
                          {tiny.obj().filename().string() + ":9:1", "simulate again"});
    EXPECT_FALSE(std::filesystem::exists(tiny.page)) << bad;
  }
}

TEST(HostileCache, AManifestNamingAFileOutsideTheCacheIsRefused) {
  for (const char* key : {"obj", "pc2", "texture"}) {
    const TinyCache tiny;
    Json manifest = tiny.manifest();
    Json& names = std::string(key) == "texture" ? manifest["objects"][0]["look"]
                                                : manifest["objects"][0]["files"];
    names[key] = "../../../../../../etc/os-release";
    tiny.write_manifest(manifest);
    const test::CommandResult viewed = tiny.view();
    EXPECT_EQ(viewed.exit_code, 2) << viewed.output;
    test::expect_contains(viewed.output, {"manifest.json", "not a file of the cache's own folder"});
    EXPECT_FALSE(std::filesystem::exists(tiny.page));
  }
}

// A file of the cache replaced by a symbolic link to a file of the machine (the manifest, the rest
// mesh, the point cache, a texture the manifest names): `view` and `render --cache` refuse it,
// naming it, exit 2, and embed or read nothing of the target.
TEST(HostileCache, AFileOfTheCacheThatIsALinkIsRefused) {
  for (const char* key : {"manifest", "obj", "pc2", "texture"}) {
    SCOPED_TRACE(key);
    const TinyCache tiny;
    const std::filesystem::path secret = tiny.folder.path() / "secret.txt";
    std::ofstream(secret) << "the machine's secret\n";
    std::filesystem::path linked;
    if (std::string(key) == "manifest") {
      linked = tiny.cache / "manifest.json";
      std::filesystem::copy_file(linked, tiny.folder.path() / "manifest.json");
      std::filesystem::remove(linked);
      std::filesystem::create_symlink(tiny.folder.path() / "manifest.json", linked);
    } else if (std::string(key) == "texture") {
      // A textured cloth's cache instead, its texture (copied into the cache) made a link.
      std::ofstream(tiny.scene) << "version: 1\nduration: 0.2\nfps: 10\nobjects:\n"
                                << "  - name: cloth\n"
                                << "    mesh: {grid: {width: 1, height: 1, columns: 2, rows: 2}}\n"
                                << "    material: {preset: cotton}\n    pinned: {all: true}\n"
                                << "    texture: " << (test::data_dir() / "quad.png").string()
                                << "\n";
      std::filesystem::remove_all(tiny.cache);
      const test::CommandResult made = test::run_dinam(
          {"simulate", tiny.scene.string(), "-o", tiny.cache.string(), "--quiet"});
      ASSERT_EQ(made.exit_code, 0) << made.output;
      linked = tiny.cache / std::string(tiny.manifest()["objects"][0]["look"]["texture"]);
      std::filesystem::remove(linked);
      std::filesystem::create_symlink(secret, linked);
    } else {
      linked = tiny.cache / std::string(tiny.manifest()["objects"][0]["files"][key]);
      std::filesystem::remove(linked);
      std::filesystem::create_symlink(secret, linked);
    }
    const test::CommandResult viewed = tiny.view();
    EXPECT_EQ(viewed.exit_code, 2) << viewed.output;
    test::expect_contains(viewed.output, {linked.filename().string(), "is a symbolic link"});
    EXPECT_FALSE(std::filesystem::exists(tiny.page));
    if (std::string(key) != "texture" && std::string(key) != "obj") {
      const test::CommandResult rendered =
          test::run_dinam({"render", tiny.scene.string(), "--cache", tiny.cache.string(), "-o",
                           (tiny.folder.path() / "frames").string(), "--movie", "none", "--quiet"});
      EXPECT_EQ(rendered.exit_code, 2) << rendered.output;
      test::expect_contains(rendered.output, {"is a symbolic link"});
    }
  }
}

// Names that would end the page's script ("</script>") or hide its end in a comment ("<!--"),
// in the scene's and the object's name: the page holds no '<' in its data and plays.
TEST(HostileCache, ThePagePlaysWithAnyName) {
  const TinyCache tiny("<!--<script>", "</script><!--");
  const test::CommandResult viewed = tiny.view();
  ASSERT_EQ(viewed.exit_code, 0) << viewed.output;
  std::ifstream in(tiny.page);
  const std::string page{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(page.find("<!--<script>"), std::string::npos);
  EXPECT_EQ(page.find("</script><!--"), std::string::npos);
  if (!std::filesystem::exists(test::kChromium)) {
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
  }
  const test::CommandResult dom = test::run_command(
      test::chromium_command(tiny.folder.path() / "chromium",
                             fmt::format("--dump-dom 'file://{}#frame=2'", tiny.page.string())));
  EXPECT_EQ(dom.exit_code, 0) << dom.output;
  test::expect_contains(dom.output,
                        {"data-status=\"ready\"", "data-errors=\"0\"", "data-frame=\"2\""});
}

// Object names a file system cannot take as they are: 300 characters (over its 255 a name), and
// names that map to one file name ("a b" and "a_b"). Each object gets files of its own, at most
// 100 characters a stem, and keeps its name in the manifest.
TEST(HostileCache, LongAndClashingNamesGetFilesOfTheirOwn) {
  const test::TemporaryFolder folder("names");
  const std::string long_name(300, 'x');
  std::string scene = "version: 1\nduration: 0.2\nfps: 10\nobjects:\n";
  for (const std::string& name :
       {std::string("a b"), std::string("a_b"), long_name, long_name.substr(0, 299) + "y"}) {
    scene += "  - name: " + Json(name).dump() +
             "\n    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]]}}\n"
             "    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.005}\n"
             "    pinned: {indices: [0]}\n";
  }
  std::ofstream(folder.path() / "names.yaml") << scene;
  const auto cache = folder.path() / "cache";
  const test::CommandResult made = test::run_dinam(
      {"simulate", (folder.path() / "names.yaml").string(), "-o", cache.string(), "--quiet"});
  ASSERT_EQ(made.exit_code, 0) << made.output;
  std::ifstream in(cache / "manifest.json");
  const Json manifest = Json::parse(in);
  std::set<std::string> files;
  for (const Json& object : manifest["objects"]) {
    const std::string obj = object["files"]["obj"];
    EXPECT_LE(obj.size(), 104u) << obj;
    EXPECT_TRUE(files.insert(obj).second) << obj;
    EXPECT_TRUE(std::filesystem::is_regular_file(cache / obj)) << obj;
  }
  EXPECT_EQ(files.size(), 4u);
  EXPECT_EQ(manifest["objects"][2]["name"], long_name);
  const test::CommandResult viewed =
      test::run_dinam({"view", cache.string(), "-o", (folder.path() / "page.html").string()});
  EXPECT_EQ(viewed.exit_code, 0) << viewed.output;
}

}  // namespace
}  // namespace dinam
