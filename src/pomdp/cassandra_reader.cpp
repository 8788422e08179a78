#include "pomdp/cassandra_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "pomdp/distribution.h"

namespace echoplan::pomdp {

namespace {

struct Token {
  std::string text;
  int line;
};

// Splits the text into words and ':' tokens, dropping '#' comments, remembering each token's line.
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> out;
  int line = 1;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) out.push_back({word, line});
    word.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '#') {
      flush();
      while (i < text.size() && text[i] != '\n') ++i;
      --i;
    } else if (c == '\n') {
      flush();
      ++line;
    } else if (c == ':') {
      flush();
      out.push_back({":", line});
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      flush();
    } else {
      word += c;
    }
  }
  flush();
  return out;
}

bool is_keyword(const std::string& t) {
  static const std::set<std::string> keywords = {
      "discount", "values", "states", "actions", "observations", "start", "T", "O", "R"};
  return keywords.count(t) > 0;
}

bool parse_number(const std::string& t, double& value) {
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && errno == 0 && std::isfinite(value);
}

bool parse_index(const std::string& t, int& value) {
  if (t.empty() || t.size() > 9) return false;
  for (char c : t) {
    if (c < '0' || c > '9') return false;
  }
  value = std::stoi(t);
  return true;
}

class Parser {
 public:
  Parser(const std::string& text, std::string file)
      : tokens_(tokenize(text)), file_(std::move(file)) {}

  std::shared_ptr<const TabularPomdp> parse();

 private:
  struct RewardEntry {
    int a, s, s_next, o;  // -1 = any
    double value;
  };
  // Which (action, state) rows of T and O were last set on which line (0: never).
  std::vector<int> t_row_line_, o_row_line_;

  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw InputError(file_, line, problem);
  }
  int line() const { return pos_ < tokens_.size() ? tokens_[pos_].line : last_line(); }
  int last_line() const { return tokens_.empty() ? 1 : tokens_.back().line; }
  bool at_end() const { return pos_ >= tokens_.size(); }
  const Token& next() {
    if (at_end()) fail(last_line(), "unexpected end of file");
    return tokens_[pos_++];
  }
  void expect_colon(const std::string& after) {
    if (at_end() || tokens_[pos_].text != ":") fail(line(), "expected ':' after '" + after + "'");
    ++pos_;
  }
  // Tokens up to the next keyword (the values of the current statement).
  std::vector<Token> rest_of_statement() {
    std::vector<Token> out;
    while (!at_end() && !is_keyword(tokens_[pos_].text)) out.push_back(tokens_[pos_++]);
    return out;
  }

  // One statement, from its keyword to the next keyword.
  void read_statement(const Token& keyword);
  void read_discount(const Token& keyword);
  void read_values(const Token& keyword);
  // A states:, actions: or observations: statement; once all three are known, sizes the tables.
  void read_name_list(const Token& keyword);
  void allocate_tables(const Token& keyword);
  void read_names(const std::string& what, std::vector<std::string>& names, int prefix);
  void read_start(const Token& keyword);
  // A T: or O: statement: fills `table` [(a * S + row) * columns + column] (columns: states for T,
  // observations for O) in the single-entry, row or matrix form, or with uniform / identity.
  void read_probabilities(const Token& keyword, const std::vector<std::string>& column_names,
                          const std::string& column_kind, bool allow_identity,
                          std::vector<double>& table, std::vector<int>& row_line);
  void read_reward(const Token& keyword);
  // Fields "x : y : z" after a T/O/R keyword, each resolved against its kind's names; -1 for '*'.
  std::vector<Token> fields(int max_fields);
  int resolve(const Token& t, const std::vector<std::string>& names, const std::string& kind) const;
  std::vector<double> numbers(const std::vector<Token>& values, std::size_t count,
                              const Token& keyword);
  void require_sizes(const Token& keyword) const;
  // After the last statement: every header line given, every row of T and O a distribution.
  void check_complete() const;
  void check_rows(const std::vector<double>& table, int width, const std::vector<int>& row_line,
                  const char* kind) const;
  // R(s, a) (states x actions), the expectation of the R: entries over s' and o.
  std::vector<double> expected_rewards() const;

  std::vector<Token> tokens_;
  std::string file_;
  std::size_t pos_ = 0;

  double discount_ = -1.0;
  bool cost_ = false;
  std::vector<std::string> states_, actions_, observations_;
  std::vector<double> start_;
  std::vector<double> t_, o_;
  std::vector<RewardEntry> rewards_;
};

