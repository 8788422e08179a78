// No input crashes: thousands of random corruptions of the shipped problem files either load or
// fail with an InputError (never another exception; the sanitizer build catches memory errors).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "common/error.h"
#include "pomdp/cassandra_reader.h"
#include "pomdp/problem.h"
#include "test_paths.h"

namespace echoplan::pomdp {
namespace {

using testing::repo_file;
using testing::repo_text;

// One random edit: delete a span, duplicate a span, overwrite a byte, or truncate.
std::string corrupt(std::string text, Rng& rng) {
  const auto pick = [&](std::size_t n) {
    return static_cast<std::size_t>(uniform01(rng) * static_cast<double>(n));
  };
  const std::size_t at = pick(text.size());
  const std::size_t len = 1 + pick(40);
  switch (pick(4)) {
    case 0:
      text.erase(at, len);
      break;
    case 1:
      text.insert(at, text.substr(at, len));
      break;
    case 2:
      text[at] = static_cast<char>(pick(256));
      break;
    default:
      text.resize(at);
      break;
  }
  return text;
}

template <class Parse>
void expect_corruptions_rejected_as_input_errors(const std::string& file, Parse parse,
                                                 std::uint64_t seed) {
  const std::string original = repo_text(file);
  Rng rng(seed);
  int rejected = 0;
  for (int i = 0; i < 2000; ++i) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(uniform01(rng) * 3);
    for (int e = 0; e < edits; ++e) text = corrupt(text, rng);
    try {
      parse(text);
    } catch (const InputError& err) {
      ++rejected;
      EXPECT_GE(err.line(), 0);
    } catch (const std::exception& other) {
      ADD_FAILURE() << file << " corruption " << i << " threw a non-input error: " << other.what()
                    << "\n"
                    << text;
      return;
    }
  }
  // Most corruptions must be caught: a loader that accepts everything would pass the loop above.
  EXPECT_GT(rejected, 1000) << file;
}

TEST(MalformedInput, YamlCorruptionsAreInputErrors) {
  expect_corruptions_rejected_as_input_errors(
      "problems/audio_objects.yaml",
      [](const std::string& t) { parse_problem_yaml(t, "fuzz.yaml"); }, 1);
}

TEST(MalformedInput, PomdpCorruptionsAreInputErrors) {
  for (const char* file : {"problems/tiger.pomdp", "problems/audio_objects.pomdp"}) {
    expect_corruptions_rejected_as_input_errors(
        file, [](const std::string& t) { parse_cassandra_pomdp(t, "fuzz.pomdp"); }, 2);
  }
}

}  // namespace
}  // namespace echoplan::pomdp
