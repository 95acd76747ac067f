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

std::vector<std::string> sortedLabelsOf(const TextLine& line)
{
    auto labels = labelsOf(line);
    std::ranges::sort(labels);
    return labels;
}

// "a, b and c"
std::string listed(const std::vector<std::string>& names)
{
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return text;
}

// A value beyond the ±3.4e38 a stored (binary32) sample holds would be
// stored as infinity: like "nan" or "inf" printed, it is no number, a hole
// in its channel alone.
void markHoles(TextLine& line)
{
    constexpr auto kLargest = static_cast<double>(std::numeric_limits<float>::max());
    for (auto& field : line.fields)
        if (!(std::abs(field.value) <= kLargest)) field.value = std::numeric_limits<double>::quiet_NaN();
}

std::uint64_t holesIn(const TextLine& line)
{
    return static_cast<std::uint64_t>(
        std::ranges::count_if(line.fields, [](const TextField& f) { return std::isnan(f.value); }));
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

std::size_t TextDecoder::unlabelledChannel(std::size_t k) const
{
    std::size_t c = 0;
    for (std::size_t seen = 0; c < m_labels.size(); ++c)
        if (m_labels[c].empty() && seen++ == k) break;
    return c;
}

std::optional<std::vector<double>> TextDecoder::inLayout(const TextLine& line) const
{
    // Teleplot's variables are printed each on its own: an instant may
    // lack some (holes), not hold others. Any other line prints the layout.
    if (m_teleplot) {
        for (const auto& field : line.fields)
            if (std::ranges::find(m_labels, field.label) == m_labels.end()) return std::nullopt;
    } else if (!std::ranges::equal(line.fields, m_layoutAsPrinted, {}, &TextField::label) &&
               sortedLabelsOf(line) != m_layout) {
        return std::nullopt;  // (labels in another order are the same layout)
    }
    std::vector<double> values(m_labels.size(), std::numeric_limits<double>::quiet_NaN());
    std::size_t unlabelled = 0;  // the k-th unlabelled value is the k-th unlabelled channel's
    for (const auto& field : line.fields) {
        const std::size_t c =
            field.label.empty() ? unlabelledChannel(unlabelled++)
                                : static_cast<std::size_t>(std::ranges::find(m_labels, field.label) - m_labels.begin());
        values[c] = field.value;
    }
    return values;
}

std::optional<std::string> TextDecoder::adopt(const TextLine& line)
{
    const bool first = m_labels.empty();
    std::vector<std::string> appeared;
    std::size_t unlabelled = 0;
    for (const auto& field : line.fields) {
        const bool known = field.label.empty()
                               ? unlabelled++ < static_cast<std::size_t>(std::ranges::count(m_labels, std::string()))
                               : std::ranges::find(m_labels, field.label) != m_labels.end();
        if (known) continue;
        m_labels.push_back(field.label);
        m_names.push_back(field.label.empty() ? "ch" + std::to_string(m_labels.size()) : field.label);
        m_units.push_back(field.unit);
        appeared.push_back(m_names.back());
    }
    // What the old layout printed and this one does not.
    std::vector<std::string> gone;
    auto now = sortedLabelsOf(line);
    if (!m_teleplot) {
        std::size_t unlabelledBefore = 0;
        for (const auto& label : m_layout) {
            if (!label.empty() && std::ranges::find(now, label) == now.end()) gone.push_back(label);
            if (label.empty()) ++unlabelledBefore;
        }
        for (std::size_t k = unlabelled; k < unlabelledBefore; ++k) gone.push_back(m_names[unlabelledChannel(k)]);
        m_layout = std::move(now);
        m_layoutAsPrinted = labelsOf(line);
    }
    if (first || (appeared.empty() && gone.empty())) return std::nullopt;
    std::string change = "the board's channels changed:";
    if (!appeared.empty()) change += " " + listed(appeared) + " appeared (holes before the first value)";
    if (!gone.empty())
        change += std::string(appeared.empty() ? " " : "; ") + listed(gone) + (gone.size() == 1 ? " is" : " are") +
                  " no longer printed (holes from here)";
    return change;
}

void TextDecoder::putOut(const TextLine& line, std::vector<double> values, double hostTime_s,
                         std::optional<std::string> change, std::vector<TextSample>& out)
{
    ++m_counters.frames;
    m_counters.valueHoles += holesIn(line);
    out.push_back({hostTime_s, std::move(values), line.boardTime, std::move(change)});
}

void TextDecoder::flushNewLayout(std::vector<TextSample>& out)
{
    if (!m_newLayout) return;
    const double at_s = m_newLayout->second;
    m_newLayout.reset();
    ++m_counters.linesSkipped;
    hole(at_s, out);
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
        m_teleplot = first.teleplot;
        adopt(first);
        auto [candidate, at_s] = std::move(*m_candidate);
        m_candidate.reset();
        onSample(std::move(candidate), at_s, out);
    }
    markHoles(line);
    if (auto values = inLayout(line)) {
        flushNewLayout(out);
        putOut(line, std::move(*values), hostTime_s, std::nullopt, out);
        return;
    }
    // Teleplot's new variable is a channel at once (a line that is not
    // Teleplot's, as the rest, is a hole); any other board's new layout
    // once a second line agrees (one line of other labels is a sample
    // garbled on the way: a hole, so that the samples after it keep their
    // time).
    if (m_teleplot) {
        if (!line.teleplot) {
            ++m_counters.linesSkipped;
            hole(hostTime_s, out);
            return;
        }
        auto change = adopt(line);
        putOut(line, *inLayout(line), hostTime_s, std::move(change), out);
        return;
    }
    if (m_newLayout && sortedLabelsOf(m_newLayout->first) == sortedLabelsOf(line)) {
        auto [previous, at_s] = std::move(*m_newLayout);
        m_newLayout.reset();
        auto change = adopt(previous);
        putOut(previous, *inLayout(previous), at_s, std::move(change), out);
        putOut(line, *inLayout(line), hostTime_s, std::nullopt, out);
        return;
    }
    flushNewLayout(out);
    m_newLayout.emplace(std::move(line), hostTime_s);
}

void TextDecoder::hole(double hostTime_s, std::vector<TextSample>& out)
{
    flushNewLayout(out);  // it came first
    if (!m_labels.empty()) out.push_back({hostTime_s, {}, std::nullopt, std::nullopt});
}

}  // namespace tactiscope::devices::protocol
