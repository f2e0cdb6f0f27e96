// The program as a user runs it: a scene file in, frames and a movie out, exit codes and
// messages for bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <iterator>
#include <sstream>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "app/output_checks.hpp"
#include "io/png_file.hpp"
#include "render/digit_label.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::CommandResult;

using test::dinam_command;
using test::run_command;

// A green rope hanging from a pinned end in front of the camera: 3 frames at 10 fps.
const char* const kTinyScene = R"(version: 1
name: tiny
duration: 0.3
fps: 10
camera: {position: [0.5, -3, 1], look_at: [0.5, 0, 0.8], fov: 45}
image: {width: 640, height: 480}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 8}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {indices: [0]}
    color: [0.1, 0.9, 0.1]
    render_radius: 0.03
)";

// Every number `info --json` prints under `key`, in order.
std::vector<double> json_numbers(const std::string& json, const std::string& key) {
  const std::string label = "\"" + key + "\": ";
  std::vector<double> found;
  for (std::size_t at = json.find(label); at != std::string::npos; at = json.find(label, at + 1)) {
    found.push_back(std::stod(json.substr(at + label.size())));
  }
  return found;
}

class EndToEnd : public ::testing::Test {
 protected:
  std::filesystem::path write_scene(const std::string& name, const std::string& text) {
    const std::filesystem::path path = folder_.path() / name;
    std::ofstream(path) << text;
    return path;
  }
  std::filesystem::path out() const { return folder_.path() / "out"; }

  test::TemporaryFolder folder_{"e2e"};
};

bool is_green(const std::uint8_t* p) {
  return p[1] > p[0] + 60 && p[1] > p[2] + 60;
}

TEST_F(EndToEnd, TinySceneGivesThreeFramesOfTheRequestedSizeAndAMovie) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result = run_command(
      dinam_command("render '" + scene.string() + "' -o '" + out().string() + "' --size 96x64"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* name : {"frame_0001.png", "frame_0002.png", "frame_0003.png"}) {
    const Image image = read_png(out() / name);  // throws if it is not a valid PNG
    EXPECT_EQ(image.width, 96) << name;
    EXPECT_EQ(image.height, 64) << name;
    int green = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        green += is_green(image.pixel(x, y)) ? 1 : 0;
      }
    }
    // The sky and the ground have no green pixels; the rope covers dozens.
    EXPECT_GT(green, 20) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(out() / "frame_0004.png"));
  EXPECT_GT(std::filesystem::file_size(out() / "tiny.mp4"), 0u);
  EXPECT_TRUE(test::temporary_files_in(out()).empty());

  // ffprobe comes with ffmpeg: the movie holds the 3 frames as H.264 in yuv420p.
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,pix_fmt,nb_read_frames -of csv=p=0 '" +
      (out() / "tiny.mp4").string() + "'");
  ASSERT_EQ(probe.exit_code, 0) << probe.output;
  EXPECT_EQ(probe.output, "h264,yuv420p,3\n");
}

TEST_F(EndToEnd, FrameRangeWritesOnlyThoseFrames) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() +
                                "' --size 64x48 --frames 2-3 --movie none --quiet"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output, "");  // --quiet
  EXPECT_FALSE(std::filesystem::exists(out() / "frame_0001.png"));
  EXPECT_TRUE(std::filesystem::exists(out() / "frame_0002.png"));
  EXPECT_TRUE(std::filesystem::exists(out() / "frame_0003.png"));
  EXPECT_FALSE(std::filesystem::exists(out() / "tiny.mp4"));
}

// A list of frames and ranges writes those frames, each the whole render's, and no movie where
// they leave gaps (a movie is of frames one after another).
TEST_F(EndToEnd, AFrameListWritesThoseFramesAndNoMovieAcrossItsGaps) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  ASSERT_EQ(
      run_command(dinam_command("render '" + scene.string() + "' -o '" +
                                (out() / "whole").string() + "' --size 64x48 --movie none --quiet"))
          .exit_code,
      0);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() +
                                "' --size 64x48 --frames 1,3-3,last"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("no movie (the frames chosen are not one run)"), std::string::npos)
      << result.output;
  std::vector<std::string> written;
  for (const auto& entry : std::filesystem::directory_iterator(out())) {
    if (entry.path().extension() == ".png" || entry.path().extension() == ".mp4") {
      written.push_back(entry.path().filename().string());
    }
  }
  std::sort(written.begin(), written.end());
  // The tiny scene has 3 frames: 'last' is the 3 already named, written once.
  const std::vector<std::string> expected = {"frame_0001.png", "frame_0003.png"};
  EXPECT_EQ(written, expected);
  for (const std::string& name : expected) {
    EXPECT_EQ(test::read_text(out() / name), test::read_text(out() / "whole" / name)) << name;
  }
  EXPECT_EQ(run_command(dinam_command("render '" + scene.string() + "' --frames 1,,3")).exit_code,
            2);
}

