// Graded observations: the class a performance was heard as, and how sure the classifier was.
//
// A hard label throws the classifier's confidence away: a strike heard as the mug with calibrated
// probability 0.45 and one heard as the mug with 0.99 are the same observation. A graded symbol
// keeps it: `mug@low`, `mug@mid` or `mug@high`, by the calibrated probability of the heard class
// (its confidence) against two edges per action, the terciles of the action's held-out confidences.
//
// The graded table is the label table times how the grades fall on right and wrong decisions:
//   P(h@g | c) = P(h | c) * P(g | right)   when h == c,
//              = P(h | c) * P(g | wrong)   otherwise,
// with P(g | right) and P(g | wrong) counted over all the action's held-out decisions, one
// pseudo-count per grade. Two rows of three numbers per action, so a few recordings per object
// suffice; the label table keeps its own calibration (smoothing, shrinkage) and the grades only
// split its cells. The `unknown` symbol (the reject option) is not graded.
//
// It is an ordinary discrete observation alphabet of kGrades times the classes (plus `unknown`):
// the problem file, the exact solver and `certify` take a graded problem as they take any other.
//
// Observations of kind `levels` are graded the same way by how noisy the recording was instead of
// how sure the classifier was: `mug@noisy`, `mug@fair` or `mug@clear`, by the event-to-background
// ratio measured from the recording (audio/levels.h) against the two cuts of the training
// recordings' ratios that best tell right readings from wrong (informative_edges()). A reading
// heard in noise is wrong more often, so P(noisy | wrong) > P(noisy | right): the table says a
// noisy reading tells less, and a planner listens again.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

namespace echoplan::perception {

// What an arm plans with: the heard class alone, or the class and its grade.
enum class ObservationKind { labels, graded, levels };
const char* observation_kind_name(ObservationKind kind);
const std::vector<std::string>& observation_kind_names();
// Throws InputError("observations '<name>' is not one of: labels, graded").
ObservationKind parse_observation_kind(const std::string& name);

inline constexpr int kGrades = 3;
// The grade names, least sure first; a `levels` grade's, noisiest first.
inline constexpr std::array<const char*, kGrades> kGradeNames{"low", "mid", "high"};
inline constexpr std::array<const char*, kGrades> kLevelNames{"noisy", "fair", "clear"};

// How an action's confidences become grades, and how often each grade comes with a right and a
// wrong decision.
struct GradeCalibration {
  // kGrades - 1 ascending confidences: grade g when edges[g - 1] <= confidence < edges[g].
  std::vector<double> edges;
  std::vector<double> given_right;  // P(grade | the heard class is the true one), sums to 1
  std::vector<double> given_wrong;  // P(grade | it is not), sums to 1
};

// The grade of `confidence` (0 = low).
int grade_of(const GradeCalibration& grades, double confidence);

// From an action's held-out decisions: their confidences (the calibrated probability of the heard
// class) and whether each was right. Rejected decisions are left out by the caller. Throws
// std::invalid_argument when the spans differ in length.
GradeCalibration fit_grades(std::span<const double> confidence, const std::vector<bool>& right);
// The kGrades - 1 edges that best tell the right decisions from the wrong ones: the cuts of the
// scores into kGrades bands of at least max(5, n/20) decisions each that maximise the likelihood of
// right and wrong under each band's own share right (cuts tried at up to 128 ranks). Levels are
// graded so: where the training set spans quiet and noisy recordings, terciles would spend two
// grades on the quiet ones. The terciles when no such cuts exist (fewer than 15 decisions, or too
// few distinct scores).
std::vector<double> informative_edges(std::span<const double> score,
                                      const std::vector<bool>& right);
// The same decisions graded with given edges (for a table fitted on some folds).
GradeCalibration fit_grades(std::span<const double> confidence, const std::vector<bool>& right,
                            std::vector<double> edges);

// The graded table from a label table [class][symbol] whose first num_classes symbols are the
// classes (and one more, `unknown`, when the model rejects): [class][graded symbol], rows sum to 1.
std::vector<std::vector<double>> graded_table(const std::vector<std::vector<double>>& labels,
                                              const GradeCalibration& grades, int num_classes);

// The graded symbols: "<class>@<grade>" for each class and grade (class-major), then "unknown"
// when `reject`; `kind` graded (confidence grades) or levels (level grades).
std::vector<std::string> graded_symbols(const std::vector<std::string>& classes, bool reject,
                                        ObservationKind kind = ObservationKind::graded);
// The index of (label symbol, grade) among graded_symbols: symbol * kGrades + grade for a class,
// the last one for `unknown` (symbol == num_classes).
int graded_symbol(int symbol, int grade, int num_classes);
// "<label>@<grade name>", a confidence grade's or (`kind` levels) a level grade's.
std::string graded_name(const std::string& label, int grade,
                        ObservationKind kind = ObservationKind::graded);
// The class a symbol names: "mug@high", "mug@noisy" and "mug" all name "mug".
std::string class_of_symbol(const std::string& symbol);

}  // namespace echoplan::perception
