#include "experiment/oppt_log.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/rng.h"
#include "pomdp/exact_belief.h"

namespace echoplan::experiment {

namespace {

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

bool starts(const std::vector<std::string>& tokens, std::initializer_list<const char*> words) {
  if (tokens.size() < words.size()) return false;
  std::size_t i = 0;
  for (const char* word : words)
    if (tokens[i++] != word) return false;
  return true;
}

// A step's fields as they are read; complete() says which one is missing.
struct PendingStep {
  OpptStep step;
  bool has_state = false, has_action = false, has_observation = false, has_reward = false;
};

// Reads a log line by line: a small state machine over runs, steps and BEGIN/END blocks.
class OpptLogParser {
 public:
  explicit OpptLogParser(std::string file) : file_(std::move(file)) {}

  std::vector<OpptRun> parse(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      ++line_;
      read_line(tokens_of(line));
    }
    if (block_ != Block::none)
      fail(fmt::format("{} at line {} has no {} (truncated log?)", block_begin_, block_line_,
                       block_end_));
    close_run();
    if (runs_.empty()) fail("no 'Run #' in the log: not an OPPT run log?");
    return std::move(runs_);
  }

 private:
  enum class Block { none, particles, skipped };

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(file_, line_, problem);
  }

  double number(const std::string& token, const char* what) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
      fail(fmt::format("{} '{}' is not a number", what, token));
    return value;
  }

  int integer(const std::string& token, const char* what) const {
    int value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      fail(fmt::format("{} '{}' is not an integer", what, token));
    return value;
  }

  // "KEY: <code> END" -> code.
  int code_field(const std::vector<std::string>& t, const char* what) const {
    if (t.size() < 2) fail(fmt::format("'{}' has no code", t[0]));
    if (t.size() < 3 || t[2] != "END") fail(fmt::format("'{}' has no END after its code", t[0]));
    return integer(t[1], what);
  }

  // "S: x1 ... xn <object> w: <weight> END ..." (and the same for "p:") -> the object.
  int object_of_state(const std::vector<std::string>& t) const {
    std::size_t w = 1;
    while (w < t.size() && t[w] != "w:") ++w;
    if (w == t.size()) fail(fmt::format("'{}' line has no 'w:' after the state", t[0]));
    if (w == 1) fail(fmt::format("'{}' line has no state numbers", t[0]));
    if (w + 2 >= t.size() || t[w + 2] != "END")
      fail(fmt::format("'{}' line has no END after its weight", t[0]));
    for (std::size_t i = 1; i + 1 < w; ++i) number(t[i], "state value");
    number(t[w + 1], "weight");
    return integer(t[w - 1], "object (the state's last number)");
  }

  PendingStep& step_for(const std::string& key) {
    if (!step_) fail(fmt::format("'{}' outside a step (no 't = ' before it)", key));
    return *step_;
  }

  void read_line(const std::vector<std::string>& t) {
    if (t.empty()) return;
    if (block_ == Block::particles) return read_particle_line(t);
    if (block_ == Block::skipped) return read_skipped_line(t);
    if (t[0] == "Run" && t.size() == 2 && t[1].starts_with("#")) return start_run(t[1]);
    if (starts(t, {"t", "="})) return start_step(t);
    if (read_step_field(t)) return;
    if (starts(t, {"PARTICLES", "BEGIN"})) {
      PendingStep& s = step_for("PARTICLES BEGIN");
      s.step.particles_after.emplace();
      s.step.particles_line = line_;
      return open_block(Block::particles, "PARTICLES BEGIN", "PARTICLES END");
    }
    if (t[0] == "SOLVER_DATA_BEGIN") return open_block(Block::skipped, t[0], "SOLVER_DATA_END");
    if (t[0] == "FINAL_STATE_BEGIN") return open_block(Block::skipped, t[0], "FINAL_STATE_END");
    if (starts(t, {"Total", "discounted", "reward:"})) return end_run(t);
    if (starts(t, {"Num", "steps:"})) {
      if (!run_ || !run_ended_) fail("'Num steps:' before the run's 'Total discounted reward'");
      if (t.size() != 3) fail("'Num steps:' needs one count");
      run_->num_steps = integer(t[2], "Num steps");
      num_steps_line_ = line_;
    }
    // Anything else (the file's header, "Run successful", timings, means) is not needed.
  }

  // S:, A:, O: and the reward lines of the open step; false for any other line.
  bool read_step_field(const std::vector<std::string>& t) {
    const std::string& key = t[0];
    if (key == "S:") {
      step_for(key).step.true_object = object_of_state(t);
      step_->has_state = true;
    } else if (key == "A:") {
      step_for(key).step.action = code_field(t, "action code");
      step_->has_action = true;
    } else if (key == "O:") {
      step_for(key).step.observation = code_field(t, "observation code");
      step_->has_observation = true;
    } else if (key == "IMMEDIATE_REWARD:" || key == "DISCOUNT_FACTOR:" ||
               key == "DISCOUNTED_REWARD:") {
      PendingStep& s = step_for(key);
      if (t.size() != 2) fail(fmt::format("'{}' needs one number", key));
      const double value = number(t[1], key.c_str());
      if (key == "IMMEDIATE_REWARD:") {
        s.step.immediate_reward = value;
        s.has_reward = true;
      } else if (key == "DISCOUNT_FACTOR:") {
        s.step.discount_factor = value;
      } else {
        s.step.discounted_reward = value;
      }
    } else {
      return false;
    }
    return true;
  }

  void read_particle_line(const std::vector<std::string>& t) {
    if (starts(t, {"PARTICLES", "END"})) {
      block_ = Block::none;
    } else if (t[0] == "p:") {
      ++(*step_->step.particles_after)[object_of_state(t)];
    } else {
      fail(fmt::format("'{}' inside the particles block of line {} (no PARTICLES END?)", t[0],
                       block_line_));
    }
  }

  void read_skipped_line(const std::vector<std::string>& t) {
    if (t[0] == block_end_) {
      block_ = Block::none;
    } else if ((t[0] == "Run" && t.size() == 2) || starts(t, {"t", "="})) {
      fail(fmt::format("{} at line {} has no {}", block_begin_, block_line_, block_end_));
    } else if (starts(t, {"NUM", "HISTORIES:"}) && step_) {
      if (t.size() != 3) fail("'NUM HISTORIES:' needs one count");
      step_->step.histories = integer(t[2], "NUM HISTORIES");
    }
  }

  void open_block(Block block, const std::string& begin, const char* end) {
    block_ = block;
    block_begin_ = begin;
    block_end_ = end;
    block_line_ = line_;
  }

  void start_run(const std::string& number_token) {
    close_run();
    run_.emplace();
    run_->number = integer(number_token.substr(1), "run number");
    run_->line = line_;
    run_ended_ = false;
  }

  void start_step(const std::vector<std::string>& t) {
    if (!run_) fail("a step before any 'Run #'");
    if (run_ended_) fail("a step after the run's 'Total discounted reward'");
    if (t.size() != 3) fail("'t = ' needs one step number");
    close_step();
    step_.emplace();
    step_->step.t = integer(t[2], "step number");
    step_->step.line = line_;
  }

  void end_run(const std::vector<std::string>& t) {
    if (!run_) fail("'Total discounted reward:' before any 'Run #'");
    if (run_ended_) fail("a second 'Total discounted reward:' in one run");
    if (t.size() != 4) fail("'Total discounted reward:' needs one number");
    close_step();
    run_->total_discounted_reward = number(t[3], "total discounted reward");
    run_ended_ = true;
  }

  // Checks the open step and adds it to the run, dropping the repeated last step.
  void close_step() {
    if (!step_) return;
    PendingStep s = std::move(*step_);
    step_.reset();
    const auto missing = [&](const char* key) {
      throw InputError(file_, s.step.line,
                       fmt::format("step t = {} has no '{}' line", s.step.t, key));
    };
    if (!s.has_state) missing("S:");
    if (!s.has_action) missing("A:");
    if (!s.has_observation) missing("O:");
    if (!s.has_reward) missing("IMMEDIATE_REWARD:");
    std::vector<OpptStep>& steps = run_->steps;
    // OPPT writes a run's last step a second time, unchanged, before its final state (reference
    // "original-robot-runs.md", "The OPPT run-log format"): the copy is dropped once.
    if (!steps.empty() && steps.back().t == s.step.t) {
      const OpptStep& first = steps.back();
      if (first.action != s.step.action || first.observation != s.step.observation ||
          first.true_object != s.step.true_object ||
          first.immediate_reward != s.step.immediate_reward)
        throw InputError(file_, s.step.line,
                         fmt::format("step t = {} is repeated with other contents than at line {}",
                                     s.step.t, first.line));
      return;
    }
    if (s.step.t != static_cast<int>(steps.size()))
      throw InputError(
          file_, s.step.line,
          fmt::format("step t = {} where t = {} was expected", s.step.t, steps.size()));
    steps.push_back(std::move(s.step));
  }

  void close_run() {
    if (!run_) return;
    if (!run_ended_)
      fail(fmt::format("run #{} (line {}) ends without 'Total discounted reward:' (truncated run?)",
                       run_->number, run_->line));
    if (run_->steps.empty())
      throw InputError(file_, run_->line, fmt::format("run #{} has no steps", run_->number));
    if (run_->num_steps && *run_->num_steps != static_cast<int>(run_->steps.size()))
      throw InputError(file_, num_steps_line_,
                       fmt::format("'Num steps: {}' but run #{} has {} steps", *run_->num_steps,
                                   run_->number, run_->steps.size()));
    runs_.push_back(std::move(*run_));
    run_.reset();
  }

  std::string file_;
  int line_ = 0;
  Block block_ = Block::none;
  std::string block_begin_, block_end_;
  int block_line_ = 0;
  std::optional<OpptRun> run_;
  bool run_ended_ = false;  // its "Total discounted reward:" was read
  int num_steps_line_ = 0;
  std::optional<PendingStep> step_;
  std::vector<OpptRun> runs_;
};