void Parser::read_names(const std::string& what, std::vector<std::string>& names, int prefix) {
  const int at = line();
  std::vector<Token> values = rest_of_statement();
  if (!names.empty()) fail(at, "'" + what + "' given twice");
  if (values.empty()) fail(at, "'" + what + ":' needs a count or a list of names");
  int count = 0;
  if (values.size() == 1 && parse_index(values[0].text, count)) {
    if (count <= 0) fail(at, "'" + what + ":' count must be a positive whole number");
    for (int i = 0; i < count; ++i)
      names.push_back(std::string(1, static_cast<char>(prefix)) + std::to_string(i));
    return;
  }
  double number = 0.0;
  if (values.size() == 1 && parse_number(values[0].text, number)) {
    fail(at, "'" + what + ":' count must be a positive whole number, got " + values[0].text);
  }
  std::set<std::string> seen;
  for (const auto& v : values) {
    if (v.text == ":" || v.text == "*")
      fail(v.line, "unexpected '" + v.text + "' in the list of " + what);
    if (!seen.insert(v.text).second) fail(v.line, "duplicate name '" + v.text + "' in " + what);
    names.push_back(v.text);
  }
}

void Parser::require_sizes(const Token& keyword) const {
  if (states_.empty() || actions_.empty() || observations_.empty()) {
    fail(keyword.line,
         "'" + keyword.text + "' before 'states:', 'actions:' and 'observations:' are all given");
  }
}

int Parser::resolve(const Token& t, const std::vector<std::string>& names,
                    const std::string& kind) const {
  if (t.text == "*") return -1;
  int index = 0;
  if (parse_index(t.text, index)) {
    if (index >= static_cast<int>(names.size())) {
      fail(t.line, kind + " index " + t.text + " out of range (there are " +
                       std::to_string(names.size()) + ")");
    }
    return index;
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == t.text) return static_cast<int>(i);
  }
  fail(t.line, "unknown " + kind + " '" + t.text + "'");
}

std::vector<Token> Parser::fields(int max_fields) {
  std::vector<Token> out;
  while (static_cast<int>(out.size()) < max_fields && !at_end() && tokens_[pos_].text == ":") {
    ++pos_;
    const Token& t = next();
    if (t.text == ":" || is_keyword(t.text))
      fail(t.line, "expected a name, index or '*' after ':'");
    out.push_back(t);
  }
  return out;
}

std::vector<double> Parser::numbers(const std::vector<Token>& values, std::size_t count,
                                    const Token& keyword) {
  if (values.size() != count) {
    fail(values.empty() ? keyword.line : values.front().line,
         "'" + keyword.text + ":' expects " + std::to_string(count) + " number(s) here, found " +
             std::to_string(values.size()));
  }
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (!parse_number(values[i].text, out[i]))
      fail(values[i].line, "expected a number, got '" + values[i].text + "'");
  }
  return out;
}

