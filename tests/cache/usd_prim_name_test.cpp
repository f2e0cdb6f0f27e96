// USD prim names from object names: USD takes [A-Za-z_][A-Za-z0-9_]* as a prim's name, and a
// stage with any other name does not open (Houdini, usdview and Blender all refuse it).
#include <gtest/gtest.h>

#include <regex>

#include "cache/usd_stage.hpp"

namespace dinam {
namespace {

TEST(UsdStage, PrimNamesAreUsdIdentifiersWhateverTheObjectIsCalled) {
  EXPECT_EQ(usd_prim_name("cloth"), "cloth");
  EXPECT_EQ(usd_prim_name("pole 1"), "pole_1");
  EXPECT_EQ(usd_prim_name("flag.v2-final"), "flag_v2_final");
  EXPECT_EQ(usd_prim_name("2nd_rope"), "_2nd_rope");
  EXPECT_EQ(usd_prim_name(""), "_");
  const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
  for (const char* name : {"drapé", "a/b", "\"quoted\"", "tab\there", "9", "_"}) {
    EXPECT_TRUE(std::regex_match(usd_prim_name(name), identifier)) << name;
  }
}

}  // namespace
}  // namespace dinam