// A part of the frames makes a movie of that part, named for it: never a short movie under the
// whole movie's name, which a player or an editor would take for the whole.
TEST_F(EndToEnd, AFrameRangesMovieIsNamedForTheRange) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() +
                                "' --size 64x48 --frames 2-3 --quiet"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out() / "tiny.mp4"));
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames -of csv=p=0 '" +
      (out() / "tiny_frames_2-3.mp4").string() + "'");
  ASSERT_EQ(probe.exit_code, 0) << probe.output;
  EXPECT_EQ(probe.output, "2\n");
}

// --preview: the scene drawn as `image: {quality: draft}` at 320 pixels wide would draw it, every
// Nth frame, as a contact sheet whose pictures are those frames, each with its frame number below
// it, and as a GIF of them.
TEST_F(EndToEnd, PreviewIsADraftContactSheetAndGifOfEveryNthFrame) {
  std::string text = kTinyScene;
  text.replace(text.find("duration: 0.3"), 13, "duration: 4.0");  // 40 frames: every 2nd, 20
  const auto scene = write_scene("tiny.yaml", text);
  const CommandResult preview = run_command(
      dinam_command("render '" + scene.string() + "' -o '" + out().string() + "' --preview"));
  ASSERT_EQ(preview.exit_code, 0) << preview.output;
  EXPECT_NE(preview.output.find("preview of 20 frames (every 2nd frame)"), std::string::npos)
      << preview.output;
  const Image sheet = read_png(out() / "tiny_preview.png");
  // 6 columns and 4 rows of 320 × 240 pictures with a band of 20 pixels for the number below
  // each, 2 pixels apart and around.
  constexpr int kCell = 240 + 20;
  EXPECT_EQ(sheet.width, 6 * 320 + 7 * 2);
  EXPECT_EQ(sheet.height, 4 * kCell + 5 * 2);
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -show_entries stream=nb_read_frames,width,height -of "
      "csv=p=0 '" +
      (out() / "tiny_preview.gif").string() + "'");
  EXPECT_EQ(probe.output, "320,240,20\n");
  EXPECT_FALSE(std::filesystem::exists(out() / "frame_0001.png"));
  EXPECT_FALSE(std::filesystem::exists(out() / "tiny.mp4"));

  // The eighth picture (row 1, column 1) is frame 15 as a full render at draft quality draws it.
  std::string draft = text;
  draft.replace(draft.find("image: {width: 640, height: 480}"), 32,
                "image: {width: 320, height: 240, quality: draft}");
  const auto draft_scene = write_scene("draft.yaml", draft);
  const CommandResult full =
      run_command(dinam_command("render '" + draft_scene.string() + "' -o '" +
                                (out() / "full").string() + "' --frames 15 --movie none -q"));
  ASSERT_EQ(full.exit_code, 0) << full.output;
  const Image frame = read_png(out() / "full" / "frame_0015.png");
  int differing = 0;
  for (int y = 0; y < 240; ++y) {
    for (int x = 0; x < 320; ++x) {
      differing += std::equal(frame.pixel(x, y), frame.pixel(x, y) + 3,
                              sheet.pixel(2 + 1 * 322 + x, 2 + 1 * (kCell + 2) + y))
                       ? 0
                       : 1;
    }
  }
  EXPECT_EQ(differing, 0);
  // Below it, its number: the band is the sheet's grey but for "15" in the label font, at the
  // band's left (3 pixels in), and nothing else.
  Image band(320, 20);
  for (std::size_t k = 0; k < band.rgba.size(); k += 4) {
    band.rgba[k] = band.rgba[k + 1] = band.rgba[k + 2] = 40;
    band.rgba[k + 3] = 255;
  }
  const unsigned char light[3] = {210, 210, 210};
  draw_digit_label(band, 3, 3, "15", 2, light);
  int lit = 0;
  differing = 0;
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 320; ++x) {
      const std::uint8_t* drawn = sheet.pixel(2 + 1 * 322 + x, 2 + 1 * (kCell + 2) + 240 + y);
      lit += drawn[0] == 210 ? 1 : 0;
      differing += std::equal(band.pixel(x, y), band.pixel(x, y) + 3, drawn) ? 0 : 1;
    }
  }
  EXPECT_GT(lit, 2 * 4 * 7);  // two digits of several 2 × 2 pixels each
  EXPECT_EQ(differing, 0);
}

