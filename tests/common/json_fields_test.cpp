// json_fields: JSON values read with errors naming the source (file, line) and the dotted path.
#include "common/json_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "input_error_message.h"

namespace echoplan::json_fields {
namespace {

using nlohmann::json;

TEST(JsonFields, ReadsWellFormedValues) {
  const json doc = json::parse(R"({"a": {"n": 2.5, "i": 7, "b": true, "s": "mug",
      "v": [1, 2.5], "m": [[1, 2], [3, 4], [5, 6]], "names": ["cup", "mug"]}})");
  const json& a = member(doc, "a", "", "model.json");
  EXPECT_EQ(number(member(a, "n", "a", "f"), "a.n", "f"), 2.5);
  EXPECT_EQ(integer(member(a, "i", "a", "f"), 0, 7, "a.i", "f"), 7);
  EXPECT_TRUE(boolean(member(a, "b", "a", "f"), "a.b", "f"));
  EXPECT_EQ(string(member(a, "s", "a", "f"), "a.s", "f"), "mug");
  EXPECT_EQ(numbers(a["v"], 2, "a.v", "f"), (std::vector<double>{1, 2.5}));
  EXPECT_EQ(numbers(a["v"], -1, "a.v", "f"), (std::vector<double>{1, 2.5}));
  // Row-major: rows one after the other.
  EXPECT_EQ(matrix(a["m"], 3, 2, "a.m", "f"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(matrix(a["m"], -1, -1, "a.m", "f"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(names(a["names"], 2, "a.names", "f"), (std::vector<std::string>{"cup", "mug"}));
}

TEST(JsonFields, RowsOfUndoesMatrix) {
  const std::vector<double> values = {1, 2, 3, 4, 5, 6};
  EXPECT_EQ(rows_of(values, 2, 3), json::parse("[[1, 2, 3], [4, 5, 6]]"));
  EXPECT_EQ(matrix(rows_of(values, 3, 2), 3, 2, "m", "f"), values);
}

TEST(JsonFields, EachMistakeNamesTheFileAndThePath) {
  const json doc = json::parse(R"({"per_action": {"strike": {"k": 3}}})");
  const json& strike = doc["per_action"]["strike"];
  EXPECT_EQ(
      input_error_message([&] { member(strike, "templates", "per_action.strike", "m.json"); }),
      "m.json: per_action.strike.templates: missing");
  EXPECT_EQ(input_error_message([&] { member(json(3), "k", "x", "m.json"); }),
            "m.json: x: expected an object");
  EXPECT_EQ(input_error_message([&] { number(json("3"), "x", "m.json"); }),
            "m.json: x: expected a number");
  EXPECT_EQ(
      input_error_message([&] { number(json(std::numeric_limits<double>::infinity()), "x", "m"); }),
      "m: x: expected a finite number");
  EXPECT_EQ(input_error_message([&] { integer(json(2.5), 0, 9, "x", "m"); }),
            "m: x: expected an integer");
  EXPECT_EQ(input_error_message([&] { integer(json(10), 0, 9, "x", "m"); }),
            "m: x: 10 is outside 0..9");
  EXPECT_EQ(input_error_message([&] { integer(json(-1), 0, 9, "x", "m"); }),
            "m: x: -1 is outside 0..9");
  EXPECT_EQ(input_error_message([&] { boolean(json(1), "x", "m"); }),
            "m: x: expected true or false");
  EXPECT_EQ(input_error_message([&] { string(json(1), "x", "m"); }), "m: x: expected a string");
  EXPECT_EQ(input_error_message([&] { numbers(json::parse("[1, 2]"), 3, "v", "m"); }),
            "m: v: expected 3 numbers, found 2");
  EXPECT_EQ(input_error_message([&] { numbers(json::parse("[1, null]"), -1, "v", "m"); }),
            "m: v[1]: expected a number");
  EXPECT_EQ(input_error_message([&] { matrix(json::parse("[[1, 2], [3]]"), -1, -1, "w", "m"); }),
            "m: w[1]: expected 2 numbers, found 1");
  EXPECT_EQ(input_error_message([&] { matrix(json::parse("[[1]]"), 2, 1, "w", "m"); }),
            "m: w: expected 2 rows, found 1");
  EXPECT_EQ(input_error_message([&] { names(json::parse(R"(["a", ""])"), -1, "c", "m"); }),
            "m: c[1]: empty name");
  EXPECT_EQ(input_error_message([&] { names(json::parse(R"(["a", "b", "a"])"), -1, "c", "m"); }),
            "m: c[2]: 'a' appears twice");
  EXPECT_EQ(input_error_message([&] { names(json::parse(R"(["a"])"), 2, "c", "m"); }),
            "m: c: expected 2 names, found 1");
}

TEST(JsonFields, ReadsWideIntegersListsAndOptionalMembers) {
  const json doc = json::parse(R"({"seed": 18446744073709551615, "episodes": -9000000000,
      "counts": [3, -1], "names": ["mug", "mug"], "steps": [{}, {}]})");
  EXPECT_EQ(unsigned64(doc["seed"], "seed", "f"), 18446744073709551615ULL);
  EXPECT_EQ(integer64(doc["episodes"], "episodes", "f"), -9000000000LL);
  EXPECT_EQ(integers(doc["counts"], 2, "counts", "f"), (std::vector<int>{3, -1}));
  EXPECT_EQ(strings(doc["names"], "names", "f"), (std::vector<std::string>{"mug", "mug"}));
  EXPECT_EQ(array(doc["steps"], "steps", "f").size(), 2u);
  EXPECT_EQ(optional_member(doc, "absent", "", "f"), nullptr);
  EXPECT_EQ(optional_member(doc, "seed", "", "f"), &doc["seed"]);
  EXPECT_EQ(child("", "a"), "a");
  EXPECT_EQ(child("a", "b"), "a.b");
  EXPECT_EQ(element("a.b", 3), "a.b[3]");
}

TEST(JsonFields, ALineOfAFileIsNamedWithTheFile) {
  const JsonSource line{"journal.jsonl", 7};
  const json entry = json::parse(R"({"step_log": [{"reward": "high"}], "seed": -1, "big": 1e3})");
  EXPECT_EQ(input_error_message(
                [&] { number(entry["step_log"][0]["reward"], "step_log[0].reward", line); }),
            "journal.jsonl:7: step_log[0].reward: expected a number");
  EXPECT_EQ(input_error_message([&] { member(entry, "id", "", line); }),
            "journal.jsonl:7: id: missing");
  EXPECT_EQ(input_error_message([&] { member(json(3), "id", "", line); }),
            "journal.jsonl:7: expected an object");
  EXPECT_EQ(input_error_message([&] { unsigned64(entry["seed"], "seed", line); }),
            "journal.jsonl:7: seed: -1 is negative");
  EXPECT_EQ(input_error_message([&] { integer64(entry["big"], "big", line); }),
            "journal.jsonl:7: big: expected an integer");
  EXPECT_EQ(input_error_message([&] { integer64(json(18446744073709551615ULL), "n", line); }),
            "journal.jsonl:7: n: 18446744073709551615 is too large");
  EXPECT_EQ(input_error_message([&] { integers(json::parse("[1, 2.5]"), -1, "c", line); }),
            "journal.jsonl:7: c[1]: expected an integer");
  EXPECT_EQ(input_error_message([&] { strings(json::parse(R"(["a", 1])"), "s", line); }),
            "journal.jsonl:7: s[1]: expected a string");
  EXPECT_EQ(input_error_message([&] { array(json(1), "steps", line); }),
            "journal.jsonl:7: steps: expected an array");
}

}  // namespace
}  // namespace echoplan::json_fields