int mapped(const std::map<int, int>& codes, int code, const char* what, const char* flag,
           const std::string& file, int line) {
  const auto it = codes.find(code);
  if (it == codes.end())
    throw InputError(file, line, fmt::format("{} code {} has no {} mapping", what, code, flag));
  return it->second;
}

std::vector<double> particle_belief(const std::map<int, int>& counts, const OpptCodes& codes,
                                    std::size_t num_objects, int scale, const std::string& file,
                                    int line) {
  std::vector<double> belief(num_objects, 0.0);
  for (const auto& [code, count] : counts)
    belief[mapped(codes.objects, code, "particle object", "--objects", file, line)] +=
        static_cast<double>(count) / scale;
  return belief;
}

}  // namespace

std::vector<OpptRun> parse_oppt_log(const std::string& text, const std::string& file) {
  return OpptLogParser(file).parse(text);
}

std::map<int, int> parse_code_mapping(const std::string& text,
                                      const std::vector<std::string>& names,
                                      const std::string& flag) {
  std::map<int, int> codes;
  std::istringstream in(text);
  for (std::string pair; std::getline(in, pair, ',');) {
    const std::size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size())
      throw InputError(fmt::format("{}: '{}' is not CODE=NAME", flag, pair));
    const std::string code_text = pair.substr(0, eq), name = pair.substr(eq + 1);
    int code = 0;
    const auto [end, error] =
        std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (error != std::errc() || end != code_text.data() + code_text.size())
      throw InputError(fmt::format("{}: code '{}' is not an integer", flag, code_text));
    int index = -1;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) index = static_cast<int>(i);
    if (index < 0)
      throw InputError(fmt::format("{}: '{}' is not one of the problem's names ({})", flag, name,
                                   fmt::join(names, ", ")));
    if (!codes.emplace(code, index).second)
      throw InputError(fmt::format("{}: code {} is mapped twice", flag, code));
  }
  if (codes.empty()) throw InputError(fmt::format("{}: no CODE=NAME pairs", flag));
  return codes;
}