void Parser::read_start(const Token& keyword) {
  require_sizes(keyword);
  const int n = static_cast<int>(states_.size());
  std::string form;
  if (!at_end() && (tokens_[pos_].text == "include" || tokens_[pos_].text == "exclude"))
    form = next().text;
  expect_colon("start");
  std::vector<Token> values = rest_of_statement();
  if (values.empty()) fail(keyword.line, "'start:' needs a distribution, 'uniform' or a state");
  start_.assign(n, 0.0);
  // resolve() reads '*' as every state (-1), which no form of 'start:' means (found by
  // fuzz/problem_file_fuzz: it indexed state -1).
  auto state = [&](const Token& t) {
    const int s = resolve(t, states_, "state");
    if (s < 0) fail(t.line, "'start:' names states, not '*' (use 'start: uniform')");
    return s;
  };
  if (!form.empty()) {
    std::vector<bool> listed(n, false);
    for (const auto& v : values) listed[state(v)] = true;
    int count = 0;
    for (int s = 0; s < n; ++s) count += (listed[s] == (form == "include")) ? 1 : 0;
    if (count == 0) fail(keyword.line, "'start " + form + ":' leaves no state to start in");
    for (int s = 0; s < n; ++s) start_[s] = (listed[s] == (form == "include")) ? 1.0 / count : 0.0;
    return;
  }
  if (values.size() == 1 && values[0].text == "uniform") {
    start_.assign(n, 1.0 / n);
    return;
  }
  double dummy = 0.0;
  if (values.size() == 1 && (n > 1 || !parse_number(values[0].text, dummy))) {
    start_[state(values[0])] = 1.0;
    return;
  }
  start_ = numbers(values, n, keyword);
  const RowCheck check = check_row(start_.data(), start_.size());
  if (!check.in_range) fail(keyword.line, "'start:' has a probability outside [0, 1]");
  if (!check.ok()) {
    fail(keyword.line,
         "'start:' distribution sums to " + std::to_string(check.sum) + ", not 1 (tolerance 1e-6)");
  }
}

void Parser::read_probabilities(const Token& keyword, const std::vector<std::string>& column_names,
                                const std::string& column_kind, bool allow_identity,
                                std::vector<double>& table, std::vector<int>& row_line) {
  require_sizes(keyword);
  const int ns = static_cast<int>(states_.size()), nc = static_cast<int>(column_names.size());
  const std::vector<Token> f = fields(3);
  if (f.empty()) fail(keyword.line, "'" + keyword.text + "' needs ': action' after it");
  const int a = resolve(f[0], actions_, "action");
  const int row = f.size() > 1 ? resolve(f[1], states_, "state") : -1;
  const int column = f.size() > 2 ? resolve(f[2], column_names, column_kind) : -1;
  const std::vector<Token> values = rest_of_statement();
  const bool uniform = values.size() == 1 && values[0].text == "uniform";
  const bool identity = values.size() == 1 && values[0].text == "identity";
  if (identity && (!allow_identity || f.size() != 1)) {
    fail(values[0].line, "'identity' is only allowed for a whole T matrix");
  }
  if (uniform && f.size() == 3) fail(values[0].line, "'uniform' is not a single probability");
  // The form decides how many numbers follow: one entry, one row, or the whole matrix.
  std::vector<double> v;
  if (!uniform && !identity)
    v = numbers(values, f.size() == 3 ? 1 : (f.size() == 2 ? nc : ns * nc), keyword);
  for (int ai = 0; ai < static_cast<int>(actions_.size()); ++ai) {
    if (a >= 0 && ai != a) continue;
    for (int ri = 0; ri < ns; ++ri) {
      if (row >= 0 && ri != row) continue;
      row_line[ai * ns + ri] = keyword.line;
      for (int ci = 0; ci < nc; ++ci) {
        if (column >= 0 && ci != column) continue;
        double p;
        if (uniform)
          p = 1.0 / nc;
        else if (identity)
          p = ri == ci ? 1.0 : 0.0;
        else if (f.size() == 3)
          p = v[0];
        else if (f.size() == 2)
          p = v[ci];
        else
          p = v[ri * nc + ci];
        table[(static_cast<std::size_t>(ai) * ns + ri) * nc + ci] = p;
      }
    }
  }
}

