// Reading a session's stored (and derived) channels and evaluating the math on them.
#include "core/math/MathColumns.h"

#include <algorithm>

namespace tactiscope::core::math {

MathColumns::MathColumns(storage::SessionSource& store, std::int64_t session, std::vector<MathDefinition> definitions,
                         std::unique_ptr<storage::ComputedColumns> derived,
                         const std::map<std::string, std::string>& readAs)
    : m_store(store),
      m_session(session),
      m_derived(std::move(derived))
{
    std::vector<ChannelDescriptor> channels;
    for (const auto& stored : store.channels(session)) channels.push_back(stored.descriptor);
    m_storedChannels = channels.size();
    m_readAs.resize(m_storedChannels);
    const auto computed = m_derived ? m_derived->channels() : std::vector<ChannelDescriptor>{};
    for (const ChannelDescriptor& channel : computed) {
        channels.push_back(channel);
        const auto unit = units::parseUnit(channel.unit);
        m_derivedToSi.push_back(unit ? unit->toSi : 1.0);
    }
    for (std::size_t c = 0; c < m_storedChannels; ++c) {
        const auto standIn = readAs.find(channels[c].name);
        if (standIn == readAs.end()) continue;
        const auto column = std::ranges::find(computed, standIn->second, &ChannelDescriptor::name);
        if (column != computed.end()) m_readAs[c] = static_cast<std::size_t>(column - computed.begin());
    }
    m_math = std::make_unique<MathChannels>(mathInputs(channels), std::move(definitions));
}

std::vector<ChannelDescriptor> MathColumns::channels() const
{
    std::vector<ChannelDescriptor> result = m_derived ? m_derived->channels() : std::vector<ChannelDescriptor>{};
    for (const MathDefinition& definition : m_math->definitions())
        result.push_back({definition.name, definition.unit == "1" ? "" : definition.unit, ChannelKind::Other});
    return result;
}

std::string MathColumns::basis() const
{
    std::string text = m_derived ? m_derived->basis() + "; " : "";
    text += "math channels (muParser, values in their declared units";
    if (std::ranges::any_of(m_readAs, [](const auto& column) { return column.has_value(); }))
        text += "; a channel the recording filtered is read filtered, as its math channels read it";
    text += "):";
    for (const MathDefinition& definition : m_math->definitions()) text += " " + definition.text() + ";";
    text.pop_back();
    return text;
}

std::vector<std::vector<double>> MathColumns::read(std::uint64_t first, std::uint64_t count)
{
    std::vector<std::vector<double>> stored;
    std::vector<std::size_t> all(m_storedChannels);
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    m_store.readChannels(m_session, all, first, count, stored);
    std::vector<std::vector<double>> derived =
        m_derived ? m_derived->read(first, count) : std::vector<std::vector<double>>{};
    // Computed columns are in their own units; the expressions read SI.
    std::vector<std::vector<double>> inSi(derived.size());
    std::vector<std::span<const double>> computed;
    for (std::size_t c = 0; c < derived.size(); ++c) {
        const double toSi = c < m_derivedToSi.size() ? m_derivedToSi[c] : 1.0;
        if (toSi == 1.0) {
            computed.emplace_back(derived[c]);
            continue;
        }
        inSi[c].resize(derived[c].size());
        std::ranges::transform(derived[c], inSi[c].begin(), [toSi](double v) { return v * toSi; });
        computed.emplace_back(inSi[c]);
    }
    std::vector<std::span<const double>> inputs;
    for (std::size_t c = 0; c < stored.size(); ++c)
        inputs.push_back(m_readAs[c] ? computed[*m_readAs[c]] : std::span<const double>(stored[c]));
    inputs.insert(inputs.end(), computed.begin(), computed.end());
    std::vector<std::vector<double>> math;
    m_math->evaluate(inputs, math);
    for (auto& column : math) derived.push_back(std::move(column));
    return derived;
}

}  // namespace tactiscope::core::math
