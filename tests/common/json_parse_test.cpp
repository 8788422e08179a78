// parse_json: nlohmann's parse with the nesting bounded (common/json_parse.h).
#include "common/json_parse.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"

namespace echoplan {
namespace {

std::string nested_arrays(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(ParseJson, ReadsWhatParseReads) {
  EXPECT_EQ(parse_json(R"({"a": [1, {"b": null}]})", "f.json"),
            nlohmann::json::parse(R"({"a": [1, {"b": null}]})"));
  EXPECT_EQ(parse_json(nested_arrays(kMaxJsonDepth), "f.json"),
            nlohmann::json::parse(nested_arrays(kMaxJsonDepth)));
  EXPECT_THROW((void)parse_json("{\"a\": ", "f.json"), nlohmann::json::parse_error);
}

// 100,000 levels (200 KB) parse without the bound, and a copy of them overflows an 8 MiB stack.
TEST(ParseJson, RefusesDeepNestingWithAnInputErrorNamingTheFile) {
  for (const int depth : {kMaxJsonDepth + 2, 100'000}) {
    try {
      (void)parse_json(nested_arrays(depth), "deep.json");
      ADD_FAILURE() << depth << " levels accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "deep.json");
      EXPECT_NE(e.problem().find("nested deeper than 128"), std::string::npos) << e.what();
    }
  }
  std::string objects = "1";
  for (int i = 0; i < 1000; ++i) objects = "{\"a\":" + objects + "}";
  EXPECT_THROW((void)parse_json(objects, "deep.json"), InputError);
}

}  // namespace
}  // namespace echoplan
