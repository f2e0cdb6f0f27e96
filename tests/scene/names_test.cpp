// Names (the scene's and each object's) go into JSON manifests, USD stages and web pages, which
// hold only UTF-8: a name that is not is refused at its line, whatever the bytes.
#include <gtest/gtest.h>

#include <string>

#include "test_support.hpp"

namespace dinam {
namespace {

SceneDescription scene_named(const std::string& object_name) {
  return test::scene_from_yaml("version: 1\nduration: 1\nobjects:\n  - name: \"" + object_name +
                               "\"\n    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]]}}\n"
                               "    material: {density: 1000, youngs_modulus: 1.0e6, "
                               "radius: 0.005}\n");
}

TEST(Names, UnicodeNamesAreKept) {
  EXPECT_EQ(scene_named("drapeau tricolore é 旗 🏳").objects[0].name,
            "drapeau tricolore é 旗 🏳");
}

TEST(Names, NamesThatAreNotUtf8AreRefusedAtTheirLine) {
  // A stray byte, a sequence cut short, an overlong '/', a surrogate, beyond U+10FFFF.
  for (const std::string& bytes :
       {std::string("flag\xff"), std::string("\xe6\x97"), std::string("\xc0\xaf"),
        std::string("\xed\xa0\x80"), std::string("\xf4\x90\x80\x80")}) {
    test::expect_user_error([&] { scene_named(bytes); }, 4,
                            {"'objects[0].name' is not UTF-8 text"});
  }
  test::expect_user_error(
      [] {
        test::scene_from_yaml(
            "version: 1\nname: \"scene\xfe\"\nduration: 1\nobjects:\n  - mesh: {polyline: {points: "
            "[[0, 0, 1], [1, 0, 1]]}}\n    material: {density: 1, youngs_modulus: 1, radius: "
            "0.01}\n");
      },
      2, {"'name' is not UTF-8 text"});
}

}  // namespace
}  // namespace dinam