TEST_F(EndToEnd, EnergyCsvHasARowPerFrameAndABalanceThatHolds) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() +
                                "' --size 64x48 --no-video --energy -q"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream csv(out() / "energy.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.substr(0, 26), "time_s,kinetic_J,axial_J,b");
  std::vector<double> totals;
  for (std::string line; std::getline(csv, line);) {
    totals.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  }
  ASSERT_EQ(totals.size(), 3u);  // one row per frame
  // The rope is undamped: its energy balance holds to the integrator's error.
  for (const double total : totals) {
    EXPECT_NEAR(total, totals.front(), 1e-3 * std::abs(totals.front()));
  }
  // energy.svg beside it: a line a frame for every account that is not zero throughout (the
  // kinetic, axial, gravitational and total here), labelled, and the worst deviation in the title.
  std::ifstream svg_file(out() / "energy.svg");
  const std::string svg(std::istreambuf_iterator<char>(svg_file), {});
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0U);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("Energy against time: balance within "), std::string::npos);
  EXPECT_NE(svg.find(" % of the peak kinetic energy"), std::string::npos);
  int lines = 0;
  for (std::size_t at = svg.find("points=\""); at != std::string::npos;
       at = svg.find("points=\"", at + 1)) {
    const std::string points = svg.substr(at + 8, svg.find('"', at + 8) - at - 8);
    EXPECT_EQ(std::count(points.begin(), points.end(), ','), 3) << points;  // one point a frame
    ++lines;
  }
  EXPECT_GE(lines, 4);
  for (const char* label : {">kinetic<", ">axial<", ">gravitational<", ">total<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_EQ(svg.find(">wind_work<"), std::string::npos);  // no wind: left out
  EXPECT_TRUE(test::temporary_files_in(out()).empty());
}

// With the implicit integrator the report is kept too: the rope swinging down from level at
// steps of a quarter frame, its numerical dissipation a column of its own (backward Euler only
// takes energy out), and the balance holding to what Newton's residual allows (at most 0.01 m/s²
// on the rope's 0.05 kg over paths under 1 m: 5e-4 J, against the 0.09 J its fall gives up).
TEST_F(EndToEnd, EnergyCsvOfTheImplicitIntegratorBooksItsNumericalDissipation) {
  const auto scene = write_scene("tiny.yaml", std::string(kTinyScene) + "integrator: implicit\n");
  const CommandResult result = run_command(
      dinam_command("simulate '" + scene.string() + "' -o '" + out().string() + "' --energy -q"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream csv(out() / "energy.csv");
  std::string header;
  std::getline(csv, header);
  const std::string column = "numerical_dissipation_J";
  const auto at = header.find(column);
  ASSERT_NE(at, std::string::npos) << header;
  const auto index = std::count(header.begin(), header.begin() + static_cast<long>(at), ',');
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(csv, line);) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) {
      row.push_back(std::stod(cell));
    }
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 3u);  // one row per frame
  EXPECT_EQ(rows.front()[0], 0.0);
  EXPECT_EQ(rows.front()[static_cast<std::size_t>(index)], 0.0);
  const double fallen = rows.front()[5] - rows.back()[5];  // J, gravitational energy given up
  std::printf("fallen %.4g J, numerical dissipation %.4g J, total %.9g J to %.9g J\n", fallen,
              rows.back()[static_cast<std::size_t>(index)], rows.front().back(),
              rows.back().back());
  EXPECT_GT(fallen, 0.05);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_GT(rows[k][static_cast<std::size_t>(index)],
              rows[k - 1][static_cast<std::size_t>(index)]);
    EXPECT_NEAR(rows[k].back(), rows.front().back(), 5e-4);
  }
}

