#include "solvers/offline/policy_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/file_io.h"
#include "common/json_parse.h"

namespace echoplan::solvers::offline {

namespace {

constexpr const char* kFormat = "echoplan-alpha-vectors";
constexpr int kVersion = 1;

// 1-based line of byte offset `byte` in `text` (nlohmann reports offsets, users think in lines).
int line_of(const std::string& text, std::size_t byte) {
  const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(byte, text.size()));
  return 1 + static_cast<int>(std::count(text.begin(), end, '\n'));
}

const nlohmann::json& require(const std::string& path, const nlohmann::json& object,
                              const std::string& key) {
  if (!object.is_object() || !object.contains(key)) {
    throw InputError(path, 0, fmt::format("missing key \"{}\"", key));
  }
  return object.at(key);
}

int require_int(const std::string& path, const nlohmann::json& object, const std::string& key) {
  const nlohmann::json& v = require(path, object, key);
  // Also rejects integers beyond int, which get<int>() would wrap into a plausible count.
  if (!v.is_number_integer() || v.get<long long>() < std::numeric_limits<int>::min() ||
      v.get<long long>() > std::numeric_limits<int>::max()) {
    throw InputError(path, 0, fmt::format("\"{}\" must be an integer", key));
  }
  return v.get<int>();
}

}  // namespace

void save_policy(const PointBasedSolver& solver, const std::string& path) {
  const SolverProgress p = solver.progress();
  nlohmann::json out;
  out["format"] = kFormat;
  out["version"] = kVersion;
  out["num_states"] = solver.pomdp().num_states;
  out["num_actions"] = solver.pomdp().num_actions;
  out["discount"] = solver.pomdp().discount;
  out["lower"] = p.root.lower;
  out["upper"] = p.root.upper;
  nlohmann::json vectors = nlohmann::json::array();
  for (const AlphaVector& v : solver.lower_bound().vectors()) {
    vectors.push_back({{"action", v.action}, {"values", v.values}});
  }
  out["vectors"] = std::move(vectors);
  std::ofstream file(path);
  file << out.dump(1) << '\n';
  if (!file) throw InputError(path, 0, "cannot write the policy file");
}

AlphaVectorSet load_policy(const std::string& path, const FlatPomdp& pomdp) {
  return parse_policy(read_text_file(path, "policy file"), path, pomdp);
}

AlphaVectorSet parse_policy(const std::string& text, const std::string& path,
                            const FlatPomdp& pomdp) {
  nlohmann::json root;
  try {
    root = parse_json(text, path);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path, line_of(text, e.byte), "not valid JSON");
  } catch (const nlohmann::json::exception&) {
    // out_of_range: a number beyond a double's range.
    throw InputError(path, 0, "a number is out of range");
  }
  const nlohmann::json& format = require(path, root, "format");
  if (!format.is_string() || format.get<std::string>() != kFormat) {
    throw InputError(path, 0, fmt::format("\"format\" must be \"{}\"", kFormat));
  }
  if (require_int(path, root, "version") != kVersion) {
    throw InputError(path, 0,
                     fmt::format("unsupported version (this echoplan reads {})", kVersion));
  }
  const int states = require_int(path, root, "num_states");
  const int actions = require_int(path, root, "num_actions");
  if (states != pomdp.num_states || actions != pomdp.num_actions) {
    throw InputError(
        path, 0,
        fmt::format("the policy is for {} states and {} actions, the problem has {} and "
                    "{}: solve this problem again",
                    states, actions, pomdp.num_states, pomdp.num_actions));
  }
  // Alpha vectors are values under one discount: acting on them under another would rank the
  // actions by the wrong horizon without any sign of it.
  const nlohmann::json& discount = require(path, root, "discount");
  if (!discount.is_number()) throw InputError(path, 0, "\"discount\" must be a number");
  if (std::abs(discount.get<double>() - pomdp.discount) > 1e-12) {
    throw InputError(path, 0,
                     fmt::format("the policy was solved at discount {}, the problem has {}: "
                                 "solve this problem again",
                                 discount.get<double>(), pomdp.discount));
  }
  const nlohmann::json& vectors = require(path, root, "vectors");
  if (!vectors.is_array() || vectors.empty()) {
    throw InputError(path, 0, "\"vectors\" must be a non-empty array");
  }
  AlphaVectorSet set;
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    const std::string where = fmt::format("vectors[{}]", i);
    const nlohmann::json& entry = vectors[i];
    if (!entry.is_object()) throw InputError(path, 0, where + " must be an object");
    const int action = require_int(path, entry, "action");
    if (action < 0 || action >= actions) {
      throw InputError(path, 0,
                       fmt::format("{}.action {} is not in [0, {})", where, action, actions));
    }
    const nlohmann::json& values = require(path, entry, "values");
    if (!values.is_array() || static_cast<int>(values.size()) != states) {
      throw InputError(path, 0,
                       fmt::format("{}.values must be an array of {} numbers", where, states));
    }
    AlphaVector v{action, {}};
    for (const nlohmann::json& x : values) {
      if (!x.is_number()) throw InputError(path, 0, where + ".values holds a non-number");
      v.values.push_back(x.get<double>());
    }
    set.add(std::move(v));
  }
  return set;
}

}  // namespace echoplan::solvers::offline
