// Simulated panel scan (seed 000): a two-cantilever viscous-capsule probe
// moved back and forth by hand over pressed sheet metal with one surface
// deflection, giving two strain channels "a" and "b".
//
// Model, deliberately simple but with the features the detector must face:
// - probe position x(t) = X·sin(2π f t): the paper's ~200 mm stroke at ~0.5 Hz;
// - cantilever A sits at x, B at x − spacing, so moving towards +x A meets the
//   deflection first (A then B), and moving back B meets it first;
// - the surface is flat but for a Gaussian dent of given depth and width; a
//   cantilever is bent by changes of the surface inclination under it, and the
//   viscous capsule adapts: its strain is the inclination high-passed with the
//   adaptation time constant (the paper's "responds only to temporal change");
// - the fluid's inertia adds a strain proportional to the probe acceleration,
//   common to both cantilevers (the paper's Fig. 6 shows it at reversals);
// - on a panel line, a rest between panels: x(t) = −X·cos(2π f t) for one
//   stroke (from a reversal, so the probe stops where it is at rest), then
//   x = −X, still, until the next panel;
// - independent white Gaussian noise on each gauge;
// - face-to-face gauges invert the sign of b, as in the paper's prototype;
// - optionally the probe's centre, x_A − spacing/2, as an encoder gives it.
#pragma once

#include "devices/simulator/GaussianNoise.h"
#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <vector>

namespace tactiscope::devices::simulator {

struct PanelScanParameters {
    double sampleRate_hz = 500.0;        // the paper's Δt = 2 ms
    double strokeAmplitude_m = 0.100;    // half of the ~200 mm stroke; 0: the probe at rest
    double strokeFrequency_hz = 0.5;     // "slow movement"
    double cantileverSpacing_m = 0.015;  // the prototype's 15 mm
    bool hasDefect = true;
    double defectPosition_m = 0.030;    // from the stroke centre
    std::vector<double> moreDefects_m;  // further dents like the first, at these places
    double defectDepth_m = 50e-6;
    double defectWidth_m = 0.004;    // Gaussian σ of the dent profile
    double strainPerRadian = 4e-3;   // inclination change → gauge strain
    double adaptationTime_s = 0.15;  // capsule relaxation time constant
    double strainPerAcceleration_s2_per_m = 1e-5;
    double noiseSigma = 0.5e-6;  // strain, per gauge
    bool faceToFace = false;
    // A panel line (0: one panel stroked back and forth for ever): each
    // panel is stroked once, from one end of the stroke over the dent to the
    // other end and back, then the probe rests there, lifted, this long
    // while the next panel comes.
    double restBetweenPanels_s = 0.0;
    // A third channel "x" [m], the role `position`: the probe's centre along
    // the stroke, as a line's encoder gives it (midway between A and B).
    bool positionChannel = false;
    std::uint64_t seed = 1;
};

class PanelScanScenario final : public SimulatedScenario {
public:
    // Throws std::invalid_argument for non-physical parameters.
    explicit PanelScanScenario(const PanelScanParameters& parameters = {});

    std::string name() const override
    {
        return m_p.strokeAmplitude_m == 0.0    ? "panel probe at rest"
               : m_p.restBetweenPanels_s > 0.0 ? "panel line"
                                               : "panel scan";
    }
    std::optional<core::Mode> mode() const override { return core::Mode::PanelScan; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double sampleRate_hz() const override { return m_p.sampleRate_hz; }
    void generate(core::SampleBlock& block) override;

    const PanelScanParameters& parameters() const { return m_p; }
    // Probe (cantilever A) position at time t, in metres from the stroke
    // centre, and its acceleration.
    double probePosition_m(double t_s) const;
    double probeAcceleration_m_s2(double t_s) const;

private:
    double inclination_rad(double x_m) const;

    PanelScanParameters m_p;
    std::vector<core::ChannelDescriptor> m_channels;
    GaussianNoise m_noiseA;
    GaussianNoise m_noiseB;
    double m_decay;  // per-sample factor of the capsule's high-pass, exp(−Δt/τ)
    std::uint64_t m_nextSample = 0;
    double m_lastInclinationA = 0.0;
    double m_lastInclinationB = 0.0;
    double m_bendA = 0.0;
    double m_bendB = 0.0;
};

}  // namespace tactiscope::devices::simulator
