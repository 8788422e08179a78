// The model file: a round trip keeps every decision, and every broken file is an error naming the
// file and the field.
#include "perception/observation_model_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "../common/source_dir.h"
#include "common/error.h"
#include "trained_model.h"

namespace echoplan::perception {
namespace {

namespace fs = std::filesystem;
using test_model::analysed;
using test_model::recording;
using test_model::trained;
using ::testing::HasSubstr;

TEST(ObservationModelJson, RoundTripsThroughTheFile) {
  const ObservationModel& model = trained().model;
  const fs::path file = trained().dir / "model.json";
  save_observation_model(model, file.string());
  const ObservationModel back = load_observation_model(file.string());
  EXPECT_EQ(observation_model_to_json(back), observation_model_to_json(model));
  const ClipAnalysis clip = analysed(model, recording(1, 777));
  const Prediction a = model.classify(clip, "tap"), b = back.classify(clip, "tap");
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.probabilities, b.probabilities);
  EXPECT_EQ(a.distance, b.distance);
}

TEST(ObservationModelJson, RecordsTheTableEstimateAndReadsOldFilesAsCounts) {
  EXPECT_EQ(observation_model_to_json(trained().model)["table_estimate"], "counts");
  FitOptions options;
  options.table = TableEstimate::soft;
  const ObservationModel soft = train_observation_model(trained().set, options);
  const fs::path file = trained().dir / "soft.json";
  save_observation_model(soft, file.string());
  const ObservationModel back = load_observation_model(file.string());
  EXPECT_EQ(back.table_estimate(), TableEstimate::soft);
  EXPECT_EQ(observation_model_to_json(back), observation_model_to_json(soft));
  // A file written before the option existed had a counts table.
  nlohmann::json old = observation_model_to_json(trained().model);
  old.erase("table_estimate");
  EXPECT_EQ(observation_model_from_json(old, "old.json").table_estimate(), TableEstimate::counts);
}

// The lookalike shares and the tables they mix round-trip; a file written before the shares has
// none, one written before the choice of tables mixes the tempered ones; a file written when the
// class-blind `atypical_share` existed reads as ever, without it.
TEST(ObservationModelJson, KeepsTheLookalikeSharesAndReadsOldFilesAsNone) {
  nlohmann::json doc = observation_model_to_json(trained().model);
  doc["lookalike_share"] = {{"labels", 0.0625}, {"graded", 0.375}};
  doc["lookalike_tables"] = {{"labels", "untempered"}, {"graded", "tempered"}};
  const ObservationModel model = observation_model_from_json(doc, "shares.json");
  EXPECT_EQ(model.lookalike_share(ObservationKind::labels), 0.0625);
  EXPECT_EQ(model.lookalike_share(ObservationKind::graded), 0.375);
  EXPECT_TRUE(model.lookalikes_untempered(ObservationKind::labels));
  EXPECT_FALSE(model.lookalikes_untempered(ObservationKind::graded));
  nlohmann::json before_tables = doc;
  before_tables.erase("lookalike_tables");
  EXPECT_FALSE(observation_model_from_json(before_tables, "before.json")
                   .lookalikes_untempered(ObservationKind::labels));
  EXPECT_EQ(observation_model_to_json(model), doc);
  nlohmann::json with_atypical = doc;
  with_atypical["atypical_share"] = {{"labels", 0.125}, {"graded", 0.25}};
  EXPECT_EQ(observation_model_to_json(observation_model_from_json(with_atypical, "older.json")),
            doc);
  doc.erase("lookalike_share");
  const ObservationModel old = observation_model_from_json(doc, "old.json");
  EXPECT_EQ(old.lookalike_share(ObservationKind::labels), 0.0);
  EXPECT_EQ(old.lookalike_share(ObservationKind::graded), 0.0);
}

// tests/data/perception/seed_gaussian_model.json was written when report-gaussian was called
// seed-gaussian: it loads under the current name, and saves with it.
TEST(ObservationModelJson, ReadsAnOldClassifierNameAsTheCurrentOne) {
  const ObservationModel old = load_observation_model(
      echoplan::testing::source_dir() + "/tests/data/perception/seed_gaussian_model.json");
  EXPECT_EQ(old.classifier_name(), "report-gaussian");
  for (const std::string action : {"slide", "strike"})
    EXPECT_EQ(old.classifier(action).name(), "report-gaussian");
  EXPECT_EQ(observation_model_to_json(old)["classifier"], "report-gaussian");
}

// A version 1 file (one classifier per action beside its calibration, no modalities or weights)
// loads as one audio modality of weight 1 and classifies exactly as the model it was written from.
TEST(ObservationModelJson, ReadsVersionOneFiles) {
  const ObservationModel& model = trained().model;
  nlohmann::json v1 = observation_model_to_json(model);
  v1["version"] = 1;
  for (auto& [action, entry] : v1["per_action"].items()) {
    nlohmann::json fit = entry["modalities"][0]["classifier"];
    fit["summary_size"] = fit["features"];  // version 1's summary-lda wrote no mean
    fit.erase("features");
    fit.erase("mean");
    entry["classifier"] = fit;
    entry.erase("modalities");
    entry.erase("weights");
  }
  const ObservationModel old = observation_model_from_json(v1, "v1.json");
  EXPECT_EQ(observation_model_to_json(old), observation_model_to_json(model));
  ASSERT_EQ(old.modalities("tap").size(), 1u);
  EXPECT_EQ(old.modalities("tap")[0].name, "audio");
  EXPECT_EQ(old.weights("tap"), std::vector<double>{1.0});
  const ClipAnalysis clip = analysed(model, recording(2, 778));
  EXPECT_EQ(old.classify(clip, "tap").probabilities, model.classify(clip, "tap").probabilities);
}

TEST(ObservationModelJson, WithoutRejectTheThresholdIsNull) {
  FitOptions options;
  options.reject = false;
  const ObservationModel model = train_observation_model(trained().set, options);
  nlohmann::json doc = observation_model_to_json(model);
  EXPECT_TRUE(doc["per_action"]["strike"]["reject_threshold"].is_null());
  EXPECT_EQ(doc["per_action"]["strike"]["symbols"].size(), 3u);
  const ObservationModel back = observation_model_from_json(doc, "m.json");
  EXPECT_FALSE(back.reject());
  EXPECT_TRUE(std::isinf(back.calibration("strike").reject_threshold));
  doc["per_action"]["strike"]["reject_threshold"] = 2.0;
  try {
    observation_model_from_json(doc, "m.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "m.json: per_action.strike.reject_threshold: must be null when reject is false");
  }
}

TEST(ObservationModelJson, EveryBrokenModelFileIsAClearError) {
  const nlohmann::json good = observation_model_to_json(trained().model);
  const fs::path file = trained().dir / "broken.json";
  auto expect_error = [&](const std::string& text, const std::string& fragment) {
    std::ofstream(file, std::ios::trunc) << text;
    try {
      load_observation_model(file.string());
      ADD_FAILURE() << "no error; expected " << fragment;
    } catch (const InputError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(file.string()));
      EXPECT_THAT(std::string(e.what()), HasSubstr(fragment));
    }
  };
  const std::string text = good.dump();
  expect_error(text.substr(0, text.size() / 2), "not a valid JSON model file");
  expect_error("", "not a valid JSON model file");
  expect_error("[1, 2]", "expected a JSON object");
  expect_error("{\"version\": 8.5e6666666}", "not a valid JSON model file");  // found by the fuzzer
  auto with = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json doc = good;
    change(doc);
    return doc.dump();
  };
  expect_error(with([](auto& d) { d["version"] = 3; }),
               "version 3 is not supported (this build reads versions 1 to 2); retrain with "
               "`echoplan train --data DIR --out MODEL`");
  expect_error(with([](auto& d) { d["version"] = 0; }), "version 0 is not supported");
  expect_error(with([](auto& d) { d["format"] = "other"; }), "not an observation model");
  expect_error(with([](auto& d) { d.erase("classes"); }), "classes: missing");
  expect_error(with([](auto& d) { d["lookalike_share"]["graded"] = 0.9; }),
               "lookalike_share.graded: 0.9 is not in [0, 0.5]");
  expect_error(with([](auto& d) { d["lookalike_share"].erase("labels"); }),
               "lookalike_share.labels: missing");
  expect_error(with([](auto& d) { d["lookalike_share"]["labels"] = -0.1; }),
               "lookalike_share.labels: -0.1 is not in [0, 0.5]");
  expect_error(with([](auto& d) { d["lookalike_tables"]["graded"] = "raw"; }),
               "lookalike_tables.graded: 'raw' is not one of: tempered, untempered");
  expect_error(with([](auto& d) { d["lookalike_tables"].erase("labels"); }),
               "lookalike_tables.labels: missing");
  expect_error(with([](auto& d) { d["classifier"] = "magic"; }),
               "classifier: 'magic' is neither an audio preset");
  expect_error(with([](auto& d) { d["analysis"]["sample_rate"] = 5; }), "analysis.sample_rate");
  expect_error(with([](auto& d) { d["analysis"]["preset"] = "nope"; }), "unknown feature preset");
  expect_error(with([](auto& d) { d["classes"][1] = d["classes"][0]; }), "appears twice");
  expect_error(with([](auto& d) { d["per_action"].erase("tap"); }), "per_action");
  expect_error(with([](auto& d) { d["per_action"]["tap"]["table"][0][0] = 0.9; }),
               "per_action.tap.table[0]: probabilities sum to");
  expect_error(with([](auto& d) { d["per_action"]["tap"]["confusion"][1][1] = -2; }),
               "per_action.tap.confusion");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["temperature"] = 0; }),
               "per_action.strike.temperature");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["reject_threshold"] = nullptr; }),
               "reject_threshold");
  expect_error(with([](auto& d) {
                 d["per_action"]["strike"]["modalities"][0]["classifier"]["scale"].erase(0);
               }),
               "per_action.strike.modalities[0].classifier.scale: expected 123 numbers");
  expect_error(with([](auto& d) {
                 d["per_action"]["strike"]["modalities"][0]["classifier"]["class_means"].erase(0);
               }),
               "fitted for 2 classes");
  expect_error(
      with([](auto& d) { d["per_action"]["strike"]["modalities"] = nlohmann::json::array(); }),
      "per_action.strike.modalities: expected 1 to 1000 modalities");
  expect_error(
      with([](auto& d) { d["per_action"]["strike"]["modalities"][0]["extractor"] = "mfcc"; }),
      "per_action.strike.modalities[0].extractor: the 'summary-lda' preset computes its "
      "rows with 'summary'");
  expect_error(with([](auto& d) {
                 d["per_action"]["strike"]["weights"] = {1.0, 2.0};
               }),
               "per_action.strike.weights: expected 1 numbers");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["weights"] = {-1.0}; }),
               "per_action.strike.weights: must be >= 0");
  expect_error(with([](auto& d) { d["per_action"]["strike"]["symbols"][3] = "nothing"; }),
               "per_action.strike.symbols");
  expect_error(with([](auto& d) { d["table_estimate"] = "hard"; }),
               "table_estimate: table estimate 'hard' is not one of: counts, soft, shrunk");
  expect_error(with([](auto& d) { d["table_estimate"] = 3; }), "table_estimate");
  // 100,000 nested arrays (200 KB): refused at the parse (common/json_parse.h), before the reader
  // sees a value that would overflow the stack if it were copied.
  expect_error(R"({"per_action": )" + std::string(100'000, '[') + std::string(100'000, ']') + "}",
               "nested deeper than");
  try {
    load_observation_model((trained().dir / "missing.json").string());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("cannot open"));
  }
}

}  // namespace
}  // namespace echoplan::perception
