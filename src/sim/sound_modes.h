// The modal bank: renders damped resonators (the object's, the table's and the wall's dense band)
// driven by impulses (impacts) and by a shared continuous excitation (friction).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "sim/modal_model.h"

namespace echoplan::sim {

// Dipole radiation (a compact body's, rising with frequency) is normalised to 1 at this frequency.
inline constexpr double kReferenceHz = 1000.0;
// ln(1e4): a mode is rendered until it fell by 80 dB (below the noise floor).
inline constexpr double kTailDecay = 9.2;

// One mode's excitation: impulses at given samples plus (optionally) a shared continuous drive.
struct ModeDrive {
  std::vector<std::pair<std::size_t, double>> impulses;  // (sample, amplitude)
  double continuous_gain = 0;                            // times the friction excitation
};

// Renders `modes` driven by `drives` into `out` (added). Each mode is the resonator
// y[n] = 2 r cos(w) y[n-1] - r^2 y[n-2] + sin(w) x[n] (impulse response r^n sin(w (n + 1))), from
// its first excitation until kTailDecay below its last. Modes run four at a time in one loop: the
// recursions are independent, so the processor overlaps them (one alone waits on its own latency).
// `friction_span` is [first, last] sample where the friction excitation is non-zero (first > last:
// none).
void render_modes(const std::vector<Mode>& modes, const std::vector<ModeDrive>& drives,
                  const std::vector<float>& friction,
                  std::pair<std::size_t, std::size_t> friction_span,
                  const std::vector<std::size_t>& friction_active, int rate,
                  std::vector<float>& out);

// Pressure amplitude factor of a plate's radiation at `frequency_hz` (1 above `coincidence_hz`):
// below its coincidence frequency a finite plate radiates through its edges and corners only, with
// an efficiency rising about as f / f_c (Maidanik 1962): pressure as its square root.
double plate_radiation(double frequency_hz, double coincidence_hz);

// Renders every bank (modes, drives) into `out` (added), the banks' continuous drives all times
// the same `friction` excitation (audio rate, zero where nothing slides).
void render_mode_banks(
    const std::vector<std::pair<const std::vector<Mode>*, const std::vector<ModeDrive>*>>& banks,
    const std::vector<float>& friction, int rate, std::vector<float>& out);

}  // namespace echoplan::sim
