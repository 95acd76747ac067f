// FirmwarePairDetector: the probe kernel's C state behind a C++ pair detector.
#include "core/detector/FirmwarePairDetector.h"

#include "probe_detector.h"

#include <stdexcept>
#include <string>

namespace tactiscope::core::detector {

struct FirmwarePairDetector::State {
    pd_detector detector{};
};

std::size_t FirmwarePairDetector::mostLags()
{
    return PD_MAX_LAGS;
}

std::size_t FirmwarePairDetector::longestLag()
{
    return PD_MAX_LAG_SAMPLES;
}

ProbeLags FirmwarePairDetector::probeLags(const DetectorParameters& parameters)
{
    if (parameters.window_s) throw std::invalid_argument("the probe's detector has the exponential form only");
    const ResolvedParameters resolved = resolve(parameters);
    if (resolved.lags.size() > mostLags() || resolved.maxLag() > longestLag())
        throw std::invalid_argument("the probe's detector holds at most " + std::to_string(mostLags()) +
                                    " lags of up to " + std::to_string(longestLag()) + " samples; these are " +
                                    std::to_string(resolved.lags.size()) + " up to " +
                                    std::to_string(resolved.maxLag()));
    ProbeLags result;
    for (const std::uint32_t k : resolved.lags) {
        result.lags.push_back(static_cast<unsigned short>(k));
        // λ as resolve() takes it: c = k·Δt for the paper's rule.
        result.lambda_s.push_back(parameters.lambdaRule == LambdaRule::EqualsLag
                                      ? static_cast<double>(k) * parameters.sampleInterval_s
                                      : parameters.fixedLambda_s);
    }
    return result;
}

FirmwarePairDetector::FirmwarePairDetector(const DetectorParameters& parameters)
    : m_state(std::make_unique<State>())
{
    const ProbeLags lags = probeLags(parameters);
    const pd_config config{parameters.sampleInterval_s,
                           static_cast<unsigned>(lags.lags.size()),
                           lags.lags.data(),
                           lags.lambda_s.data(),
                           parameters.epsilon,
                           parameters.threshold,
                           parameters.faceToFace ? 1 : 0};
    if (const int refused = pd_init(&m_state->detector, &config); refused != PD_OK)
        throw std::invalid_argument("the probe's detector refuses these settings (code " + std::to_string(refused) +
                                    ")");
}

FirmwarePairDetector::~FirmwarePairDetector() = default;
FirmwarePairDetector::FirmwarePairDetector(FirmwarePairDetector&&) noexcept = default;
FirmwarePairDetector& FirmwarePairDetector::operator=(FirmwarePairDetector&&) noexcept = default;

void FirmwarePairDetector::process(std::span<const double> a, std::span<const double> b, std::span<DetectorOutput> out)
{
    if (a.size() != b.size() || a.size() != out.size())
        throw std::invalid_argument("detector: a, b and output differ in length");
    for (std::size_t i = 0; i < a.size(); ++i) {
        pd_output o;
        pd_step(&m_state->detector, static_cast<float>(a[i]), static_cast<float>(b[i]), &o);
        out[i] = {o.decision, o.rab, o.rba, o.lag_ab, o.lag_ba};
    }
}

void FirmwarePairDetector::reset()
{
    pd_reset(&m_state->detector);
}

}  // namespace tactiscope::core::detector
