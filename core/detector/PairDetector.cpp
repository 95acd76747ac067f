// PairDetector: history management around the partial-correlation kernel.
#include "core/detector/PairDetector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tactiscope::core::detector {
namespace {

// Samples handed to the kernel at once; also the history's extra room.
constexpr std::size_t kRun = 4096;

}  // namespace

PairDetector::PairDetector(const DetectorParameters& parameters, KernelVariant variant)
    : m_parameters(resolve(parameters)),
      m_variant(variant)
{
    if (!kernelVariantSupported(variant))
        throw std::invalid_argument(std::string("this CPU cannot run the ") + toString(variant) + " detector kernel");
    m_state.moments.assign(m_parameters.lags,
                           m_parameters.window == 0 ? m_parameters.forgetting : std::vector<double>{});
    m_historyBack = m_state.moments.largestLaneLag() + m_parameters.window;
    m_maxima.resize(kRun);
    m_scratch.resize(kernelScratchSize(m_state.moments, m_parameters.window));
    reset();
}

void PairDetector::reset()
{
    m_state.moments.zero();
    // Zero history: the detector sees silence before the first sample.
    m_state.historyA.assign(m_historyBack + kRun, 0.0);
    m_state.historyB.assign(m_historyBack + kRun, 0.0);
    m_state.position = m_historyBack;
    m_state.samplesProcessed = 0;
}

void PairDetector::restore(const Snapshot& snapshot)
{
    if (snapshot.moments.lag != m_state.moments.lag || snapshot.moments.forgetting != m_state.moments.forgetting ||
        snapshot.historyA.size() != m_state.historyA.size())
        throw std::invalid_argument("detector snapshot was taken with other parameters");
    m_state = snapshot;
}

void PairDetector::compactHistory()
{
    // Keep the newest m_historyBack samples at the front; room for kRun more.
    const auto keepFrom = static_cast<std::ptrdiff_t>(m_state.position - m_historyBack);
    std::copy(m_state.historyA.begin() + keepFrom,
              m_state.historyA.begin() + static_cast<std::ptrdiff_t>(m_state.position), m_state.historyA.begin());
    std::copy(m_state.historyB.begin() + keepFrom,
              m_state.historyB.begin() + static_cast<std::ptrdiff_t>(m_state.position), m_state.historyB.begin());
    m_state.position = m_historyBack;
}

void PairDetector::process(std::span<const double> a, std::span<const double> b, std::span<DetectorOutput> out)
{
    if (a.size() != b.size() || a.size() != out.size())
        throw std::invalid_argument("detector: a, b and output differ in length");
    KernelInput input;
    input.epsilonSquared = m_parameters.epsilonSquared;
    input.window = m_parameters.window;
    input.scratch = m_scratch.data();

    for (std::size_t done = 0; done < a.size();) {
        if (m_state.position + 1 > m_state.historyA.size()) compactHistory();
        const std::size_t n = std::min(a.size() - done, m_state.historyA.size() - m_state.position);
        double* ha = m_state.historyA.data() + m_state.position;
        double* hb = m_state.historyB.data() + m_state.position;
        std::copy_n(a.begin() + static_cast<std::ptrdiff_t>(done), n, ha);
        for (std::size_t i = 0; i < n; ++i) hb[i] = m_parameters.bSign * b[done + i];

        input.a = ha;
        input.b = hb;
        input.count = n;
        runPartialCorrelationKernel(m_variant, input, m_state.moments, m_maxima.data());

        for (std::size_t i = 0; i < n; ++i) {
            const SampleMaxima& m = m_maxima[i];
            DetectorOutput& o = out[done + i];
            o.rab = m.ab.r;
            o.rba = m.ba.r;
            o.lagAb = m.ab.lagIndex >= 0 ? m_parameters.lags[static_cast<std::size_t>(m.ab.lagIndex)] : 0;
            o.lagBa = m.ba.lagIndex >= 0 ? m_parameters.lags[static_cast<std::size_t>(m.ba.lagIndex)] : 0;
            o.decision = decide(o.rab, o.rba, m_parameters.threshold);
        }
        m_state.position += n;
        m_state.samplesProcessed += n;
        done += n;
    }
}

void PairDetector::currentCorrelations(std::span<double> rab, std::span<double> rba) const
{
    if (rab.size() != m_parameters.lags.size() || rba.size() != m_parameters.lags.size())
        throw std::invalid_argument("detector: correlation outputs must have one entry per lag");
    correlationsFromMoments(m_state.moments, m_parameters.window, m_parameters.epsilonSquared, rab.data(), rba.data());
}

}  // namespace tactiscope::core::detector