void Parser::read_reward(const Token& keyword) {
  require_sizes(keyword);
  const int ns = static_cast<int>(states_.size()), no = static_cast<int>(observations_.size());
  const std::vector<Token> f = fields(4);
  if (f.size() < 2) fail(keyword.line, "'R' needs ': action : start-state' at least");
  const int a = resolve(f[0], actions_, "action");
  const int s = resolve(f[1], states_, "state");
  const int s_next = f.size() > 2 ? resolve(f[2], states_, "state") : -1;
  const int o = f.size() > 3 ? resolve(f[3], observations_, "observation") : -1;
  const std::vector<Token> values = rest_of_statement();
  const double sign = cost_ ? -1.0 : 1.0;
  if (f.size() == 4) {
    rewards_.push_back({a, s, s_next, o, sign * numbers(values, 1, keyword)[0]});
  } else if (f.size() == 3) {
    const std::vector<double> v = numbers(values, no, keyword);
    for (int oi = 0; oi < no; ++oi) rewards_.push_back({a, s, s_next, oi, sign * v[oi]});
  } else {
    const std::vector<double> v = numbers(values, static_cast<std::size_t>(ns) * no, keyword);
    for (int sj = 0; sj < ns; ++sj) {
      for (int oi = 0; oi < no; ++oi) rewards_.push_back({a, s, sj, oi, sign * v[sj * no + oi]});
    }
  }
}

void Parser::read_discount(const Token& keyword) {
  expect_colon("discount");
  const std::vector<Token> v = rest_of_statement();
  discount_ = numbers(v, 1, keyword)[0];
  if (!(discount_ > 0.0 && discount_ < 1.0)) fail(keyword.line, "discount must be in (0, 1)");
}

void Parser::read_values(const Token& keyword) {
  expect_colon("values");
  const std::vector<Token> v = rest_of_statement();
  if (v.size() != 1 || (v[0].text != "reward" && v[0].text != "cost")) {
    fail(keyword.line, "'values:' must be 'reward' or 'cost'");
  }
  if (!rewards_.empty()) fail(keyword.line, "'values:' must come before any 'R:' line");
  cost_ = v[0].text == "cost";
}

void Parser::read_name_list(const Token& keyword) {
  expect_colon(keyword.text);
  auto& names = keyword.text == "states"    ? states_
                : keyword.text == "actions" ? actions_
                                            : observations_;
  read_names(keyword.text, names,
             keyword.text[0] == 'o'   ? 'o'
             : keyword.text[0] == 'a' ? 'a'
                                      : 's');
  if (!states_.empty() && !actions_.empty() && !observations_.empty() && t_.empty())
    allocate_tables(keyword);
}

void Parser::allocate_tables(const Token& keyword) {
  const std::size_t ns = states_.size(), na = actions_.size();
  // Dense tables: refuse sizes that would exhaust memory rather than crash.
  if (static_cast<double>(na) * ns * std::max(ns, observations_.size()) > 5e7) {
    fail(keyword.line, "problem too large for dense tables (actions x states x states > 5e7)");
  }
  t_.assign(na * ns * ns, 0.0);
  o_.assign(na * ns * observations_.size(), 0.0);
  t_row_line_.assign(na * ns, 0);
  o_row_line_.assign(na * ns, 0);
}

void Parser::read_statement(const Token& keyword) {
  if (!is_keyword(keyword.text)) {
    fail(keyword.line, "unexpected '" + keyword.text +
                           "' (expected discount:, values:, states:, actions:, "
                           "observations:, start:, T:, O: or R:)");
  }
  if (keyword.text == "discount") {
    read_discount(keyword);
  } else if (keyword.text == "values") {
    read_values(keyword);
  } else if (keyword.text == "states" || keyword.text == "actions" ||
             keyword.text == "observations") {
    read_name_list(keyword);
  } else if (keyword.text == "start") {
    read_start(keyword);
  } else if (keyword.text == "T") {  // T, O and R are followed directly by their fields
    read_probabilities(keyword, states_, "state", true, t_, t_row_line_);
  } else if (keyword.text == "O") {
    read_probabilities(keyword, observations_, "observation", false, o_, o_row_line_);
  } else {
    read_reward(keyword);
  }
}

