#include "common/error.h"

#include <gtest/gtest.h>

namespace echoplan {
namespace {

TEST(InputError, NamesFileLineAndProblem) {
  InputError e("problems/x.yaml", 12, "row does not sum to 1");
  EXPECT_STREQ(e.what(), "problems/x.yaml:12: row does not sum to 1");
  EXPECT_EQ(e.file(), "problems/x.yaml");
  EXPECT_EQ(e.line(), 12);
  EXPECT_EQ(e.problem(), "row does not sum to 1");
}

TEST(InputError, OmitsUnknownLineAndFile) {
  EXPECT_STREQ(InputError("a.wav", 0, "empty file").what(), "a.wav: empty file");
  EXPECT_STREQ(InputError("--trials must be positive").what(), "--trials must be positive");
}

}  // namespace
}  // namespace echoplan
