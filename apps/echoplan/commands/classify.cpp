// `echoplan classify` and `echoplan evaluate`: use a trained observation model on recordings.
#include <fmt/core.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/perception_report.h"
#include "common/error.h"
#include "perception/observation_model.h"

namespace echoplan::cli {

void add_classify_command(CLI::App& app) {
  struct Options {
    std::string model;
    std::string action;
    bool json = false;
    std::vector<std::string> files;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "classify",
      "Classify recordings made with one sensing action: per file, the heard class (or `unknown`), "
      "the\n"
      "calibrated probability of each class and the distance to the nearest class.\n"
      "Example: echoplan classify --model model.json --action strike --json clip1.wav clip2.flac");
  cmd->add_option("--model", opt->model, "Model file written by `echoplan train`")->required();
  cmd->add_option("--action", opt->action, "The sensing action the recordings were made with")
      ->required();
  cmd->add_flag("--json", opt->json,
                "One JSON object per line: {\"file\", \"action\", \"class\", \"probabilities\": "
                "{class: p}, \"distance\"}");
  cmd->add_option("FILE", opt->files, "Recordings (WAV, FLAC, AIFF; any rate and channel count)")
      ->required();
  cmd->callback([opt] {
    const perception::ObservationModel model = perception::load_observation_model(opt->model);
    (void)model.calibration(opt->action);  // an unknown action fails before any file is read
    perception::ClipAnalyzer analyzer(model.analysis());
    perception::ClipAnalysis analysis;
    for (const auto& file : opt->files) {
      analyzer.analyse(perception::read_recording(file, model.analysis().sample_rate), file,
                       analysis);
      const perception::Prediction p = model.classify(analysis, opt->action);
      if (opt->json) {
        nlohmann::json probabilities = nlohmann::json::object();
        for (std::size_t k = 0; k < p.probabilities.size(); ++k)
          probabilities[model.classes()[k]] = p.probabilities[k];
        const nlohmann::json line{{"file", file},
                                  {"action", opt->action},
                                  {"class", p.label},
                                  {"probabilities", probabilities},
                                  {"distance", p.distance}};
        fmt::print("{}\n", line.dump());
      } else {
        std::string probabilities;
        for (std::size_t k = 0; k < p.probabilities.size(); ++k)
          probabilities += fmt::format("{}{} {:.3f}", k == 0 ? "" : ", ", model.classes()[k],
                                       p.probabilities[k]);
        const std::string threshold =
            std::isinf(p.reject_threshold)
                ? "no reject"
                : fmt::format("unknown beyond {:.4g}", p.reject_threshold);
        fmt::print("{}: {} (distance {:.4g}, {}; {})\n", file, p.label, p.distance, threshold,
                   probabilities);
      }
    }
  });
}

void add_evaluate_command(CLI::App& app) {
  struct Options {
    std::string model;
    std::string data;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "evaluate",
      "Accuracy and confusion matrix per action of a trained model on held-out recordings\n"
      "DIR/<object>/<action>/*. Objects the model was not trained on are rows too (their right "
      "answer is\n"
      "`unknown`); accuracy counts the model's classes only. A set whose manifest has a `surface`\n"
      "column (recorded on several tables) is also counted table by table.\n"
      "Example: echoplan evaluate --model model.json --data held_out");
  cmd->add_option("--model", opt->model, "Model file written by `echoplan train`")->required();
  cmd->add_option("--data", opt->data, "Folder of held-out recordings")->required();
  cmd->add_flag(
      "--json", opt->json,
      "One JSON document: {\"model\", \"data\", \"actions\": {action: {accuracy, "
      "objects, symbols, confusion}}}; for a set whose manifest names each recording's table, "
      "also \"surfaces\": {table: {action: {...}}}");
  cmd->callback([opt] {
    const perception::ObservationModel model = perception::load_observation_model(opt->model);
    const perception::RecordingSet set = perception::load_recording_set(opt->data);
    const perception::Evaluation evaluation = perception::evaluate_observation_model(
        model, set, [](const std::string& stage, int done, int total) {
          if (done == total || done % 50 == 0) spdlog::info("{} {}/{}", stage, done, total);
        });
    std::vector<std::string> actions;
    for (const auto& a : model.actions())
      if (std::find(set.actions.begin(), set.actions.end(), a) != set.actions.end())
        actions.push_back(a);
    if (opt->json) {
      nlohmann::json per_action = nlohmann::json::object();
      for (std::size_t i = 0; i < actions.size(); ++i)
        per_action[actions[i]] = confusion_json(evaluation.per_action[i]);
      nlohmann::json out{{"model", opt->model}, {"data", opt->data}, {"actions", per_action}};
      for (const auto& [table, matrices] : evaluation.per_surface)
        for (std::size_t i = 0; i < actions.size(); ++i)
          out["surfaces"][table][actions[i]] = confusion_json(matrices[i]);
      fmt::print("{}\n", out.dump());
      return;
    }
    for (std::size_t i = 0; i < actions.size(); ++i) {
      print_confusion(actions[i], evaluation.per_action[i]);
      if (evaluation.per_surface.empty()) continue;
      std::vector<std::string> tables;
      for (const auto& [table, matrices] : evaluation.per_surface)
        tables.push_back(table + " " + accuracy_text(matrices[i]));
      fmt::print("  per table: {}\n", fmt::join(tables, ", "));
    }
  });
}

}  // namespace echoplan::cli
