// Validation and sample-domain form of the detector parameters.
#include "core/detector/DetectorParameters.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tactiscope::core::detector {
namespace {

// Lags beyond this many samples make no physical sense for a hand scan and
// would only cost memory.
constexpr double kMaxLagSamples = 1e6;

bool positiveFinite(double value)
{
    return std::isfinite(value) && value > 0.0;
}

}  // namespace

std::vector<double> DetectorParameters::defaultLags_s()
{
    return lagRange_s(0.002, 0.150, 0.002);
}

std::vector<double> lagRange_s(double start_s, double stop_s, double step_s)
{
    if (!positiveFinite(start_s)) throw std::invalid_argument("lag range: start must be positive");
    if (!positiveFinite(step_s)) throw std::invalid_argument("lag range: step must be positive");
    if (!std::isfinite(stop_s) || stop_s < start_s)
        throw std::invalid_argument("lag range: stop must not be below start");
    const double count = std::floor((stop_s - start_s) / step_s + 1e-9 / step_s) + 1.0;
    if (count > kMaxLagSamples) throw std::invalid_argument("lag range: too many lags");
    std::vector<double> lags(static_cast<std::size_t>(count));
    // Each lag from its index, so rounding errors do not accumulate.
    for (std::size_t i = 0; i < lags.size(); ++i) lags[i] = start_s + static_cast<double>(i) * step_s;
    return lags;
}

double shortestJudged_s(const DetectorParameters& parameters)
{
    const double longestLag_s =
        parameters.lags_s.empty() ? 0.0 : *std::max_element(parameters.lags_s.begin(), parameters.lags_s.end());
    if (parameters.window_s) return longestLag_s + *parameters.window_s;
    const double lambda_s = parameters.lambdaRule == LambdaRule::EqualsLag ? longestLag_s : parameters.fixedLambda_s;
    return longestLag_s + 3.0 * lambda_s;
}

std::vector<double> liveLags_s(double sampleRate_hz)
{
    const double step_s = std::max(0.002, 1.0 / sampleRate_hz);
    return lagRange_s(step_s, 0.150, step_s);
}

ResolvedParameters resolve(const DetectorParameters& p)
{
    if (!positiveFinite(p.sampleInterval_s)) throw std::invalid_argument("sampling interval must be positive");
    if (p.lags_s.empty()) throw std::invalid_argument("the lag set is empty");
    if (!(std::isfinite(p.epsilon) && p.epsilon > 0.0)) throw std::invalid_argument("epsilon must be positive");
    if (!(std::isfinite(p.threshold) && p.threshold > 0.0 && p.threshold < 1.0))
        throw std::invalid_argument("threshold must lie between 0 and 1");
    if (p.lambdaRule == LambdaRule::Fixed && !positiveFinite(p.fixedLambda_s))
        throw std::invalid_argument("lambda must be positive");

    ResolvedParameters r;
    r.sampleInterval_s = p.sampleInterval_s;
    for (double lag_s : p.lags_s) {
        if (!positiveFinite(lag_s)) throw std::invalid_argument("lags must be positive");
        const double k = std::round(lag_s / p.sampleInterval_s);
        if (k < 1.0)
            throw std::invalid_argument("lag " + std::to_string(lag_s * 1e3) +
                                        " ms is shorter than half a sampling interval");
        if (k > kMaxLagSamples) throw std::invalid_argument("lag " + std::to_string(lag_s) + " s is too long");
        r.lags.push_back(static_cast<std::uint32_t>(k));
    }
    std::sort(r.lags.begin(), r.lags.end());
    r.lags.erase(std::unique(r.lags.begin(), r.lags.end()), r.lags.end());

    for (std::uint32_t k : r.lags) {
        const double lambda_s =
            p.lambdaRule == LambdaRule::EqualsLag ? static_cast<double>(k) * p.sampleInterval_s : p.fixedLambda_s;
        r.forgetting.push_back(std::exp(-p.sampleInterval_s / lambda_s));
    }
    if (p.window_s) {
        if (!positiveFinite(*p.window_s)) throw std::invalid_argument("window must be positive");
        const double h = std::round(*p.window_s / p.sampleInterval_s);
        if (h < 2.0) throw std::invalid_argument("window must span at least two samples");
        if (h > kMaxLagSamples) throw std::invalid_argument("window is too long");
        r.window = static_cast<std::uint32_t>(h);
    }
    r.epsilonSquared = p.epsilon * p.epsilon;
    r.threshold = p.threshold;
    r.bSign = p.faceToFace ? -1.0 : 1.0;
    return r;
}

}  // namespace tactiscope::core::detector
