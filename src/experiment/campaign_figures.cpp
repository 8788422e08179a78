#include "experiment/campaign_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "audio/features.h"
#include "audio/io.h"
#include "audio/onsets.h"
#include "common/error.h"
#include "experiment/gnuplot.h"

namespace echoplan::experiment {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kFramesBefore = 5;
constexpr std::size_t kFramesAfter = 40;

// gnuplot string literal in double quotes, taken literally ('noenhanced' keeps '_' as is).
std::string gnuplot_text(const std::string& text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '\n') {
      q += "\\n";  // a line break inside the title
      continue;
    }
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

std::string tic_labels(const std::vector<std::string>& names) {
  std::string tics = "(";
  for (std::size_t i = 0; i < names.size(); ++i)
    tics += fmt::format("{}{} {}", i ? ", " : "", gnuplot_text(names[i]), i);
  return tics + ")";
}

// Each figure as a list of gnuplot commands after "set output"; the same for PNG and SVG.
struct Drawing {
  Figure figure;
  int width = 1200;
  int height = 600;
  std::string commands;
};

Drawing belief_drawing(const CampaignResults& results, const std::string& arm,
                       const ObjectGroup& group, const fs::path& data_dir) {
  std::vector<const JournalEntry*> trials;
  for (const JournalEntry& e : results.entries)
    if (e.arm == arm && e.object == group.object) trials.push_back(&e);
  const auto& objects = results.spec.state.discrete_value_names.at(0);
  const auto& actions = results.spec.action_names;
  const bool particles = results.belief_particles > 0;
  const int columns = std::min<int>(5, static_cast<int>(trials.size()));
  const int rows = (static_cast<int>(trials.size()) + columns - 1) / columns;

  Drawing d;
  d.figure.stem = fmt::format("belief_{}_{}", arm, group.object);
  d.figure.title =
      fmt::format("Belief at each decision: {} in the world, arm {}", group.object, arm);
  std::string legend;
  for (std::size_t a = 0; a < actions.size(); ++a)
    legend += fmt::format("{}{} = {}", a ? ", " : "", a + 1, actions[a]);
  d.figure.caption = fmt::format(
      "One panel per trial (as the report's Figure 5.1): {} of each object before each decision. "
      "Panel titles: trial id, the believed object at the end (✓ when right), the discounted "
      "reward and "
      "the actions taken ({}).",
      particles ? "belief particles" : "probability", legend);
  d.width = 330 * columns;
  d.height = 280 * rows + 40;
  std::string& c = d.commands;
  c += fmt::format("set multiplot layout {},{} title {} noenhanced\n", rows, columns,
                   gnuplot_text(d.figure.title));
  c += fmt::format("set yrange [0:{}]\nset xlabel 'decision'\nset key off\nset grid\n",
                   particles ? results.belief_particles : 1);
  for (std::size_t t = 0; t < trials.size(); ++t) {
    const JournalEntry& e = *trials[t];
    const std::string file = fmt::format("belief_{}.dat", e.id);
    std::ofstream(data_dir / file) << belief_data(e.result.steps, results.belief_particles);
    std::string sequence;
    for (const StepRecord& s : e.result.steps) sequence += fmt::format(" {}", s.action + 1);
    const bool right = e.result.record.believed_state == e.result.record.true_state;
    if (sequence.size() > 36) sequence = sequence.substr(0, 33) + " ...";
    c += fmt::format(
        "set title {} noenhanced font ',8'\n",
        gnuplot_text(fmt::format("#{} {}{}, {:.2f}\nactions{}", e.id,
                                 objects[e.result.record.believed_state], right ? " ✓" : " ✗",
                                 e.result.record.discounted_reward, sequence)));
    const std::size_t last = std::max<std::size_t>(1, e.result.steps.size() - 1);
    c += fmt::format("set xrange [-0.2:{}]\nset xtics {}\n", last + 0.2,
                     last <= 10 ? 1 : (last + 9) / 10);
    // The legend once, in the first panel.
    c += t == 0 ? "set key top left font ',8' opaque box\n" : "set key off\n";
    c += "plot ";
    for (std::size_t k = 0; k < objects.size(); ++k)
      c += fmt::format("{}'{}' using 1:{} with linespoints lw 2 title {} noenhanced", k ? ", " : "",
                       file, k + 2, gnuplot_text(objects[k]));
    c += '\n';
  }
  c += "unset multiplot\n";
  return d;
}

Drawing confusion_drawing(const CampaignResults& results, const std::string& arm,
                          const fs::path& data_dir) {
  std::vector<ConfusionCounts> matrices;
  for (ConfusionCounts& c : confusion_counts(results))
    if (c.arm == arm) matrices.push_back(std::move(c));
  Drawing d;
  d.figure.stem = fmt::format("confusion_{}", arm);
  d.figure.title = fmt::format("What was heard, arm {}", arm);
  d.figure.caption =
      "Counts of each heard class (columns) against the object in the world (rows), over every "
      "sensing "
      "step of the arm's trials, one panel per sensing action.";
  if (matrices.empty()) return d;
  d.width = 560 * static_cast<int>(matrices.size());
  d.height = 520;
  std::string& c = d.commands;
  c += fmt::format("set multiplot layout 1,{} title {} noenhanced\n", matrices.size(),
                   gnuplot_text(d.figure.title));
  c += "set palette defined (0 'white', 1 '#08519c')\nunset colorbox\nset key off\nset xlabel "
       "'heard'\n"
       "set xtics rotate by 30 right\nset size ratio -1\n";
  for (const ConfusionCounts& m : matrices) {
    const std::string file = fmt::format("confusion_{}_{}.dat", arm, m.action);
    std::ofstream(data_dir / file) << confusion_data(m);
    int largest = 1;
    for (const std::vector<int>& row : m.counts)
      for (int count : row) largest = std::max(largest, count);
    c += fmt::format("set title {} noenhanced\n", gnuplot_text(m.action));
    c += fmt::format("set xtics {} noenhanced\nset ytics {} noenhanced\n", tic_labels(m.columns),
                     tic_labels(m.rows));
    c += fmt::format("set xrange [-0.5:{}]\nset yrange [{}:-0.5]\nset cbrange [0:{}]\n",
                     m.columns.size() - 0.5, m.rows.size() - 0.5, largest);
    c += fmt::format(
        "plot '{}' using 1:2:3 with image, '' using 1:2:(sprintf('%d', $3)) with labels\n", file);
  }
  c += "unset multiplot\n";
  return d;
}

// Each arm's accuracy against its mean number of sensing actions per trial: where a strategy sits
// between deciding early and performing every behaviour.
// One point per arm over all its trials: the share sorted right against `x` of the arm's "all" row
// (sensing actions, or cost, per trial). `name` is the figure's stem and data file.
struct TradeoffAxis {
  std::string name;
  std::string title;
  std::string caption;
  std::string xlabel;
  std::function<double(const TrialSummary&)> x;
};

// The share-sorted-right axis from a little below the lowest share plotted to just above 1, in
// steps of 0.05: arms between 0.92 and 0.97 fill the figure instead of its top twentieth.
std::string accuracy_range(double lowest) {
  const double bottom = std::max(0.0, std::floor((lowest - 0.02) * 20.0) / 20.0);
  return fmt::format("set yrange [{}:{}]\n", bottom, 1.0 + 0.03 * (1.0 - bottom));
}

Drawing tradeoff_drawing(const CampaignResults& results, const TradeoffAxis& axis,
                         const fs::path& data_dir) {
  Drawing d;
  d.figure.stem = axis.name;
  d.figure.title = axis.title;
  d.figure.caption = axis.caption;
  d.width = 700;
  d.height = 500;
  std::string data;
  std::string plot;
  int index = 0;
  // The axes fit the points: x ends a little past the rightmost, so none sits on the border.
  double lowest = 1.0, rightmost = 0.0;
  const std::string file = axis.name + ".dat";
  for (const SummaryRow& row : summary_rows(results)) {
    if (row.scope != RowScope::all) continue;
    data += fmt::format("{} {}\n", axis.x(row.summary), row.summary.accuracy);
    lowest = std::min(lowest, row.summary.accuracy);
    rightmost = std::max(rightmost, axis.x(row.summary));
    // One series per arm, so each has its own colour and a key entry (labels would overlap).
    plot += fmt::format("{}'{}' every ::{}::{} using 1:2 with points pt 7 ps 2 title {}",
                        index ? ", " : "plot ", file, index, index, gnuplot_text(row.arm));
    ++index;
  }
  std::ofstream(data_dir / file) << data;
  d.commands = fmt::format(
      "set xlabel '{}'\nset ylabel 'sorted right'\n"
      "{}set xrange [0:{}]\nset grid\nset key bottom right noenhanced\n{}\n",
      axis.xlabel, accuracy_range(lowest),
      rightmost > 0.0 ? fmt::format("{}", 1.08 * rightmost) : "*", plot);
  return d;
}

// Reliability: per arm and confidence bin, the share sorted right against the mean belief at the
// sort (sort_confidence.h); an honest planner's points lie on the diagonal.
Drawing reliability_drawing(const CampaignResults& results, const fs::path& data_dir) {
  Drawing d;
  d.figure.stem = "reliability";
  d.figure.title = "How sure each arm was when it sorted, against how often it was right";
  d.figure.caption =
      "Each point is one arm's sorts whose belief in the chosen bin (at the decision that sorted) "
      "fell in one bin of confidence: the share of them sorted right against their mean belief; "
      "the point's size grows with the number of sorts. Points below the diagonal are sorts surer "
      "than they were right.";
  d.width = 700;
  d.height = 500;
  std::string data;
  std::string plot = "plot x title 'belief = share right' with lines lc rgb '#888888'";
  int index = 0;
  for (const ArmConfidence& c : arm_confidence(results)) {
    if (c.sorts == 0) continue;
    // One data block per arm (blank-line separated), so each has its colour and key entry.
    for (const ReliabilityBin& b : c.bins)
      if (b.sorts > 0)
        data += fmt::format("{} {} {}\n", b.mean_belief, b.share_right,
                            0.8 + 2.0 * std::sqrt(static_cast<double>(b.sorts) / c.sorts));
    data += "\n\n";
    plot += fmt::format(
        ", 'reliability.dat' index {} using 1:2:3 with points pt 7 ps variable "
        "title {}",
        index++, gnuplot_text(c.arm));
  }
  std::ofstream(data_dir / "reliability.dat") << data;
  d.commands =
      "set xlabel 'mean belief in the chosen bin at the sort'\nset ylabel 'sorted right'\n"
      "set xrange [0:1.02]\nset yrange [0:1.05]\nset grid\nset key bottom right noenhanced\n" +
      plot + "\n";
  return d;
}

// A campaign heard through noise: per arm and band of the trials' measured noise level
// (noise_levels.h), the share sorted right (solid) and the mean belief at the sort (dashed); an
// honest arm's two lines lie on each other.
Drawing noise_levels_drawing(const std::vector<ArmNoiseBands>& all, const fs::path& data_dir) {
  Drawing d;
  d.figure.stem = "noise_levels";
  d.figure.title = "Sorted right and how sure, by how noisy the trial's recordings were";
  d.figure.caption =
      "Each arm's trials banded by the median event-to-background ratio measured from their own "
      "recordings: the share sorted right (solid) and the mean belief in the chosen bin at the "
      "sort "
      "(dashed). Where the dashed line is above the solid one the arm was surer than right.";
  d.width = 800;
  d.height = 500;
  std::string data, plot, tics;
  int index = 0;
  for (const ArmNoiseBands& a : all) {
    for (std::size_t b = 0; b < a.bands.size(); ++b)
      if (a.bands[b].sorts > 0)
        data += fmt::format("{} {} {}\n", b, a.bands[b].share_right, a.bands[b].mean_belief);
    data += "\n\n";
    plot += fmt::format(
        "{}'noise_levels.dat' index {} using 1:2 with linespoints lw 2 pt 7 lc {} title {}, "
        "'' index {} using 1:3 with linespoints dt 2 pt 6 lc {} notitle",
        index ? ", " : "plot ", index, index + 1, gnuplot_text(a.arm + ": right"), index,
        index + 1);
    ++index;
  }
  for (std::size_t b = 0; !all.empty() && b < all.front().bands.size(); ++b)
    tics += fmt::format("{}{} {}", b ? ", " : "", gnuplot_text(all.front().bands[b].label()), b);
  std::ofstream(data_dir / "noise_levels.dat") << data;
  d.commands = fmt::format(
      "set xlabel 'measured event-to-background ratio of the trial'\nset ylabel 'share'\n"
      "set xtics ({})\nset xrange [-0.3:{}]\nset yrange [0:1.05]\nset grid\n"
      "set key bottom right noenhanced\n{}\n",
      tics, all.empty() ? 1.0 : all.front().bands.size() - 0.7, plot);
  return d;
}

// Accuracy against the sensing actions performed, and, when actions have costs, against the cost.
std::vector<Drawing> tradeoff_drawings(const CampaignResults& results, const fs::path& data_dir) {
  const int sensing = results.sensing_actions;
  std::vector<Drawing> drawings{tradeoff_drawing(
      results,
      {"accuracy_vs_actions", "Accuracy against sensing actions per trial, per arm",
       "Each point is an arm over all its trials: the share sorted right against the mean number "
       "of sensing actions it performed before sorting.",
       "mean sensing actions per trial",
       [sensing](const TrialSummary& s) {
         double actions = 0.0;
         for (int a = 0; a < sensing; ++a) actions += s.mean_action_counts.at(a);
         return actions;
       }},
      data_dir)};
  if (!results.action_costs.empty())
    drawings.push_back(tradeoff_drawing(
        results,
        {"accuracy_vs_cost", "Accuracy against cost per trial, per arm",
         "Each point is an arm over all its trials: the share sorted right against the mean cost "
         "of the sensing actions it performed before sorting (task.costs; the others at "
         "-task.rewards.sense).",
         "mean cost per trial", [](const TrialSummary& s) { return s.mean_cost; }},
        data_dir));
  return drawings;
}

// How often each arm chose each sensing action: mean uses per trial.
Drawing action_use_drawing(const CampaignResults& results, int sensing, const fs::path& data_dir) {
  Drawing d;
  d.figure.stem = "actions_chosen";
  d.figure.title = "How often each arm chose each sensing action";
  d.figure.caption = "Mean number of times each sensing action was performed per trial, per arm.";
  // At most the page's width: a wider image is shrunk to fit, and its labels with it.
  d.width = std::clamp(45 * sensing * static_cast<int>(results.arms.size()), 700, 1200);
  d.height = 500;
  std::string data = "action";
  for (const ResolvedArm& arm : results.arms) data += " " + gnuplot_text(arm.name);
  data += "\n";
  std::vector<std::vector<double>> uses;
  for (const SummaryRow& row : summary_rows(results))
    if (row.scope == RowScope::all) uses.push_back(row.summary.mean_action_counts);
  for (int a = 0; a < sensing; ++a) {
    data += gnuplot_text(results.spec.action_names[a]);
    for (const std::vector<double>& arm : uses) data += fmt::format(" {}", arm.at(a));
    data += "\n";
  }
  std::ofstream(data_dir / "actions_chosen.dat") << data;
  d.commands = fmt::format(
      "set style data histograms\nset style histogram clustered gap 1\nset style fill solid "
      "0.8 border -1\nset ylabel 'uses per trial'\nset xtics rotate by 30 right noenhanced\n"
      "set key outside right top noenhanced\nset grid ytics\nset yrange [0:*]\n"
      "plot for [c=2:{}] 'actions_chosen.dat' using c:xtic(1) title columnhead\n",
      results.arms.size() + 1);
  return d;
}

Drawing templates_drawing(const std::vector<TemplateMatrix>& templates, const fs::path& data_dir) {
  std::vector<std::string> objects, actions;
  for (const TemplateMatrix& t : templates) {
    if (std::find(objects.begin(), objects.end(), t.object) == objects.end())
      objects.push_back(t.object);
    if (std::find(actions.begin(), actions.end(), t.action) == actions.end())
      actions.push_back(t.action);
  }
  Drawing d;
  d.figure.stem = "templates";
  d.figure.title = "Mean log-mel spectrogram of each object and action in the training set";
  d.figure.caption = fmt::format(
      "As the report's Figures 3.1 and 3.2: the mean over each pair's recordings of the log-mel "
      "energies "
      "(psf preset), aligned on each recording's first onset ({} frames before, {} after).",
      kFramesBefore, kFramesAfter);
  d.width = 330 * static_cast<int>(objects.size());
  d.height = 280 * static_cast<int>(actions.size()) + 40;
  std::string& c = d.commands;
  c += fmt::format("set multiplot layout {},{} title {} noenhanced\n", actions.size(),
                   objects.size(), gnuplot_text(d.figure.title));
  c += "set palette rgbformulae 33,13,10\nset xlabel 'time from window start (s)'\nset ylabel 'mel "
       "band'\n"
       "set autoscale xfix\nset autoscale yfix\nset key off\nset xtics 0.1 format '%.1f'\n";
  for (const std::string& action : actions)
    for (const std::string& object : objects) {
      auto it = std::find_if(templates.begin(), templates.end(), [&](const TemplateMatrix& t) {
        return t.object == object && t.action == action;
      });
      if (it == templates.end()) {
        c += "set multiplot next\n";
        continue;
      }
      const std::string file = fmt::format("template_{}_{}.dat", object, action);
      std::ofstream data(data_dir / file);
      for (std::size_t r = 0; r < it->mean.rows; ++r) {
        for (std::size_t k = 0; k < it->mean.cols; ++k)
          data << fmt::format("{:.6g} {} {:.6g}\n", r * it->hop_seconds, k,
                              it->mean.values[r * it->mean.cols + k]);
        data << '\n';
      }
      c += fmt::format(
          "set title {} noenhanced\n",
          gnuplot_text(fmt::format("{}, {} ({} recordings)", object, action, it->recordings)));
      c += fmt::format("plot '{}' using 1:2:3 with image\n", file);
    }
  c += "unset multiplot\n";
  return d;
}

}  // namespace