TEST_F(EndToEnd, SameSceneRendersToByteIdenticalFramesTwice) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  for (const char* folder : {"first", "second"}) {
    const CommandResult result = run_command(dinam_command("render '" + scene.string() + "' -o '" +
                                                           (folder_.path() / folder).string() +
                                                           "' --size 96x64 --movie gif -q"));
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  auto bytes = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* name : {"frame_0001.png", "frame_0002.png", "frame_0003.png", "tiny.gif"}) {
    const std::string first = bytes(folder_.path() / "first" / name);
    ASSERT_FALSE(first.empty()) << name;
    EXPECT_EQ(first, bytes(folder_.path() / "second" / name)) << name;
  }
  // The GIF is a real three-frame GIF.
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,nb_read_frames -of csv=p=0 '" +
      (folder_.path() / "first" / "tiny.gif").string() + "'");
  EXPECT_EQ(probe.output, "gif,3\n");
}

TEST_F(EndToEnd, SnapshotFailsWithoutGoldenUpdatesThenCatchesAChange) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const std::string golden = (folder_.path() / "golden").string();
  const std::string snapshot = "snapshot '" + scene.string() + "' --golden '" + golden +
                               "' --frames 1,3 --size 160x90 -o '" + out().string() + "'";
  // No golden yet: it fails and says how to make one.
  CommandResult result = run_command(dinam_command(snapshot));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("--update"), std::string::npos) << result.output;
  // --update writes them; then the same scene matches.
  result = run_command(dinam_command(snapshot + " --update"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder_.path() / "golden" / "tiny_0001.png"));
  EXPECT_TRUE(std::filesystem::exists(folder_.path() / "golden" / "tiny_0003.png"));
  result = run_command(dinam_command(snapshot));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  // A visibly changed scene (the rope's colour) fails, with the three images written.
  std::string changed = kTinyScene;
  changed.replace(changed.find("color: [0.1, 0.9, 0.1]"), 22, "color: [0.9, 0.1, 0.9]");
  write_scene("tiny.yaml", changed);
  result = run_command(dinam_command(snapshot));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("DIFFERS"), std::string::npos) << result.output;
  for (const char* name :
       {"tiny_0003_actual.png", "tiny_0003_expected.png", "tiny_0003_diff.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out() / name)) << name;
    EXPECT_NE(result.output.find((out() / name).string()), std::string::npos) << name;
  }
}

TEST_F(EndToEnd, BadSceneExitsTwoNamingFileLineAndKeyAndWritesNothing) {
  std::string text = kTinyScene;
  text.replace(text.find("density: 1000"), 13, "density: -1");
  const auto scene = write_scene("bad.yaml", text);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() + "'"));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find(scene.string() + ":10:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("density"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(EndToEnd, UnstableStepExitsTwoWithBothNumbers) {
  std::string text = kTinyScene;
  text.replace(text.find("fps: 10"), 7, "fps: 10\ntimestep: 0.01");
  const auto scene = write_scene("unstable.yaml", text);
  const CommandResult result =
      run_command(dinam_command("render '" + scene.string() + "' -o '" + out().string() + "'"));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("unstable.yaml:5:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("0.01 s is above"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("stability limit"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(EndToEnd, MissingFfmpegKeepsTheFramesAndSaysHowToInstallIt) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result = run_command(
      "PATH='" + folder_.path().string() + "' " +
      dinam_command("render '" + scene.string() + "' -o '" + out().string() + "' --size 64x48"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("apt-get install ffmpeg"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out() / "frame_0003.png"));
  EXPECT_FALSE(std::filesystem::exists(out() / "tiny.mp4"));
}

TEST_F(EndToEnd, UsageErrorsExitTwoAndHelpExitsZero) {
  EXPECT_EQ(run_command(dinam_command("--help")).exit_code, 0);
  EXPECT_EQ(run_command(dinam_command("render --help")).exit_code, 0);
  EXPECT_EQ(run_command(dinam_command("info --help")).exit_code, 0);
  EXPECT_EQ(run_command(dinam_command("")).exit_code, 2);
  EXPECT_EQ(run_command(dinam_command("render")).exit_code, 2);
  EXPECT_EQ(run_command(dinam_command("render x.yaml --bogus")).exit_code, 2);
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  EXPECT_EQ(run_command(dinam_command("render '" + scene.string() + "' --frames 2-9")).exit_code,
            2);
  EXPECT_EQ(run_command(dinam_command("render '" + scene.string() + "' --size 10")).exit_code, 2);
  EXPECT_EQ(run_command(dinam_command("info '" + (folder_.path() / "missing.yaml").string() + "'"))
                .exit_code,
            2);
}

TEST_F(EndToEnd, InfoPrintsTheModelSummary) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult result = run_command(dinam_command("info '" + scene.string() + "'"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* line :
       {"nodes            9 (1 pinned)", "bars             8", "axial 8, bending 7, torsion 0",
        "no torsion       8 bars", "stability limit", "time step", "steps per frame",
        "frames           3 at 10 fps"}) {
    EXPECT_NE(result.output.find(line), std::string::npos) << line << "\n" << result.output;
  }
}

// `info --energy` says what balance to expect: the automatic step is at most 0.8 of the stability
// limit, itself at most 2/ω_max (less with damping), so ω_max·Δt is at most 1.6; the step it
// offers for 0.1 % is smaller by √(0.1 % / the expected share), since the error grows as Δt².
TEST_F(EndToEnd, InfoSaysWhatEnergyBalanceTheStepGives) {
  const auto scene = write_scene("tiny.yaml", kTinyScene);
  const CommandResult text = run_command(dinam_command("info --energy '" + scene.string() + "'"));
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("energy balance   ω_max·Δt = "), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("brings that to about 0.1 %"), std::string::npos) << text.output;
  const CommandResult json = run_command(dinam_command("info --json '" + scene.string() + "'"));
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto number = [&](const std::string& key) {
    const std::vector<double> found = json_numbers(json.output, key);
    EXPECT_FALSE(found.empty()) << key;
    return found.empty() ? 0.0 : found.front();
  };
  const double omega_dt = number("omega_max_dt");
  const double limit = number("stability_limit_s");
  const double step = number("timestep_s");
  EXPECT_GT(omega_dt, 0.0);
  EXPECT_LE(omega_dt, 2.0 * step / limit * (1.0 + 1e-12));  // the limit is at most 2/ω_max
  EXPECT_LE(step, 0.8 * limit * (1.0 + 1e-12));             // so ω_max·Δt ≤ 1.6
  const double balance = number("expected_energy_balance");
  EXPECT_NEAR(number("timestep_for_0_1_percent_balance_s") / step, std::sqrt(0.001 / balance),
              1e-9);
}

