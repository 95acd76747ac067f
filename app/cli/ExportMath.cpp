// The export's math channels, over one device's session or each part.
#include "ExportMath.h"

#include "CliSupport.h"
#include "DeviceValues.h"

#include "core/math/MathColumns.h"
#include "core/signal/SignalChain.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace tactiscope::cli {

namespace {

using core::math::MathDefinition;

std::vector<MathDefinition> parseDefinitions(const QStringList& texts)
{
    std::vector<MathDefinition> definitions;
    for (const QString& text : texts) definitions.push_back(core::math::parseMathDefinition(text.toStdString()));
    return definitions;
}

// Each stored channel of `session` whose filtered series `columns` holds,
// mapped to that column's name.
std::map<std::string, std::string> filteredInPlace(core::storage::SessionSource& store, std::int64_t session,
                                                   const core::storage::ComputedColumns* columns)
{
    std::map<std::string, std::string> readAs;
    if (!columns) return readAs;
    const auto computed = columns->channels();
    for (const auto& stored : store.channels(session)) {
        const std::string filtered = core::signal::filteredName(stored.descriptor.name);
        if (std::ranges::find(computed, filtered, &core::ChannelDescriptor::name) != computed.end())
            readAs[stored.descriptor.name] = filtered;
    }
    return readAs;
}

// `definitions`' columns after `columns` (may be null), over `session`.
std::unique_ptr<core::storage::ComputedColumns> withMath(core::storage::SessionSource& store, std::int64_t session,
                                                         std::vector<MathDefinition> definitions,
                                                         std::unique_ptr<core::storage::ComputedColumns> columns)
{
    auto readAs = filteredInPlace(store, session, columns.get());
    return std::make_unique<core::math::MathColumns>(store, session, std::move(definitions), std::move(columns),
                                                     readAs);
}

}  // namespace

std::optional<QString> addExportMath(core::storage::SessionSource& store, std::int64_t session,
                                     const QStringList& definitions,
                                     std::unique_ptr<core::storage::ComputedColumns>& computed,
                                     core::storage::PartColumns& partColumns)
{
    if (definitions.isEmpty()) return std::nullopt;
    const auto parts = store.parts(session);
    if (parts.empty()) {
        try {
            computed = withMath(store, session, parseDefinitions(definitions), std::move(computed));
        } catch (const core::math::MathError& e) {
            return QStringLiteral("--math: %1").arg(toQString(e.what()));
        }
        return std::nullopt;
    }
    std::vector<std::string> devices;
    for (const auto& part : parts) devices.push_back(part.deviceName);
    QString error;
    const auto byDevice =
        valuesByDevice(QStringLiteral("math"), QStringLiteral("DEVICE/NAME[UNIT]=EXPR"), definitions, devices, error);
    if (!byDevice) return error;
    // Each part's definitions, made once here so that a refusal is said
    // before the export starts.
    std::map<std::int64_t, std::vector<MathDefinition>> ofPart;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if ((*byDevice)[i].isEmpty()) continue;
        try {
            auto definitionsOfPart = parseDefinitions((*byDevice)[i]);
            withMath(store, parts[i].id, definitionsOfPart, partColumns ? partColumns(parts[i].id) : nullptr);
            ofPart[parts[i].id] = std::move(definitionsOfPart);
        } catch (const core::math::MathError& e) {
            return QStringLiteral("--math: %1: %2").arg(toQString(parts[i].deviceName), toQString(e.what()));
        }
    }
    partColumns = [&store, ofPart = std::move(ofPart), recorded = std::move(partColumns)](std::int64_t part) {
        auto columns = recorded ? recorded(part) : nullptr;
        const auto math = ofPart.find(part);
        return math == ofPart.end() ? std::move(columns) : withMath(store, part, math->second, std::move(columns));
    };
    return std::nullopt;
}

}  // namespace tactiscope::cli
