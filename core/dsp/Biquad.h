// Second-order IIR sections and their cascade, the form every filter of
// the signal tools runs in (Butterworth low/high-pass, mains notches):
// sections in double precision keep a 4th-order low-pass at 1/500 of the
// sample rate as exact as the design, where one high-order polynomial
// would not be. The cascade runs in transposed direct form II and starts
// at the steady state of its first input, so a strain channel sitting at
// 300 µε does not ring for a second as the filter is switched on.
#pragma once

#include <complex>
#include <optional>
#include <span>
#include <vector>

namespace tactiscope::core::dsp {

// H(z) = (b0 + b1 z⁻¹ + b2 z⁻²) / (1 + a1 z⁻¹ + a2 z⁻²)
struct Biquad {
    double b0 = 1.0;
    double b1 = 0.0;
    double b2 = 0.0;
    double a1 = 0.0;
    double a2 = 0.0;

    // The response at `cycles` per sample (frequency / sample rate).
    std::complex<double> response(double cycles) const;
    // The gain for a constant input.
    double dcGain() const { return (b0 + b1 + b2) / (1.0 + a1 + a2); }
};

class BiquadCascade {
public:
    BiquadCascade() = default;
    explicit BiquadCascade(std::vector<Biquad> sections);

    const std::vector<Biquad>& sections() const { return m_sections; }
    bool empty() const { return m_sections.empty(); }

    // The next output. The first input after construction or reset() sets
    // every section's state to its steady state for that input.
    double process(double x);
    // Forgets the past: the next input starts the filter afresh (after a gap).
    void reset() { m_started = false; }
    // Where it stands: each section's two states, none before its first
    // input. A recording keeps its filters' at its first sample, so
    // re-analysis goes on from where the live filter stood.
    std::optional<std::vector<double>> state() const;
    // Goes on from a state() of the same sections, or afresh when none.
    // Throws std::invalid_argument for a state of another size.
    void setState(const std::optional<std::vector<double>>& state);

    std::complex<double> response(double cycles) const;
    // The group delay in samples at `cycles` per sample: −dφ/dω of the
    // whole cascade, from the phase's derivative computed exactly per section.
    double groupDelay_samples(double cycles) const;

private:
    void settle(double x);

    struct State {
        double s1 = 0.0;
        double s2 = 0.0;
    };
    std::vector<Biquad> m_sections;
    std::vector<State> m_state;
    bool m_started = false;
};

// Runs `cascade` forward over `values` and then backward over the result
// (zero phase, the magnitude squared), each pass starting at its first
// input's steady state. For review only: it needs the whole stretch.
void filterZeroPhase(BiquadCascade cascade, std::span<double> values);

}  // namespace tactiscope::core::dsp