// Every row must be a distribution; point at the line that last wrote it.
void Parser::check_rows(const std::vector<double>& table, int width,
                        const std::vector<int>& row_line, const char* kind) const {
  const int ns = static_cast<int>(states_.size()), na = static_cast<int>(actions_.size());
  for (int ai = 0; ai < na; ++ai) {
    for (int si = 0; si < ns; ++si) {
      const int row = ai * ns + si;
      const RowCheck check = check_row(&table[static_cast<std::size_t>(row) * width], width);
      if (!check.in_range) {
        fail(row_line[row], std::string(kind) + " has a probability outside [0, 1]");
      }
      if (!check.ok()) {
        std::ostringstream msg;
        msg << kind << " row for action '" << actions_[ai] << "' and state '" << states_[si]
            << "' sums to " << check.sum << ", not 1 (tolerance 1e-6)"
            << (row_line[row] == 0 ? "; it was never given" : "");
        fail(row_line[row] == 0 ? last_line() : row_line[row], msg.str());
      }
    }
  }
}

void Parser::check_complete() const {
  if (discount_ < 0.0) fail(1, "missing 'discount:' line");
  if (states_.empty() || actions_.empty() || observations_.empty()) {
    fail(last_line(), "missing 'states:', 'actions:' or 'observations:' line");
  }
  check_rows(t_, static_cast<int>(states_.size()), t_row_line_, "T");
  check_rows(o_, static_cast<int>(observations_.size()), o_row_line_, "O");
}

// Entries that give no s' or o apply to every outcome, so when only such entries touch (a, s) the
// last one is the expected reward itself.
std::vector<double> Parser::expected_rewards() const {
  const int ns = static_cast<int>(states_.size()), na = static_cast<int>(actions_.size()),
            no = static_cast<int>(observations_.size());
  std::vector<double> reward(static_cast<std::size_t>(ns) * na, 0.0);
  std::vector<double> outcome(static_cast<std::size_t>(ns) * no);
  for (int ai = 0; ai < na; ++ai) {
    for (int si = 0; si < ns; ++si) {
      std::fill(outcome.begin(), outcome.end(), 0.0);
      for (const RewardEntry& e : rewards_) {
        if ((e.a >= 0 && e.a != ai) || (e.s >= 0 && e.s != si)) continue;
        for (int sj = 0; sj < ns; ++sj) {
          if (e.s_next >= 0 && e.s_next != sj) continue;
          for (int oi = 0; oi < no; ++oi) {
            if (e.o < 0 || e.o == oi) outcome[static_cast<std::size_t>(sj) * no + oi] = e.value;
          }
        }
      }
      double r = 0.0;
      for (int sj = 0; sj < ns; ++sj) {
        const double t = t_[(static_cast<std::size_t>(ai) * ns + si) * ns + sj];
        if (t == 0.0) continue;
        for (int oi = 0; oi < no; ++oi) {
          r += t * o_[(static_cast<std::size_t>(ai) * ns + sj) * no + oi] *
               outcome[static_cast<std::size_t>(sj) * no + oi];
        }
      }
      reward[static_cast<std::size_t>(si) * na + ai] = r;
    }
  }
  return reward;
}

std::shared_ptr<const TabularPomdp> Parser::parse() {
  if (tokens_.empty())
    fail(1, "the file is empty; expected a .pomdp problem (discount:, states:, ...)");
  while (!at_end()) read_statement(next());
  check_complete();

  TabularPomdpData d;
  const std::size_t slash = file_.find_last_of('/');
  d.name = slash == std::string::npos ? file_ : file_.substr(slash + 1);
  d.state_names = states_;
  d.action_names = actions_;
  d.observation_names = observations_;
  d.discount = discount_;
  d.reward = expected_rewards();
  d.transition = std::move(t_);
  d.observation = std::move(o_);
  const std::size_t ns = states_.size();
  d.start = start_.empty() ? std::vector<double>(ns, 1.0 / static_cast<double>(ns)) : start_;
  return std::make_shared<const TabularPomdp>(std::move(d));
}

}  // namespace

std::shared_ptr<const TabularPomdp> parse_cassandra_pomdp(const std::string& text,
                                                          const std::string& source_name) {
  Parser parser(text, source_name);
  return parser.parse();
}

}  // namespace echoplan::pomdp