std::string belief_data(const std::vector<StepRecord>& steps, int belief_particles) {
  std::ostringstream data;
  for (const StepRecord& s : steps) {
    data << s.step;
    for (double p : s.belief) data << ' ' << (belief_particles > 0 ? p * belief_particles : p);
    data << '\n';
  }
  return data.str();
}

std::string confusion_data(const ConfusionCounts& counts) {
  std::ostringstream data;
  for (std::size_t r = 0; r < counts.rows.size(); ++r)
    for (std::size_t k = 0; k < counts.columns.size(); ++k)
      data << k << ' ' << r << ' ' << counts.counts[r][k] << '\n';
  return data.str();
}

std::vector<TemplateMatrix> template_matrices(const fs::path& recordings,
                                              const std::vector<std::string>& objects,
                                              const std::vector<std::string>& actions) {
  std::vector<TemplateMatrix> templates;
  for (const std::string& object : objects)
    for (const std::string& action : actions) {
      const fs::path folder = recordings / object / action;
      std::error_code error;
      if (!fs::is_directory(folder, error)) continue;
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".wav") files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      if (files.empty()) continue;
      TemplateMatrix t;
      t.object = object;
      t.action = action;
      for (const fs::path& file : files) {
        audio::ReadOptions read;
        read.channel_policy = audio::ChannelPolicy::mean;
        const audio::AudioClip clip = audio::read_audio(file.string(), read);
        const audio::FeatureConfig config = audio::preset_by_name("psf", clip.sample_rate);
        audio::FeatureExtractor extractor(config);
        audio::Features features;
        extractor.compute(clip.samples, features);
        const std::size_t anchor = audio::alignment_frame(features.flux, audio::OnsetChoice::first);
        const audio::FeatureMatrix window =
            audio::onset_window(features.log_mel, anchor, kFramesBefore, kFramesAfter);
        if (t.recordings == 0) {
          t.mean = window;
          t.hop_seconds = static_cast<double>(config.stft.framing.hop) / clip.sample_rate;
        } else {
          if (window.cols != t.mean.cols)
            throw InputError(file.string(), 0,
                             "has another sample rate than the other recordings of its pair");
          for (std::size_t v = 0; v < window.values.size(); ++v)
            t.mean.values[v] += window.values[v];
        }
        ++t.recordings;
      }
      for (float& v : t.mean.values) v /= static_cast<float>(t.recordings);
      templates.push_back(std::move(t));
    }
  return templates;
}

