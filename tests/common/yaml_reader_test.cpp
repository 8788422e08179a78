#include "common/yaml_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"
#include "common/file_io.h"

namespace echoplan {
namespace {

// The InputError `read` throws; fails the test when it throws none.
template <class Read>
InputError error_of(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("", 0, "");
}

bool has(const InputError& e, const std::string& text) {
  return e.problem().find(text) != std::string::npos;
}

const char* const kDoc =
    "name: tiger\n"       // line 1
    "discount: 0.95\n"    // line 2
    "size: [1, 2, 3]\n"   // line 3
    "names: [a, b, a]\n"  // line 4
    "count: -3\n"         // line 5
    "flag: maybe\n"       // line 6
    "section:\n"          // line 7
    "  inner: x\n"        // line 8
    "  discont: 1\n";     // line 9

class YamlReaderTest : public testing::Test {
 protected:
  YAML::Node root = parse_yaml(kDoc, "doc.yaml");
  YamlReader r{"doc.yaml"};
};

TEST_F(YamlReaderTest, ReadsWellFormedValues) {
  EXPECT_EQ(r.name(root["name"], "name"), "tiger");
  EXPECT_DOUBLE_EQ(r.number(root["discount"], "discount", NumberRange::open(0, 1)), 0.95);
  EXPECT_EQ(r.numbers(root["size"], "size", 3), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(r.boolean(YAML::Load("yes"), "flag"));
  EXPECT_FALSE(r.boolean(YAML::Load("false"), "flag"));
  EXPECT_EQ(r.non_negative_int(YAML::Load("42"), "count"), 42);
  EXPECT_EQ(r.names(YAML::Load("[a, b]"), "names"), (std::vector<std::string>{"a", "b"}));
}

TEST_F(YamlReaderTest, ErrorsNameFileLineFieldAndWhatIsExpected) {
  InputError e =
      error_of([&] { r.number(root["discount"], "discount", NumberRange::closed(0, 0.5)); });
  EXPECT_EQ(e.file(), "doc.yaml");
  EXPECT_EQ(e.line(), 2);
  EXPECT_TRUE(has(e, "discount must be in [0, 0.5], got 0.95")) << e.what();

  e = error_of([&] { r.numbers(root["size"], "offset", 2); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_TRUE(has(e, "offset needs 2 numbers, got 3")) << e.what();

  e = error_of([&] { r.names(root["names"], "objects"); });
  EXPECT_EQ(e.line(), 4);
  EXPECT_TRUE(has(e, "duplicate name 'a' in objects")) << e.what();

  e = error_of([&] { r.non_negative_int(root["count"], "particles"); });
  EXPECT_EQ(e.line(), 5);
  EXPECT_TRUE(has(e, "particles must not be negative")) << e.what();

  e = error_of([&] { r.boolean(root["flag"], "closed"); });
  EXPECT_EQ(e.line(), 6);
  EXPECT_TRUE(has(e, "closed must be true or false")) << e.what();

  e = error_of([&] { r.number(root["name"], "discount"); });
  EXPECT_EQ(e.line(), 1);
  EXPECT_TRUE(has(e, "discount must be a number like 0.5, got 'tiger'")) << e.what();
}

TEST_F(YamlReaderTest, UnknownKeysAreListedWithTheAllowedOnes) {
  const InputError e = error_of([&] {
    r.only_keys(root["section"], {"inner", "discount"}, "section");
  });
  EXPECT_EQ(e.line(), 9);
  EXPECT_TRUE(has(e, "unknown key 'discont' in section (expected one of: inner, discount)"))
      << e.what();
}

TEST_F(YamlReaderTest, MissingKeyPointsAtTheMapping) {
  const InputError e = error_of([&] { r.require(root["section"], "outer", "section"); });
  EXPECT_EQ(e.line(), 8);
  EXPECT_TRUE(has(e, "missing key 'outer' in section")) << e.what();
  EXPECT_FALSE(r.optional(root["section"], "outer", "section").IsDefined());
}

TEST_F(YamlReaderTest, NonMappingWhereAMappingBelongs) {
  const InputError e = error_of([&] { r.optional(root["size"], "x", "size"); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_TRUE(has(e, "size must be a mapping")) << e.what();
}

TEST(YamlReader, DuplicateKeysAreRejectedAtTheSecondOccurrence) {
  const YAML::Node root = parse_yaml("a:\n  b: 1\n  c: 2\n  b: 3\n", "dup.yaml");
  const InputError e = error_of([&] { YamlReader("dup.yaml").reject_duplicate_keys(root); });
  EXPECT_EQ(e.line(), 4);
  EXPECT_TRUE(has(e, "key 'b' appears twice")) << e.what();
}

TEST(YamlReader, SyntaxErrorsCarryTheirLine) {
  const InputError e = error_of([] { parse_yaml("a: 1\nb: [1, 2\n", "bad.yaml"); });
  EXPECT_EQ(e.file(), "bad.yaml");
  EXPECT_GE(e.line(), 2);
  EXPECT_TRUE(has(e, "not valid YAML")) << e.what();
}

TEST(YamlReader, UnanticipatedShapesBecomeInputErrors) {
  const YAML::Node root = parse_yaml("a: [1, 2]\n", "shape.yaml");
  const InputError e =
      error_of([&] { read_yaml_guarded("shape.yaml", [&] { return root["a"].as<double>(); }); });
  EXPECT_EQ(e.file(), "shape.yaml");
  EXPECT_EQ(e.line(), 1);
  EXPECT_TRUE(has(e, "unexpected YAML structure")) << e.what();
  EXPECT_EQ(read_yaml_guarded("shape.yaml", [&] { return root["a"][1].as<int>(); }), 2);
}

TEST(YamlReader, FilesThatCannotBeReadAreNamed) {
  const std::string missing = testing::TempDir() + "/echoplan_no_such_file.yaml";
  InputError e = error_of([&] { load_yaml_file(missing, "sim config"); });
  EXPECT_EQ(e.file(), missing);
  EXPECT_TRUE(has(e, "cannot open the sim config")) << e.what();

  e = error_of([] { load_yaml_file(testing::TempDir(), "sim config"); });
  EXPECT_TRUE(has(e, "not a regular file")) << e.what();

  const std::string path = testing::TempDir() + "/echoplan_yaml_reader_test.yaml";
  std::ofstream(path) << "x: 1\n";
  EXPECT_EQ(load_yaml_file(path, "test file")["x"].as<int>(), 1);
  std::remove(path.c_str());
}

// "Billion laughs": ten levels of ten aliases each stand for 10^10 nodes from a dozen lines; the
// reader refuses the document at the line where the count passes the limit, without expanding it.
TEST(YamlReader, AliasesThatExpandPastTheLimitAreRefused) {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string below = "*l" + std::to_string(level - 1);
    text += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", " : "") + below;
    text += "]\n";
  }
  const InputError e = error_of([&] { parse_yaml(text, "laughs.yaml"); });
  EXPECT_EQ(e.file(), "laughs.yaml");
  // Level 6 stands for 10^7 nodes: its aliases pass 2,000,000 on line 7.
  EXPECT_EQ(e.line(), 7);
  EXPECT_TRUE(has(e, "aliases expanded")) << e.what();

  // Anchors and aliases within the limit are ordinary YAML: three levels stand for about 1,100.
  const std::size_t third = [&] {
    std::size_t at = 0;
    for (int line = 0; line < 3; ++line) at = text.find('\n', at) + 1;
    return at;
  }();
  const YAML::Node root = parse_yaml(text.substr(0, third), "small.yaml");
  EXPECT_EQ(root["l2"].size(), 10u);
  EXPECT_EQ(root["l2"][3][4][5].as<std::string>(), "x");
}

// An alias inside its own anchor's node is a cycle in yaml-cpp's node graph: walking it (as
// reject_duplicate_keys does) overflowed the stack (found by fuzz/experiment_files_fuzz).
TEST(YamlReader, AnAliasInsideItsOwnAnchorIsRefused) {
  for (const char* text : {"a: &x [1, *x]\n", "a: &x {b: {c: *x}}\n"}) {
    const InputError e = error_of([&] { parse_yaml(text, "cycle.yaml"); });
    EXPECT_EQ(e.file(), "cycle.yaml");
    EXPECT_EQ(e.line(), 1);
    EXPECT_TRUE(has(e, "a cycle")) << text << ": " << e.what();
  }
  // An alias after its anchor's node has closed is ordinary YAML.
  EXPECT_EQ(parse_yaml("a: &x [1]\nb: [*x, *x]\n", "ok.yaml")["b"][1][0].as<int>(), 1);
}

// yaml-cpp 0.7 reads a lone ',' as an endless stream of empty documents: reading them all took 2
// million documents (5 s under the fuzzer's sanitizers) before the node limit stopped it. A file is
// one document, so the reader stops at the second (found by fuzz/experiment_files_fuzz).
TEST(YamlReader, ASecondDocumentIsRefused) {
  for (const char* text : {",", " , x", "a: 1\n---\nb: 2\n"}) {
    const InputError e = error_of([&] { parse_yaml(text, "two.yaml"); });
    EXPECT_EQ(e.file(), "two.yaml");
    EXPECT_TRUE(has(e, "more than one document")) << text << ": " << e.what();
  }
  EXPECT_EQ(parse_yaml("---\na: 1\n", "one.yaml")["a"].as<int>(), 1);
  EXPECT_EQ(parse_yaml("a: 1\n...\n", "one.yaml")["a"].as<int>(), 1);
}

// A file over kMaxInputFileBytes is refused before it is read (a sparse file: no disk is used).
TEST(YamlReader, AFileOverTheSizeLimitIsRefusedUnread) {
  const std::string path = testing::TempDir() + "/echoplan_huge_input.yaml";
  std::ofstream(path) << "x: 1\n";
  std::filesystem::resize_file(path, kMaxInputFileBytes + 1);
  const InputError e = error_of([&] { load_yaml_file(path, "problem file"); });
  EXPECT_EQ(e.file(), path);
  EXPECT_TRUE(has(e, "at most 512 MiB")) << e.what();
  std::remove(path.c_str());
}

TEST(YamlMapping, ReadsFieldsAndNamesThemEntryDotKey) {
  const std::string text =
      "objects:\n"                 // line 1
      "  mug:\n"                   // line 2
      "    radius: 0.04\n"         // line 3
      "    closed: yes\n"          // line 4
      "    position: [1, 2, 3]\n"  // line 5
      "    mass: -1\n";            // line 6
  const YAML::Node root = parse_yaml(text, "cat.yaml");
  const YamlReader r("cat.yaml");
  const YamlMapping mug(r, "objects.mug", root["objects"]["mug"]);
  EXPECT_DOUBLE_EQ(mug.number("radius", NumberRange::above(0)), 0.04);
  EXPECT_DOUBLE_EQ(mug.number_or("friction", 0.4), 0.4);
  EXPECT_TRUE(mug.boolean_or("closed", false));
  EXPECT_FALSE(mug.boolean_or("hollow", false));
  EXPECT_EQ(mug.numbers("position", 3), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(mug.has("mass"));
  EXPECT_FALSE(mug.has("material"));

  InputError e = error_of([&] { mug.number("mass", NumberRange::above(0)); });
  EXPECT_EQ(e.line(), 6);
  EXPECT_TRUE(has(e, "objects.mug.mass must be > 0, got -1")) << e.what();
  e = error_of([&] { mug.name("material"); });
  EXPECT_EQ(e.line(), 3);  // a missing key points at the mapping, which starts at its first key
  EXPECT_TRUE(has(e, "missing key 'material' in objects.mug")) << e.what();
  e = error_of([&] { mug.only_keys({"radius", "closed", "position"}); });
  EXPECT_EQ(e.line(), 6);
  EXPECT_TRUE(has(e, "unknown key 'mass' in objects.mug")) << e.what();
  e = error_of([&] { mug.fail(mug.node()["closed"], "unknown shape 'cube'"); });
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.problem(), "objects.mug: unknown shape 'cube'");
  e = error_of([&] { mug.fail(mug.node()["nothing"], "no material"); });
  EXPECT_EQ(e.line(), 3);
  e = error_of([&] { YamlMapping(r, "objects.mug.radius", root["objects"]["mug"]["radius"]); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_TRUE(has(e, "objects.mug.radius must be a mapping")) << e.what();
}

TEST(NumberRange, DescribesAndContainsItsBounds) {
  EXPECT_EQ(NumberRange::open(0, 1).describe(), "in (0, 1)");
  EXPECT_EQ(NumberRange::closed(0, 1).describe(), "in [0, 1]");
  EXPECT_EQ(NumberRange::above(0).describe(), "> 0");
  EXPECT_EQ(NumberRange::at_least(0).below(0.5).describe(), ">= 0 and < 0.5");
  EXPECT_EQ(NumberRange{}.describe(), "finite");
  EXPECT_FALSE(NumberRange::above(0).contains(0));
  EXPECT_TRUE(NumberRange::at_least(0).contains(0));
  EXPECT_FALSE(NumberRange::at_least(0).below(0.5).contains(0.5));
  EXPECT_TRUE(NumberRange::closed(0, 1).contains(1));
}

}  // namespace
}  // namespace echoplan
