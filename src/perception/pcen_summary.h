// The clip's mel spectrum after per-channel energy normalisation (audio/pcen.h), in the summary's
// four segments after the onset: what `pcen-lda` classifies, the front end the field uses against
// background noise beside the level-normalised summary (summary_features.h).
//
// Where the summary scales each clip to its loudest frame, so a louder background raises its floor,
// PCEN divides each band by the running average of that band's own past (0.4 s), so the background
// heard before the contact maps to about the same small value at any level and the event is
// described by how far each band rises above it: a band far above its background reads about 1/s
// (s the average's coefficient, 0.025) at the event's first frame whatever its level, so PCEN keeps
// where and how long each band rose rather than the spectrum's shape. The average starts at the
// clip's first sound (ClipAnalysis::first_sound_frame) as the mean energy of the frames before the
// onset: a recorder's leading digital silence is not a background.
//
// Layout (kPcenSummarySize = 104): the mean PCEN of each of the 26 psf mel bands over frames 0-3,
// 3-15, 15-50 and 50-150 after the onset (kSummarySegments; past the clip's end, its last frame).
// Energies are taken in 16-bit sample units (the psf filterbank energies x 2^30), so PCEN's eps
// sits below any recorded background and above digital silence.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "perception/clip_analysis.h"

namespace echoplan::perception {

inline constexpr std::size_t kPcenSummarySize = 104;

// The row of `clip` (psf features: 26 natural-log mel bands). InputError for another band count or
// a clip without frames.
std::vector<double> pcen_summary(const ClipAnalysis& clip);
// pcen0_band0 ... pcen3_band25.
std::vector<std::string> pcen_summary_names();

}  // namespace echoplan::perception
