#include "experiment/html_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "common/error.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), 0, "cannot read the figure");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const char* kStyle = R"(
body { font-family: sans-serif; margin: 2em auto; max-width: 1250px; color: #222; line-height: 1.4; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 2em; }
table { border-collapse: collapse; margin: .8em 0; font-size: .9em; display: block; overflow-x: auto; max-width: 100%; }
th, td { border: 1px solid #bbb; padding: .25em .6em; text-align: right; }
th { background: #e8eef6; } td.l, th.l { text-align: left; }
tr.total td { font-weight: bold; background: #f4f4f4; }
td.bad { background: #fbe3e3; } td.good { background: #e3f4e3; }
.note { background: #fff8e0; border-left: 4px solid #e0b000; padding: .6em 1em; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: .9em; color: #444; }
details { margin: 1em 0; }
)";

}  // namespace

std::string base64(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

namespace {

// The page's head, title, the campaign's settings and what its world is.
std::string page_opening(const CampaignResults& results) {
  const CampaignConfig& config = results.config;
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  const std::string title = escape(results.world.title);
  h += "<title>" + title + "</title>\n<style>" + std::string(kStyle) + "</style>\n";
  h += "</head>\n<body>\n<h1>" + title + "</h1>\n";
  h += fmt::format(
      "<p>{} of {} trials finished; campaign <code>{}</code>, seed {}, planner {} with {}.</p>\n",
      results.entries.size(), results.planned_trials, escape(config.source), config.seed,
      escape(config.planner.solver),
      config.planner.episodes > 0 ? fmt::format("{} episodes per step", config.planner.episodes)
                                  : fmt::format("{} ms per step", config.planner.step_ms));
  if (!results.world.note.empty())
    h += "<p class=\"note\">" + escape(results.world.note) + "</p>\n";
  return h;
}

// Up to this many actions the results table gives each a column; with more (recorded data with
// many behaviours) the table would run off a laptop's screen, and behaviours_table() gives them
// a row each instead.
constexpr int kActionColumns = 4;

// The summary rows, with the reference's columns when the campaign names a reference.
std::string results_table(const CampaignResults& results) {
  const std::optional<ReferenceResults>& reference = results.config.reference;
  std::string h = reference ? "<h2>Results and the " + escape(reference->label) + "'s</h2>\n"
                            : std::string("<h2>Results</h2>\n");
  h += "<table>\n<tr><th class=\"l\">arm</th><th class=\"l\">objects</th>"
       "<th>trials</th><th>accuracy</th><th>mean discounted reward (95% CI)</th><th>mean "
       "steps</th>";
  const bool costed = !results.action_costs.empty();  // the mean cost beside the steps
  if (costed) h += "<th>mean cost</th>";
  const int shown = shown_actions(results) <= kActionColumns ? shown_actions(results) : 0;
  for (int a = 0; a < shown; ++a) h += "<th>mean " + escape(results.spec.action_names[a]) + "</th>";
  if (reference)
    h += fmt::format("<th>{0}: correct</th><th>{0}: reward</th>", escape(reference->label));
  h += "</tr>\n";
  for (const SummaryRow& row : summary_rows(results)) {
    const TrialSummary& s = row.summary;
    h += fmt::format(
        "<tr{}><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td><td "
        "class=\"{}\">{:.0f}%</td><td>{:.2f} ± {:.2f}</td><td>{:.2f}</td>",
        row.scope != RowScope::object ? " class=\"total\"" : "", escape(row.arm), escape(row.label),
        s.trials, s.accuracy >= 0.999 ? "good" : (s.accuracy < 0.8 ? "bad" : ""),
        100.0 * s.accuracy, s.mean_discounted_reward, s.ci95, s.mean_steps);
    if (costed) h += fmt::format("<td>{:.2f}</td>", s.mean_cost);
    for (int a = 0; a < shown; ++a) h += fmt::format("<td>{:.2f}</td>", s.mean_action_counts[a]);
    if (row.reference)
      h += fmt::format("<td>{}/{}</td><td>{:.2f}</td>", row.reference->correct,
                       row.reference->trials, row.reference->mean_discounted_reward);
    else if (reference)
      h += "<td></td><td></td>";
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

// With more actions than the results table has columns for: per action, each arm's mean uses per
// trial over all its trials (a row per action, a column per arm).
std::string behaviours_table(const CampaignResults& results) {
  const int shown = shown_actions(results);
  if (shown <= kActionColumns) return "";
  std::vector<const SummaryRow*> all;
  const std::vector<SummaryRow> rows = summary_rows(results);
  for (const SummaryRow& row : rows)
    if (row.scope == RowScope::all) all.push_back(&row);
  std::string h =
      "<h2>Behaviours performed per trial</h2>\n<table>\n<tr><th class=\"l\">behaviour</th>";
  for (const SummaryRow* row : all) h += "<th>" + escape(row->arm) + "</th>";
  h += "</tr>\n";
  for (int a = 0; a < shown; ++a) {
    h += "<tr><td class=\"l\">" + escape(results.spec.action_names[a]) + "</td>";
    for (const SummaryRow* row : all)
      h += fmt::format("<td>{:.2f}</td>", row->summary.mean_action_counts[a]);
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

// Each later arm against the first, trial by trial.
std::string paired_comparison(const CampaignResults& results) {
  const nlohmann::json summary = summary_json(results);
  if (!summary.contains("paired_differences")) return "";
  std::string h =
      "<p>Paired comparison of the arms (each trial of one arm against the trial of the other "
      "with the " +
      escape(results.world.pairing) + "):</p>\n<ul>\n";
  for (const auto& d : summary["paired_differences"])
    h +=
        fmt::format("<li>{} minus {}: {:+.2f} ± {:.2f} discounted reward (95% CI, {} pairs)</li>\n",
                    escape(d["arm"].get<std::string>()), escape(d["minus"].get<std::string>()),
                    d["mean_discounted_reward_difference"].get<double>(), d["ci95"].get<double>(),
                    d["pairs"].get<int>());
  return h + "</ul>\n";
}

// Every figure, its PNG inlined.
std::string figure_sections(const fs::path& directory, const std::vector<Figure>& figures) {
  std::string h;
  for (const Figure& f : figures)
    h += fmt::format(
        "<h2>{}</h2>\n<figure><img alt=\"{}\" src=\"data:image/png;base64,{}\">"
        "<figcaption>{} (also <code>figures/{}.svg</code>)</figcaption></figure>\n",
        escape(f.title), escape(f.title),
        base64(read_bytes(directory / "figures" / (f.stem + ".png"))), escape(f.caption),
        escape(f.stem));
  return h;
}

// The name of the report's table a campaign beside the report's results reproduces.
std::string as_report_table(const CampaignResults& results, const char* table) {
  return results.config.reference
             ? fmt::format(" (the {}'s Table {})", escape(results.config.reference->label), table)
             : std::string();
}

// Every trial (the report's Table 5.1).
std::string trials_table(const CampaignResults& results) {
  const auto& objects = results.spec.state.discrete_value_names.at(0);
  std::string h =
      "<h2>Every trial" + as_report_table(results, "5.1") +
      "</h2>\n<details "
      "open><summary>trials.csv</summary>\n<table>\n"
      "<tr><th>trial</th><th class=\"l\">arm</th><th class=\"l\">object</th><th class=\"l\">true "
      "state</th><th class=\"l\">final belief</th><th>steps</th>";
  for (const auto& a : results.spec.action_names) h += "<th>" + escape(a) + "</th>";
  h += "<th>discounted reward</th></tr>\n";
  for (const JournalEntry& e : results.entries) {
    const TrialRecord& r = e.result.record;
    h += fmt::format(
        "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td>"
        "<td class=\"l{}\">{}</td><td>{}</td>",
        e.id, escape(e.arm),
        escape(e.session.empty() ? e.object : e.object + " (session " + e.session + ")"),
        escape(objects.at(r.true_state)), r.believed_state == r.true_state ? "" : " bad",
        escape(objects.at(r.believed_state)), r.steps);
    for (int c : r.action_counts) h += fmt::format("<td>{}</td>", c);
    h += fmt::format("<td>{:.4f}</td></tr>\n", r.discounted_reward);
  }
  return h + "</table>\n</details>\n";
}

// One decision's row: the belief before it (particles or probabilities), the action, what was
// heard and its probability.
std::string step_row(const CampaignResults& results, const std::vector<std::string>& observations,
                     int trial, const StepRecord& s) {
  const auto& spec = results.spec;
  std::string h = fmt::format("<tr><td>{}</td><td>{}</td>", trial, s.step);
  for (double p : s.belief)
    h += results.belief_particles > 0
             ? fmt::format("<td>{}</td>", std::llround(p * results.belief_particles))
             : fmt::format("<td>{:.3f}</td>", p);
  const std::string heard =
      s.observation.index >= 0 && s.observation.index < static_cast<int>(observations.size())
          ? observations[static_cast<std::size_t>(s.observation.index)]
          : std::string();
  return h + fmt::format(
                 "<td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td></tr>\n",
                 escape(spec.action_names.at(s.action)), escape(heard),
                 s.heard_probability ? fmt::format("{:.3f}", *s.heard_probability) : std::string());
}

// Every decision (the report's Table 5.2).
std::string steps_table(const CampaignResults& results) {
  const bool particles = results.belief_particles > 0;
  std::string h = "<h2>Every decision" + as_report_table(results, "5.2") +
                  "</h2>\n<details><summary>steps.csv</summary>\n<table>\n"
                  "<tr><th>trial</th><th>step</th>";
  for (const auto& o : results.spec.state.discrete_value_names.at(0))
    h += "<th>" + escape(o) + (particles ? " particles" : " p") + "</th>";
  h += "<th class=\"l\">action</th><th class=\"l\">heard</th><th>heard p</th></tr>\n";
  const auto observations = observation_names(results);
  for (const JournalEntry& e : results.entries)
    for (const StepRecord& s : e.result.steps)
      h += step_row(results, observations.at(e.arm), e.id, s);
  return h + "</table>\n</details>\n";
}

// One object's counts of one action: "a b c d" (per class heard) and the share heard as `right`
// (the object itself, or the original a variant plays).
std::string heard_cells(const HeardCounts* counts, const std::string& object,
                        const std::string& right) {
  if (!counts) return "<td>-</td><td>-</td>";
  const auto row = std::find(counts->rows.begin(), counts->rows.end(), object);
  if (row == counts->rows.end()) return "<td>-</td><td>-</td>";
  const auto r = static_cast<std::size_t>(row - counts->rows.begin());
  const int n = counts->total(r);
  const std::string heard = fmt::format("<td>{}</td>", fmt::join(counts->counts[r], " "));
  const bool a_class =
      std::find(counts->columns.begin(), counts->columns.end(), right) != counts->columns.end();
  if (!a_class || n == 0) return heard + "<td>-</td>";
  const int k = counts->heard_as(r, right);
  return heard + fmt::format("<td>{}/{} = {:.2f}</td>", k, n, static_cast<double>(k) / n);
}

const HeardCounts* of_action(const std::vector<HeardCounts>& all, const std::string& action) {
  for (const HeardCounts& h : all)
    if (h.action == action) return &h;
  return nullptr;
}

// The simulated training set heard by the reference's classifier beside what the lab's heard,
// per action and object (a simulated world whose reference has `heard:` counts).
std::string heard_section(const CampaignResults& results) {
  const std::optional<ReferenceResults>& reference = results.config.reference;
  if (results.heard.empty() || !reference || !reference->heard) return "";
  const HeardReference& lab = *reference->heard;
  std::string h = fmt::format(
      "<h2>What the classifier hears: the simulated training set and the {}'s runs</h2>\n"
      "<p>Classifier <code>{}</code>; simulated: leave-one-out over the training set, and the "
      "variants heard by the classifier fitted on all of it. Each row: the object's recordings "
      "heard as {}, and the share heard as itself (a variant: as the object it plays).</p>\n",
      escape(reference->label), escape(lab.classifier),
      escape(fmt::format("{}", fmt::join(results.heard.front().columns, ", "))));
  if (!lab.note.empty()) h += "<p>" + escape(lab.note) + "</p>\n";
  std::map<std::string, std::string> plays;  // a variant's row is right when heard as its original
  for (const ObjectGroup& group : results.groups) plays[group.object] = group.plays;
  for (const HeardCounts& simulated : results.heard) {
    const HeardCounts* measured = of_action(lab.actions, simulated.action);
    std::vector<std::string> objects = simulated.rows;
    if (measured)
      for (const std::string& o : measured->rows)
        if (std::find(objects.begin(), objects.end(), o) == objects.end()) objects.push_back(o);
    h += fmt::format(
        "<h3>{0}</h3>\n<table>\n<tr><th>object</th><th>simulated: heard as</th><th>simulated: "
        "right</th><th>{1}: heard as</th><th>{1}: right</th></tr>\n",
        escape(simulated.action), escape(reference->label));
    for (const std::string& o : objects) {
      const std::string right = plays.contains(o) ? plays.at(o) : o;
      h += "<tr><td>" + escape(o) + "</td>" + heard_cells(&simulated, o, right) +
           heard_cells(measured, o, right) + "</tr>\n";
    }
    h += "</table>\n";
  }
  return h;
}

// Per arm, the belief in its choice at the sort beside the share sorted right (sort_confidence.h).
std::string confidence_table(const CampaignResults& results) {
  std::string h =
      "<h2>How sure each arm was when it sorted</h2>\n<table>\n<tr><th class=\"l\">arm</th>"
      "<th>sorts</th><th>mean belief in its choice</th><th>sorted right</th><th>belief minus "
      "right (points)</th></tr>\n";
  for (const ArmConfidence& c : arm_confidence(results))
    if (c.sorts > 0)
      h += fmt::format(
          "<tr><td class=\"l\">{}</td><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:+.1f}</td>"
          "</tr>\n",
          escape(c.arm), c.sorts, c.mean_belief, c.share_right,
          100.0 * (c.mean_belief - c.share_right));
  return h + "</table>\n";
}

}  // namespace

std::string html_report(const fs::path& directory, const CampaignResults& results,
                        const std::vector<Figure>& figures) {
  std::string h = page_opening(results) + results_table(results) + paired_comparison(results) +
                  behaviours_table(results);
  const std::optional<ReferenceResults>& reference = results.config.reference;
  if (reference && !reference->note.empty()) h += "<p>" + escape(reference->note) + "</p>\n";
  h += heard_section(results) + confidence_table(results);
  h += figure_sections(directory, figures) + trials_table(results);
  // A dataset's decisions (a belief over every class at each) would make a page of megabytes.
  h += results.world.per_object
           ? steps_table(results)
           : "<p>Every decision, with the belief it was taken from: steps.csv.</p>\n";
  h += "<p>Files in this folder: trials.csv, steps.csv, arms/&lt;arm&gt;/ (the same per arm, for "
       "<code>echoplan certify</code>), summary.json, summary.txt, figures/ (PNG and SVG), "
       "journal.jsonl (one line per finished trial; everything else is rebuilt from it).</p>\n";
  h += "</body>\n</html>\n";
  return h;
}

}  // namespace echoplan::experiment
