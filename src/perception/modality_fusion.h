// Fusing several modalities' class log-scores into one calibrated probability (ObservationModel
// fitted on sessions).
//
// The fused log-score of class c is sum_m w_m * s_m(c), and P(c) = softmax of it: a weighted
// product of the modalities' tempered likelihoods (stacking with one weight per modality; a single
// modality's weight is its inverse temperature). The weights, w_m >= 0, minimise the mean negative
// log-likelihood of the true classes on held-out scores; the objective is convex in w, and the
// search (projected Newton with backtracking, started at the best single modality with its fitted
// temperature) only accepts steps that lower it, so the fused result is never worse on those
// scores than the best modality alone. A modality that carries no information gets a weight near
// 0, where naive equal weights would let its noise blur the informative ones.
#pragma once

#include <span>
#include <vector>

namespace echoplan::perception {

// scores[m][i]: modality m's log-scores (one per class) for example i; every modality scores the
// same examples.
using ModalityScores = std::vector<std::vector<std::vector<double>>>;

struct Fusion {
  std::vector<double> weights;  // one per modality, >= 0
  double mean_nll = 0.0;        // of the true classes under the fused probabilities
};

// sum_m weights[m] * scores[m] for one example (scores[m] is one modality's log-scores).
std::vector<double> fuse(const std::vector<std::vector<double>>& scores,
                         const std::vector<double>& weights);

// Mean NLL of `labels` under softmax(fused log-scores) with `weights`.
double fused_mean_nll(const ModalityScores& scores, std::span<const int> labels,
                      const std::vector<double>& weights);

// The weights as above. Requires at least one modality and one example (std::invalid_argument).
Fusion fit_fusion(const ModalityScores& scores, std::span<const int> labels);

}  // namespace echoplan::perception