std::vector<Figure> draw_figures(const fs::path& directory, const CampaignResults& results,
                                 const std::vector<TemplateMatrix>& templates) {
  const fs::path figures = directory / "figures";
  fs::create_directories(figures);
  const TemporaryFolder work("echoplan-figures");
  std::vector<Drawing> drawings;
  if (!templates.empty()) drawings.push_back(templates_drawing(templates, work.path()));
  if (!results.world.per_object) {
    // A belief panel per trial and a confusion matrix per object would be hundreds of figures: a
    // page of recorded data compares the arms instead.
    for (Drawing& d : tradeoff_drawings(results, work.path())) drawings.push_back(std::move(d));
    drawings.push_back(action_use_drawing(results, results.sensing_actions, work.path()));
  }
  for (const ResolvedArm& arm : results.arms) {
    if (!results.world.per_object) break;
    for (const ObjectGroup& group : results.groups) {
      const bool any = std::any_of(
          results.entries.begin(), results.entries.end(),
          [&](const JournalEntry& e) { return e.arm == arm.name && e.object == group.object; });
      if (any) drawings.push_back(belief_drawing(results, arm.name, group, work.path()));
    }
    Drawing confusion = confusion_drawing(results, arm.name, work.path());
    if (!confusion.commands.empty()) drawings.push_back(std::move(confusion));
  }
  drawings.push_back(reliability_drawing(results, work.path()));
  if (const auto bands = noise_bands(results); !bands.empty())
    drawings.push_back(noise_levels_drawing(bands, work.path()));

  std::vector<Figure> drawn;
  for (const char* format : {"png", "svg"}) {
    std::string script;
    for (const Drawing& d : drawings) {
      const std::string terminal =
          std::string(format) == "png"
              ? fmt::format("pngcairo size {},{} font 'sans,9'", d.width, d.height)
              : fmt::format("svg size {},{} font 'sans,9' background '#ffffff'", d.width, d.height);
      script +=
          fmt::format("reset\nset terminal {}\nset output {}\n{}set output\n", terminal,
                      gnuplot_text(fs::absolute(figures / (d.figure.stem + "." + format)).string()),
                      d.commands);
    }
    std::string error;
    if (!run_gnuplot(script, work.path(), error))
      throw InputError((figures / "").string(), 0, "gnuplot failed drawing the figures: " + error);
  }
  for (const Drawing& d : drawings) drawn.push_back(d.figure);
  return drawn;
}

}  // namespace echoplan::experiment