// With the implicit integrator, `info --energy` says where its loss is booked and how much of a
// mode's amplitude each scheme keeps a period at the scene's step (a quarter frame here, 25 ms):
// backward Euler's root 1/(1 − iωh) has modulus (1 + ω²h²)^−½, so over a period of N steps
// (ωh = 2π/N) it keeps (1 + (2π/N)²)^−N/2; BDF2's characteristic equation (3 − 2iωh) z² − 4z + 1
// = 0 has the principal root (2 + √(1 + 2iωh))/(3 − 2iωh).
TEST_F(EndToEnd, InfoSaysHowMuchTheImplicitSchemesDampAMode) {
  const auto scene = write_scene("tiny.yaml", std::string(kTinyScene) + "integrator: implicit\n");
  const CommandResult text = run_command(dinam_command("info --energy '" + scene.string() + "'"));
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("numerical_dissipation_J"), std::string::npos) << text.output;
  EXPECT_EQ(text.output.find("ω_max·Δt"), std::string::npos) << text.output;
  const CommandResult json = run_command(dinam_command("info --json '" + scene.string() + "'"));
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto numbers = [&](const std::string& key) { return json_numbers(json.output, key); };
  const std::vector<double> steps = numbers("steps_per_period");
  const std::vector<double> frequency = numbers("frequency_hz");
  const std::vector<double> euler = numbers("backward_euler");
  const std::vector<double> bdf2 = numbers("bdf2");
  ASSERT_EQ(steps.size(), 3u);
  ASSERT_EQ(euler.size(), 3u);
  ASSERT_EQ(bdf2.size(), 3u);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const double n = steps[k];
    const double omega_h = 2.0 * std::numbers::pi / n;
    EXPECT_NEAR(frequency[k], 1.0 / (n * 0.025), 1e-9);
    EXPECT_NEAR(euler[k], std::pow(1.0 + omega_h * omega_h, -n / 2.0), 1e-12);
    const std::complex<double> z(0.0, omega_h);
    const std::complex<double> root = (2.0 + std::sqrt(1.0 + 2.0 * z)) / (3.0 - 2.0 * z);
    EXPECT_NEAR(bdf2[k], std::pow(std::abs(root), n), 1e-12);
  }
  EXPECT_NEAR(euler[1], 0.32, 0.005);  // 16 steps: 68 % lost a period (docs/scene-format.md)
  EXPECT_NEAR(bdf2[1], 0.933, 0.001);  // and BDF2 6.7 %
}

}  // namespace
}  // namespace dinam
