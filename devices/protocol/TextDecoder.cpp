// TextDecoder: lines, Teleplot's gathering, and the channels' layout.
#include "devices/protocol/TextDecoder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::devices::protocol {

namespace {

std::vector<std::string> labelsOf(const TextLine& line)
{
    std::vector<std::string> labels;
    for (const auto& field : line.fields) labels.push_back(field.label);
    return labels;
}

// A value beyond the ±3.4e38 a stored (binary32) sample holds would be
// stored as infinity: like "nan" or "inf" printed, it is no number, a hole
// in its channel alone. Returns how many a line holds.
std::uint64_t markHoles(TextLine& line)
{
    constexpr auto kLargest = static_cast<double>(std::numeric_limits<float>::max());
    std::uint64_t holes = 0;
    for (auto& field : line.fields)
        if (!(std::abs(field.value) <= kLargest)) {
            field.value = std::numeric_limits<double>::quiet_NaN();
            ++holes;
        }
    return holes;
}

}  // namespace

void TextDecoder::push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<TextSample>& out)
{
    m_counters.bytes += bytes.size();
    for (const std::uint8_t byte : bytes) {
        if (byte == '\n') {
            if (m_overlong) {
                ++m_counters.linesSkipped;
                hole(hostTime_s, out);
            } else
                onLine(hostTime_s, out);
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

void TextDecoder::onLine(double hostTime_s, std::vector<TextSample>& out)
{
    ParsedLine parsed = parseTextLine(m_line);
    if (!parsed.line) {
        if (parsed.refusal == LineRefusal::Blank) return;
        ++m_counters.linesSkipped;
        // A line with no number in it is the board's log ("Sensor OK"), as
        // Teleplot shows the lines beside its variables: no sample lost.
        if (m_teleplot || !hasNumber(m_line)) return;
        flushGathering(out);
        if (m_candidate) ++m_counters.linesSkipped;  // the first sample must be followed by an agreeing one
        m_candidate.reset();
        hole(hostTime_s, out);
        return;
    }
    TextLine& line = *parsed.line;
    if (!line.teleplot) {
        flushGathering(out);
        onSample(std::move(line), hostTime_s, out);
        return;
    }
    // Teleplot: a variable seen again, or another timestamp, begins the
    // next instant; the one gathered so far is a sample.
    if (m_gathering) {
        auto& [gathered, at_s] = *m_gathering;
        const bool again = std::ranges::any_of(
            gathered.fields, [&](const TextField& f) { return f.label == line.fields.front().label; });
        const bool movedOn = line.boardTime && gathered.boardTime && line.boardTime->value != gathered.boardTime->value;
        if (!again && !movedOn) {
            gathered.fields.push_back(std::move(line.fields.front()));
            at_s = hostTime_s;
            return;
        }
        flushGathering(out);
    }
    m_gathering.emplace(std::move(line), hostTime_s);
}

void TextDecoder::flushGathering(std::vector<TextSample>& out)
{
    if (!m_gathering) return;
    auto [line, at_s] = std::move(*m_gathering);
    m_gathering.reset();
    onSample(std::move(line), at_s, out);
}

std::optional<std::vector<double>> TextDecoder::inLayout(const TextLine& line) const
{
    if (line.fields.size() != m_labels.size()) return std::nullopt;
    std::vector<double> values(m_labels.size());
    for (std::size_t c = 0; c < m_labels.size(); ++c) {
        if (m_labels[c].empty()) {
            // Unlabelled: by position, and only where the line is unlabelled too.
            if (!line.fields[c].label.empty()) return std::nullopt;
            values[c] = line.fields[c].value;
            continue;
        }
        const auto field =
            std::ranges::find_if(line.fields, [&](const TextField& f) { return f.label == m_labels[c]; });
        if (field == line.fields.end()) return std::nullopt;
        values[c] = field->value;
    }
    return values;
}

void TextDecoder::onSample(TextLine line, double hostTime_s, std::vector<TextSample>& out)
{
    if (m_labels.empty()) {
        // The layout is fixed by two consecutive samples that agree: a port
        // opened mid-line starts with a fragment, which must not decide it.
        const bool agrees = m_candidate && labelsOf(m_candidate->first) == labelsOf(line);
        if (!agrees) {
            if (m_candidate) ++m_counters.linesSkipped;
            m_candidate.emplace(std::move(line), hostTime_s);
            return;
        }
        TextLine& first = m_candidate->first;
        // Teleplot's variables are independent lines, gathered in the order
        // printed from wherever the port was opened: in name order they
        // are the same channels on every connection.
        if (first.teleplot) std::ranges::sort(first.fields, {}, [](const TextField& f) { return f.label; });
        for (std::size_t c = 0; c < first.fields.size(); ++c) {
            m_labels.push_back(first.fields[c].label);
            m_names.push_back(first.fields[c].label.empty() ? "ch" + std::to_string(c + 1) : first.fields[c].label);
            m_units.push_back(first.fields[c].unit);
        }
        m_teleplot = first.teleplot;
        auto [candidate, at_s] = std::move(*m_candidate);
        m_candidate.reset();
        onSample(std::move(candidate), at_s, out);
    }
    const std::uint64_t holes = markHoles(line);
    auto values = inLayout(line);
    if (!values) {
        // A sample was sent here and cannot be read: a hole, so that the
        // samples after it keep their time.
        ++m_counters.linesSkipped;
        hole(hostTime_s, out);
        return;
    }
    ++m_counters.frames;
    m_counters.valueHoles += holes;
    out.push_back({hostTime_s, std::move(*values), line.boardTime});
}

void TextDecoder::hole(double hostTime_s, std::vector<TextSample>& out)
{
    if (!m_labels.empty()) out.push_back({hostTime_s, {}, std::nullopt});
}

}  // namespace tactiscope::devices::protocol
