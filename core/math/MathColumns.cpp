// Reading a session's stored (and derived) channels and evaluating the math on them.
#include "core/math/MathColumns.h"

#include <algorithm>

namespace tactiscope::core::math {

MathColumns::MathColumns(storage::SessionSource& store, std::int64_t session, std::vector<MathDefinition> definitions,
                         std::unique_ptr<storage::ComputedColumns> derived)
    : m_store(store),
      m_session(session),
      m_derived(std::move(derived))
{
    std::vector<ChannelDescriptor> channels;
    for (const auto& stored : store.channels(session)) channels.push_back(stored.descriptor);
    m_storedChannels = channels.size();
    if (m_derived)
        for (const ChannelDescriptor& channel : m_derived->channels()) {
            channels.push_back(channel);
            const auto unit = units::parseUnit(channel.unit);
            m_derivedToSi.push_back(unit ? unit->toSi : 1.0);
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
    text += "math channels (muParser, values in their declared units):";
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
    std::vector<std::span<const double>> inputs(stored.begin(), stored.end());
    // Computed columns are in their own units; the expressions read SI.
    std::vector<std::vector<double>> inSi(derived.size());
    for (std::size_t c = 0; c < derived.size(); ++c) {
        const double toSi = c < m_derivedToSi.size() ? m_derivedToSi[c] : 1.0;
        if (toSi == 1.0) {
            inputs.emplace_back(derived[c]);
            continue;
        }
        inSi[c].resize(derived[c].size());
        std::ranges::transform(derived[c], inSi[c].begin(), [toSi](double v) { return v * toSi; });
        inputs.emplace_back(inSi[c]);
    }
    std::vector<std::vector<double>> math;
    m_math->evaluate(inputs, math);
    for (auto& column : math) derived.push_back(std::move(column));
    return derived;
}

}  // namespace tactiscope::core::math