TrialResult oppt_run_records(const OpptRun& run, const OpptCodes& codes,
                             const pomdp::Problem& problem, int trial, const std::string& file,
                             BeliefSources& sources) {
  const pomdp::ModelSpec& spec = problem.model->spec();
  const int scale = problem.belief.particles;
  const std::size_t num_objects = spec.state.discrete_value_names.at(0).size();
  pomdp::ExactBelief exact(problem.model);
  Rng unused_rng(0);  // the exact update draws nothing
  TrialResult result;
  TrialRecord& record = result.record;
  record.trial = trial;
  record.steps = static_cast<int>(run.steps.size());
  record.action_counts.assign(spec.action_names.size(), 0);
  double discount = 1.0;
  for (std::size_t i = 0; i < run.steps.size(); ++i) {
    const OpptStep& logged = run.steps[i];
    StepRecord step;
    step.trial = trial;
    step.step = static_cast<int>(i);
    step.action = mapped(codes.actions, logged.action, "action", "--actions", file, logged.line);
    step.observation.index = mapped(codes.observations, logged.observation, "observation",
                                    "--observations", file, logged.line);
    const OpptStep* before = i > 0 ? &run.steps[i - 1] : nullptr;
    if (before == nullptr) {
      step.belief = exact.discrete_marginal(0);
      ++sources.initial;
    } else if (before->particles_after && !before->particles_after->empty()) {
      step.belief = particle_belief(*before->particles_after, codes, num_objects, scale, file,
                                    before->particles_line);
      ++sources.particles;
    } else {
      step.belief = exact.discrete_marginal(0);
      ++sources.exact;
    }
    exact.update(step.action, step.observation, unused_rng);
    step.reward = logged.immediate_reward;
    step.episodes = logged.histories;
    record.discounted_reward += discount * step.reward;
    discount *= spec.discount;
    ++record.action_counts[step.action];
    result.steps.push_back(std::move(step));
  }
  record.true_state = mapped(codes.objects, run.steps.front().true_object, "object (S:)",
                             "--objects", file, run.steps.front().line);
  const std::vector<double>& last = result.steps.back().belief;
  for (std::size_t s = 0; s < last.size(); ++s)
    if (last[s] > last[record.believed_state]) record.believed_state = static_cast<int>(s);
  return result;
}

}  // namespace echoplan::experiment
