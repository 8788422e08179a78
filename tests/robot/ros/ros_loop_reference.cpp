// Helper of the ros_* tests (not a test by itself):
//   ros_loop_reference prepare DIR
//       trains a small observation model on simulated recordings (DIR/model.json) and writes the
//       shipped problem with that model's calibrated table (DIR/problem.yaml) and with its table
//       graded by the recordings' levels (DIR/problem-levels.yaml);
//   ros_loop_reference run DIR OUT sim|mic SEED EPISODES TRIALS [MAX_SECONDS]
//       runs the loop in process - the simulated arm, the simulated microphone (sim) or PortAudio
//       on the default capture device (mic, recording exactly MAX_SECONDS per action), the
//       classifier - through the same run_loop_trials as echoplan_planner, writing
//       OUT/loop_steps.csv: the log the ROS run must reproduce.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "../../common/source_dir.h"
#include "loop/calibrated_problem.h"
#include "loop/object_problem.h"
#include "loop/robot_world.h"
#include "loop_trials.h"
#include "perception/observation_model.h"
#include "pomdp/problem.h"
#include "robot/classifier_service.h"
#include "robot/portaudio_recorder.h"
#include "robot/simulated_world.h"
#include "small_training_set.h"

namespace {

using namespace echoplan;

int prepare(const std::string& dir) {
  const pomdp::Problem base =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  const auto& data = loop::object_problem(*base.model).data();
  const auto model = testing::train_small_model(data.objects, {"slide", "strike"}, 3);
  perception::save_observation_model(*model, dir + "/model.json");
  loop::save_problem(*loop::calibrate_problem(base, *model), dir + "/problem.yaml");
  loop::save_problem(
      *loop::calibrate_problem(base, *model, "", perception::ObservationKind::levels),
      dir + "/problem-levels.yaml");
  return 0;
}

int run(int argc, char** argv) {
  const std::string dir = argv[2];
  ros_app::LoopTrialSettings settings;
  settings.problem = dir + "/problem.yaml";
  settings.out = argv[3];
  const std::string source = argv[4];
  settings.seed = std::stoull(argv[5]);
  settings.episodes = std::stoll(argv[6]);
  settings.trials = std::stoi(argv[7]);
  const pomdp::Problem problem = pomdp::load_problem(settings.problem);
  const auto& data = loop::object_problem(*problem.model).data();
  std::vector<std::string> sorting;
  sorting = data.sorting;
  auto world = std::make_shared<robot::SimulatedWorld>(testing::shipped_catalogue(),
                                                       sim::SimConfig{}, sorting);
  loop::RobotParts parts;
  parts.robot = std::make_unique<robot::SimulatedArm>(world);
  if (source == "mic") {
    robot::CaptureConfig capture;
    capture.max_seconds = argc > 8 ? std::stod(argv[8]) : 1.0;
    // The tests' device reads a file faster than real time: only a recording that runs to its
    // limit has a length that does not depend on when the arm answered (the listener is run
    // with the same ~min_seconds).
    capture.min_seconds = capture.max_seconds;
    parts.recorder = std::make_unique<robot::PortAudioRecorder>(capture);
  } else {
    parts.recorder = std::make_unique<robot::SimulatedMicrophone>(world);
  }
  parts.service = std::make_unique<robot::ClassifierService>(
      std::make_shared<const perception::ObservationModel>(
          perception::load_observation_model(dir + "/model.json")));
  ros_app::run_loop_trials(settings, std::move(parts),
                           [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "prepare" && argc == 3) return prepare(argv[2]);
  if (mode == "run" && argc >= 8) return run(argc, argv);
  std::fprintf(stderr,
               "usage: ros_loop_reference prepare DIR | run DIR OUT sim|mic SEED EPISODES TRIALS "
               "[MAX_SECONDS]\n");
  return 2;
}
