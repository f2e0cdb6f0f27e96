// `dinam snapshot` as a CI uses it: what must pass (another thread count, a camera moved by a
// fraction of a pixel) and what must fail (a colour, a moved object), the tolerance file's regions
// in the scene's metres, and the reports a CI system and a person read.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "test_support.hpp"

namespace dinam {
namespace {

using test::CommandResult;
using test::dinam_command;
using test::run_command;

// A cotton banner pinned along a pole, drawn from 3.2 m: at 320 × 180 and 40° a pixel is 1.3 cm
// across at the banner.
struct Banner {
  double camera_x = 0.5;  // m: the camera and the point it looks at move together
  double distance = 3.2;  // m, of the camera in front of the banner
  double pole_x = 0.0;    // m
  const char* cloth_color = "[0.80, 0.25, 0.15]";
  const char* pole_color = "[0.55, 0.55, 0.58]";
  double pole_radius = 0.02;  // m

  std::string yaml() const {
    return fmt::format(R"(version: 1
name: banner
duration: 0.5
fps: 10
camera: {{position: [{0}, {4}, 1.3], look_at: [{0}, 0, 1.2], fov: 40}}
objects:
  - name: pole
    mesh: {{polyline: {{points: [[{1}, 0, 0], [{1}, 0, 1.7]], segments: 4}}}}
    material: {{density: 7850, youngs_modulus: 2.0e11, radius: {5}}}
    pinned: {{all: true}}
    color: {3}
  - name: cloth
    mesh:
      grid: {{width: 1, height: 0.6, columns: 10, rows: 6}}
      rotation: [90, 0, 0]
      translation: [0.03, 0, 1.0]
    material: {{preset: cotton}}
    pinned: {{box: {{min: [0, -0.1, 0.9], max: [0.05, 0.1, 1.7]}}}}
    color: {2}
)",
                       camera_x, pole_x, cloth_color, pole_color, -distance, pole_radius);
  }
};

class Snapshot : public ::testing::Test {
 protected:
  std::filesystem::path scene(const Banner& banner) {
    const std::filesystem::path path = folder_.path() / "banner.yaml";
    std::ofstream(path) << banner.yaml();
    return path;
  }
  std::filesystem::path golden() const { return folder_.path() / "golden"; }
  // Runs `dinam snapshot` on the banner against the goldens, with `extra` arguments.
  CommandResult snapshot(const Banner& banner, const std::string& extra = "") {
    return run_command(dinam_command(fmt::format(
        "snapshot {} --golden {} --frames 1,5 -o {} {}", test::shell_quoted(scene(banner)),
        test::shell_quoted(golden()), test::shell_quoted(folder_.path() / "out"), extra)));
  }
  void write_tolerances(const std::string& text) {
    std::ofstream(golden() / "tolerances.yaml") << text;
  }
  std::string read(const std::filesystem::path& path) const {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  void SetUp() override {
    const CommandResult made = snapshot(Banner{}, "--update --threads 2");
    ASSERT_EQ(made.exit_code, 0) << made.output;
  }
  test::TemporaryFolder folder_{"snapshot"};
};

TEST_F(Snapshot, UpdateWritesTheGoldensAndTheirToleranceFile) {
  for (const char* name : {"banner_0001.png", "banner_0005.png", "tolerances.yaml"}) {
    EXPECT_TRUE(std::filesystem::exists(golden() / name)) << name;
  }
  const std::string tolerances = read(golden() / "tolerances.yaml");
  EXPECT_NE(tolerances.find("min_ssim: 0.99"), std::string::npos) << tolerances;
  EXPECT_NE(tolerances.find("  banner: {}"), std::string::npos) << tolerances;
}

TEST_F(Snapshot, AnotherThreadCountAndACameraMovedByUnderAPixelPass) {
  const CommandResult one_thread = snapshot(Banner{}, "--threads 1");
  EXPECT_EQ(one_thread.exit_code, 0) << one_thread.output;
  EXPECT_NE(one_thread.output.find("SSIM 1.0000"), std::string::npos) << one_thread.output;
  // A third of a pixel to the side: every edge moves, nothing changed.
  Banner jittered;
  jittered.camera_x += 0.0043;
  const CommandResult moved = snapshot(jittered);
  EXPECT_EQ(moved.exit_code, 0) << moved.output;
  EXPECT_EQ(moved.output.find("SSIM 1.0000"), std::string::npos) << moved.output;  // it did move
}

TEST_F(Snapshot, AChangedColourAndAMovedPoleFail) {
  Banner recoloured;
  recoloured.cloth_color = "[0.15, 0.35, 0.80]";
  const CommandResult colour = snapshot(recoloured);
  EXPECT_EQ(colour.exit_code, 1) << colour.output;
  EXPECT_NE(colour.output.find("DIFFERS"), std::string::npos) << colour.output;
  EXPECT_TRUE(std::filesystem::exists(folder_.path() / "out" / "banner_0005_diff.png"));
  // The pole three pixels to the side.
  Banner moved;
  moved.pole_x = 0.04;
  const CommandResult pole = snapshot(moved);
  EXPECT_EQ(pole.exit_code, 1) << pole.output;
  EXPECT_NE(pole.output.find("DIFFERS"), std::string::npos) << pole.output;
}

// A pole 1 cm thick is drawn under a pixel wide at 320 × 180 from 3.2 m: its colour could change
// and its goldens pass. --update says so, naming the pole (not the cloth) and a max_differing that
// sees it; under that, a change of the pole's green by 0.13 (0.55 → 0.42) fails, which under the
// default limits passes.
TEST_F(Snapshot, UpdateWarnsOfAnObjectTooThinForItsGoldensToSee) {
  Banner thin;
  thin.pole_radius = 0.005;
  const CommandResult made = snapshot(thin, "--update");
  ASSERT_EQ(made.exit_code, 0) << made.output;
  EXPECT_NE(made.output.find("warning: these goldens would not see object 'pole' change"),
            std::string::npos)
      << made.output;
  EXPECT_EQ(made.output.find("see object 'cloth'"), std::string::npos) << made.output;
  std::smatch found;
  ASSERT_TRUE(std::regex_search(made.output, found,
                                std::regex(R"(max_differing: ([0-9.e-]+) for the scene)")))
      << made.output;
  Banner repainted = thin;
  repainted.pole_color = "[0.55, 0.42, 0.58]";
  const CommandResult unseen = snapshot(repainted);
  EXPECT_EQ(unseen.exit_code, 0) << unseen.output;
  write_tolerances(
      fmt::format("version: 1\nscenes:\n  banner: {{max_differing: {}}}\n", found[1].str()));
  const CommandResult seen = snapshot(repainted);
  EXPECT_EQ(seen.exit_code, 1) << seen.output;
  EXPECT_NE(seen.output.find("DIFFERS"), std::string::npos) << seen.output;
  // And the goldens still pass the pole as it was, under the lower limit.
  const CommandResult same = snapshot(thin, "--threads 1");
  EXPECT_EQ(same.exit_code, 0) << same.output;
  // The goldens' own check: under the limit that sees it, --update warns no more.
  const CommandResult again = snapshot(thin, "--update");
  EXPECT_EQ(again.output.find("would not see"), std::string::npos) << again.output;
}

// --framing: the banner seen from 4 m passes (its 1.7 m pole spans 58 % of the height; from
// the goldens' 3.2 m the frame cuts the pole's foot); seen from 12 m it spans under a fifth of
// it and fails, even against goldens it matches, and so does a camera moved 2.5 m to the side,
// which cuts the cloth's far end.
TEST_F(Snapshot, FramingFailsAShotThatLosesOrCutsItsSubject) {
  Banner framed;
  framed.distance = 4.0;
  const CommandResult whole = snapshot(framed, "--update --framing 0.5");
  EXPECT_EQ(whole.exit_code, 0) << whole.output;
  EXPECT_NE(whole.output.find("framed (the subject spans"), std::string::npos) << whole.output;
  const CommandResult foot_cut = snapshot(Banner{}, "--framing 0.5");
  EXPECT_EQ(foot_cut.exit_code, 1) << foot_cut.output;
  EXPECT_NE(foot_cut.output.find("cuts the subject at the bottom"), std::string::npos)
      << foot_cut.output;

  Banner far;
  far.distance = 12.0;
  const CommandResult written = snapshot(far, "--update --framing 0.5");
  EXPECT_EQ(written.exit_code, 1) << written.output;
  EXPECT_NE(written.output.find("BADLY FRAMED"), std::string::npos) << written.output;
  const CommandResult matched = snapshot(far);
  EXPECT_EQ(matched.exit_code, 0) << matched.output;  // the pictures are the goldens
  const std::filesystem::path junit = folder_.path() / "framing.xml";
  const CommandResult small = snapshot(far, "--framing 0.5 --junit " + test::shell_quoted(junit));
  EXPECT_EQ(small.exit_code, 1) << small.output;
  EXPECT_NE(small.output.find("of the height, under the 50 % asked"), std::string::npos)
      << small.output;
  EXPECT_NE(read(junit).find("<failure"), std::string::npos) << read(junit);

  Banner aside;
  aside.distance = 4.0;
  aside.camera_x = -2.0;
  const CommandResult cut = snapshot(aside, "--update --framing 0.5");
  EXPECT_EQ(cut.exit_code, 1) << cut.output;
  EXPECT_NE(cut.output.find("cuts the subject at the right"), std::string::npos) << cut.output;
}

// Regions in the scene's metres: the pole's box left out lets the moved pole pass; weighed more,
// a change of the pole's colour too faint to fail the whole frame fails.
TEST_F(Snapshot, TheToleranceFileLeavesOutAndWeighsRegionsOfTheScene) {
  Banner moved;
  moved.pole_x = 0.04;
  write_tolerances(R"(version: 1
scenes:
  banner:
    ignore: [{box: [[-0.1, -0.1, -0.1], [0.1, 0.1, 1.8]]}]
)");
  const CommandResult ignored = snapshot(moved);
  EXPECT_EQ(ignored.exit_code, 0) << ignored.output;

  Banner tinted;
  tinted.pole_color = "[0.62, 0.50, 0.50]";
  write_tolerances("version: 1\n");
  const CommandResult plain = snapshot(tinted);
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  write_tolerances(R"(version: 1
scenes:
  banner:
    weigh: [{box: [[-0.05, -0.05, 0], [0.05, 0.05, 1.7]], weight: 50}]
)");
  const CommandResult weighed = snapshot(tinted);
  EXPECT_EQ(weighed.exit_code, 1) << weighed.output;
  // A frame's own limit: frame 5 alone loosened until the tint passes there.
  write_tolerances(R"(version: 1
scenes:
  banner:
    weigh: [{box: [[-0.05, -0.05, 0], [0.05, 0.05, 1.7]], weight: 50}]
    frames:
      5: {max_differing: 1, max_mean_error: 255, min_ssim: -1}
)");
  const CommandResult loosened = snapshot(tinted);
  EXPECT_NE(loosened.output.find("banner_0005: ok"), std::string::npos) << loosened.output;
  EXPECT_NE(loosened.output.find("banner_0001: DIFFERS"), std::string::npos) << loosened.output;
}

TEST_F(Snapshot, JUnitAndHtmlReportsHoldEveryFrame) {
  Banner recoloured;
  recoloured.cloth_color = "[0.15, 0.35, 0.80]";
  const std::filesystem::path junit = folder_.path() / "snapshots.xml";
  const std::filesystem::path html = folder_.path() / "snapshots.html";
  const CommandResult result = snapshot(
      recoloured,
      fmt::format("--junit {} --report {}", test::shell_quoted(junit), test::shell_quoted(html)));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  const std::string xml = read(junit);
  EXPECT_NE(xml.find(R"(<testsuites name="dinam snapshot" tests="2" failures="2")"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find(R"(<testcase classname="snapshot.banner" name="frame 0005")"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure type=\"differs\" message=\""), std::string::npos) << xml;
  EXPECT_EQ(xml.find("<testsuites", 1 + xml.find("<testsuites")), std::string::npos);
  const std::string page = read(html);
  EXPECT_NE(page.find("2 of 2 frames differ"), std::string::npos);
  // Expected, actual and difference of each frame, inside the page.
  std::size_t pictures = 0;
  for (std::size_t at = page.find("data:image/png;base64,"); at != std::string::npos;
       at = page.find("data:image/png;base64,", at + 1)) {
    ++pictures;
  }
  EXPECT_EQ(pictures, 6u);
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);  // nothing fetched
  EXPECT_NE(page.find("SSIM"), std::string::npos);
  // A run that passes writes a report that says so.
  const CommandResult passing =
      snapshot(Banner{}, fmt::format("--junit {}", test::shell_quoted(junit)));
  EXPECT_EQ(passing.exit_code, 0) << passing.output;
  EXPECT_NE(read(junit).find(R"(tests="2" failures="0")"), std::string::npos) << read(junit);
}

// Reports named in folders that do not exist yet are written there (the folders made before any
// frame is compared); options that cannot be right are refused before any work, exit 2: a
// --golden that names a file, a --framing that is no fraction.
TEST_F(Snapshot, ReportsIntoMissingFoldersAreWrittenAndImpossibleOptionsRefused) {
  const std::filesystem::path junit = folder_.path() / "ci" / "reports" / "snapshots.xml";
  const std::filesystem::path html = folder_.path() / "pages" / "snapshots.html";
  const CommandResult passing = snapshot(
      Banner{}, fmt::format("--junit {} --report {}", test::shell_quoted(junit),
                            test::shell_quoted(html)));
  EXPECT_EQ(passing.exit_code, 0) << passing.output;
  EXPECT_NE(read(junit).find(R"(tests="2" failures="0")"), std::string::npos) << passing.output;
  EXPECT_NE(read(html).find("frames"), std::string::npos);
  const CommandResult file_golden = run_command(dinam_command(
      fmt::format("snapshot {} --golden {}", test::shell_quoted(scene(Banner{})),
                  test::shell_quoted(golden() / "banner_0001.png"))));
  EXPECT_EQ(file_golden.exit_code, 2) << file_golden.output;
  EXPECT_NE(file_golden.output.find("banner_0001.png is a file; give the folder"),
            std::string::npos)
      << file_golden.output;
  for (const char* framing : {"nan", "inf", "1.5"}) {
    const CommandResult refused = snapshot(Banner{}, fmt::format("--framing {}", framing));
    EXPECT_EQ(refused.exit_code, 2) << framing << ": " << refused.output;
  }
}

// A golden image or the tolerance file replaced by a symbolic link (to another picture, to a file
// of the machine) is refused, naming it, exit 2: goldens are read only as files of their folder.
TEST_F(Snapshot, AGoldenOrToleranceFileThatIsALinkIsRefused) {
  for (const char* name : {"banner_0005.png", "tolerances.yaml"}) {
    const std::filesystem::path file = golden() / name;
    const std::filesystem::path elsewhere = folder_.path() / (std::string("kept-") + name);
    std::filesystem::rename(file, elsewhere);
    std::filesystem::create_symlink(elsewhere, file);
    const CommandResult result = snapshot(Banner{});
    EXPECT_EQ(result.exit_code, 2) << name << ": " << result.output;
    EXPECT_NE(result.output.find(std::string(name) + ": error:"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("is a symbolic link"), std::string::npos) << result.output;
    std::filesystem::remove(file);
    std::filesystem::rename(elsewhere, file);
  }
}

TEST_F(Snapshot, ABadToleranceFileStopsAtItsLine) {
  write_tolerances("version: 1\nscenes:\n  banner: {min_sim: 0.9}\n");
  const CommandResult result = snapshot(Banner{});
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("tolerances.yaml:3:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("min_ssim"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace dinam
