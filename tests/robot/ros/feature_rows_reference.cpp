// Helper of the ros_haptic test (not a test by itself): the expected side, computed in process.
//   feature_rows_reference classify MODEL PUBLISHED
//       what the model makes of each performance a stand-in robot published (PUBLISHED:
//       `performance,behaviour,modality,value...` per row, haptic_robot_stand_in.py), straight from
//       ObservationModel::classify_rows with the rows in the model's modality order. One line per
//       performance: `behaviour label unknown probability class=p...` (%.17g: the exact doubles);
//   feature_rows_reference trial-seed SEED
//       the seed of trial 0 of `echoplan_planner _seed:=SEED _object:=...` (`echoplan run`'s trial
//       stream), so `echoplan run --data --seed` replays the session with the same streams.
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/file_io.h"
#include "loop/streams.h"
#include "perception/observation_model.h"

namespace {

using namespace echoplan;

struct Performance {
  std::string behaviour;
  std::map<std::string, std::vector<double>> rows;  // modality -> values
};

std::vector<Performance> read_published(const std::string& path) {
  std::vector<Performance> performances;
  std::istringstream lines(read_text_file(path, "the published rows"));
  std::string performance_id;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::vector<std::string> cell;
    for (std::string c; std::getline(cells, c, ',');) cell.push_back(c);
    if (cell.size() < 4) throw InputError(path, 0, "a line with fewer than 4 cells: " + line);
    if (performances.empty() || cell[0] != performance_id) performances.push_back({cell[1], {}});
    performance_id = cell[0];
    std::vector<double>& values = performances.back().rows[cell[2]];
    for (std::size_t i = 3; i < cell.size(); ++i) values.push_back(std::stod(cell[i]));
  }
  return performances;
}

int classify(const std::string& model_path, const std::string& published) {
  const perception::ObservationModel model = perception::load_observation_model(model_path);
  for (const Performance& p : read_published(published)) {
    std::vector<std::span<const double>> rows;
    for (const perception::ModalityModel& m : model.modalities(p.behaviour))
      rows.emplace_back(p.rows.at(m.name));
    const perception::Prediction prediction =
        model.classify_rows(model.action_index(p.behaviour), rows);
    std::printf("%s %s %d %.17g", p.behaviour.c_str(), prediction.label.c_str(),
                prediction.unknown ? 1 : 0,
                prediction.probabilities[static_cast<std::size_t>(prediction.best_class)]);
    for (std::size_t k = 0; k < model.classes().size(); ++k)
      std::printf(" %s=%.17g", model.classes()[k].c_str(), prediction.probabilities[k]);
    std::printf("\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "classify" && argc == 4) return classify(argv[2], argv[3]);
    if (mode == "trial-seed" && argc == 3) {
      std::printf("%llu\n", static_cast<unsigned long long>(
                                loop::stream_seed(std::stoull(argv[2]), loop::Stream::run_trial)));
      return 0;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "feature_rows_reference: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr,
               "usage: feature_rows_reference classify MODEL PUBLISHED | trial-seed SEED\n");
  return 2;
}
