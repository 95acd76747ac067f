// Serial-Plotter style line parsing.
#include "devices/protocol/TextDecoder.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace tactiscope::devices::protocol {

void TextDecoder::reset()
{
    m_line.clear();
    m_overlong = false;
    m_names.clear();
    m_labels.clear();
    m_candidate.reset();
    m_candidateLabels.clear();
    m_counters = {};
}

void TextDecoder::push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<TextSample>& out)
{
    m_counters.bytes += bytes.size();
    for (const std::uint8_t byte : bytes) {
        if (byte == '\n') {
            if (m_overlong) {
                ++m_counters.linesSkipped;
                if (!m_labels.empty()) out.push_back({hostTime_s, {}});  // a hole, as any unreadable line
            } else
                parseLine(hostTime_s, out);
            m_line.clear();
            m_overlong = false;
        } else if (!m_overlong) {
            if (m_line.size() >= kMaxLine)
                m_overlong = true;
            else
                m_line.push_back(static_cast<char>(byte));
        }
    }
}

void TextDecoder::parseLine(double hostTime_s, std::vector<TextSample>& out)
{
    std::vector<std::string> labels;
    TextSample sample{hostTime_s, {}};
    bool empty = true;
    bool ok = true;
    std::size_t i = 0;
    const auto separator = [](char c) { return c == ',' || c == ' ' || c == '\t' || c == '\r'; };
    while (i < m_line.size()) {
        while (i < m_line.size() && separator(m_line[i])) ++i;
        if (i == m_line.size()) break;
        std::size_t end = i;
        while (end < m_line.size() && !separator(m_line[end])) ++end;
        std::string_view token(m_line.data() + i, end - i);
        empty = false;
        std::string label;
        if (const auto colon = token.rfind(':'); colon != std::string_view::npos) {
            label = std::string(token.substr(0, colon));
            token.remove_prefix(colon + 1);
        }
        double value = 0.0;
        const auto [ptr, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        // A value beyond the ±3.4e38 a stored (binary32) sample holds would
        // be stored as infinity and poison the live detector for the rest of
        // the session: like an unreadable line, it is a hole.
        constexpr auto kLargestStorable = static_cast<double>(std::numeric_limits<float>::max());
        if (error != std::errc() || ptr != token.data() + token.size() || token.empty() || !std::isfinite(value) ||
            std::abs(value) > kLargestStorable) {
            ok = false;
            break;
        }
        labels.push_back(std::move(label));
        sample.values.push_back(value);
        i = end;
    }
    if (empty) return;
    if (m_labels.empty()) {
        // The layout is fixed by two consecutive lines that agree: a port
        // opened mid-line starts with a fragment, which must not decide it.
        if (!ok || !m_candidate || m_candidateLabels != labels) {
            if (m_candidate) ++m_counters.linesSkipped;
            m_candidate.reset();
            if (ok) {
                m_candidate = std::move(sample);
                m_candidateLabels = std::move(labels);
            } else {
                ++m_counters.linesSkipped;
            }
            return;
        }
        m_labels = labels;
        for (std::size_t c = 0; c < labels.size(); ++c)
            m_names.push_back(labels[c].empty() ? "ch" + std::to_string(c + 1) : labels[c]);
        ++m_counters.frames;
        out.push_back(std::move(*m_candidate));
        m_candidate.reset();
    } else if (!ok || labels != m_labels) {
        // A sample was sent here and cannot be read: a hole, so that the
        // samples after it keep their time.
        ++m_counters.linesSkipped;
        out.push_back({hostTime_s, {}});
        return;
    }
    ++m_counters.frames;
    out.push_back(std::move(sample));
}

}  // namespace tactiscope::devices::protocol
