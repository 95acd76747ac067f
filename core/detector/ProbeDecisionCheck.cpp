// ProbeDecisionCheck: the probe's decisions beside the workstation's.
#include "core/detector/ProbeDecisionCheck.h"

#include "core/SampleBlock.h"
#include "core/detector/DefectOrder.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::detector {
std::optional<ProbeDecisionChannels> probeDecisionChannels(const std::vector<ChannelDescriptor>& channels)
{
    std::optional<std::size_t> out, rab, rba, lagAb, lagBa;
    for (std::size_t i = 0; i < channels.size(); ++i) {
        if (channels[i].kind != ChannelKind::Decision) continue;
        if (channels[i].name == "out") out = i;
        if (channels[i].name == "rab") rab = i;
        if (channels[i].name == "rba") rba = i;
        if (channels[i].name == "lag_ab") lagAb = i;
        if (channels[i].name == "lag_ba") lagBa = i;
    }
    if (!out || !rab || !rba) return std::nullopt;
    return ProbeDecisionChannels{*out, *rab, *rba, lagAb, lagBa};
}

std::string agreementText(const ProbeAgreement& agreement)
{
    return "probe and workstation agree on " + std::to_string(agreement.agreeing) + " of " +
           std::to_string(agreement.compared) + (agreement.compared == 1 ? " decision" : " decisions");
}

int probeDecisionOf(double value)
{
    return value > 0.5 && value < 1.5 ? 1 : value < -0.5 && value > -1.5 ? -1 : 0;
}

std::string ProbeDisagreement::text() const
{
    return std::string("the probe's detector and the workstation's disagree: the probe says ") +
           defectOrderText(probe) + ", the workstation " + defectOrderText(workstation) + " (for " +
           std::to_string(ProbeDecisionCheck::kLastingSamples) +
           " samples or more; check the probe's firmware and its detector's settings)";
}

ProbeDecisionCheck::ProbeDecisionCheck(ProbeDecisionChannels channels, double sampleInterval_s, double hold_s,
                                       std::optional<double> spacing_m)
    : m_channels(channels),
      m_sampleInterval_s(sampleInterval_s),
      m_segmenter(hold_s, spacing_m),
      m_warmUp(static_cast<std::uint64_t>(std::ceil(kWarmUp_s / sampleInterval_s)))
{
}

void ProbeDecisionCheck::push(const SampleBlock& block, std::size_t s, const DetectorOutput& workstation,
                              std::vector<DefectEvent>& probeEvents, std::vector<ProbeDisagreement>& disagreements)
{
    // The probe's word: a decision that is no −1, 0 or +1 (a garbled
    // channel) counts as none.
    const int probe = probeDecisionOf(block.value(m_channels.out, s));
    DetectorOutput probeOutput;
    probeOutput.decision = static_cast<std::int8_t>(probe);
    probeOutput.rab = block.value(m_channels.rab, s);
    probeOutput.rba = block.value(m_channels.rba, s);
    // Its lags in samples, from seconds; a value that is no lag (negative,
    // NaN, beyond a minute) is none.
    const auto lagOf = [&](const std::optional<std::size_t>& channel) -> std::uint32_t {
        if (!channel) return 0;
        const double samples = std::round(block.value(*channel, s) / m_sampleInterval_s);
        return samples >= 1.0 && samples * m_sampleInterval_s <= 60.0 ? static_cast<std::uint32_t>(samples) : 0;
    };
    probeOutput.lagAb = lagOf(m_channels.lagAb);
    probeOutput.lagBa = lagOf(m_channels.lagBa);
    m_segmenter.push(block.timeAt_s(s), probeOutput, m_sampleInterval_s, probeEvents);
    if (++m_sinceStart <= m_warmUp) return;
    ++m_agreement.compared;
    if (probe == workstation.decision) {
        ++m_agreement.agreeing;
        m_run = 0;
        m_told = false;
        return;
    }
    if (++m_run < kLastingSamples || m_told) return;
    m_told = true;
    const double start_s = block.timeAt_s(s) - static_cast<double>(m_run - 1) * m_sampleInterval_s;
    disagreements.push_back({start_s, probe, workstation.decision});
}

void ProbeDecisionCheck::restart(std::vector<DefectEvent>& probeEvents)
{
    m_segmenter.finish(probeEvents);
    m_segmenter.reset();
    m_sinceStart = 0;
    m_run = 0;
    m_told = false;
}

}  // namespace tactiscope::core::detector
