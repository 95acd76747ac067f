// PortLinks: each link option's values shared out to the ports.
#include "PortLinks.h"

#include "CliSupport.h"

#include <algorithm>

namespace tactiscope::cli {

namespace {

// Each port's value of one option: the one named for it, else the one
// given for every port, else none.
std::optional<std::vector<std::optional<QString>>> shareOut(const QString& option, const QStringList& values,
                                                            const std::vector<ProbePortArgument>& ports, QString& error)
{
    std::optional<QString> forEvery;
    std::vector<std::optional<QString>> named(ports.size());
    for (const QString& value : values) {
        const auto equals = value.indexOf(QLatin1Char('='));
        if (equals < 0) {
            if (forEvery) {
                error = QStringLiteral("--%1: give one value for every port, or NAME=VALUE once for each port "
                                       "named (--port NAME=PATH)")
                            .arg(option);
                return std::nullopt;
            }
            forEvery = value;
            continue;
        }
        const std::string name = value.left(equals).toStdString();
        const auto port = std::ranges::find(ports, name, &ProbePortArgument::name);
        if (name.empty() || port == ports.end()) {
            error = QStringLiteral("--%1: no port is named %2 (name one with --port NAME=PATH)")
                        .arg(option, quoted(value.left(equals)));
            return std::nullopt;
        }
        auto& slot = named[static_cast<std::size_t>(port - ports.begin())];
        if (slot) {
            error = QStringLiteral("--%1: %2 is given twice").arg(option, quoted(value.left(equals)));
            return std::nullopt;
        }
        slot = value.mid(equals + 1);
    }
    for (auto& slot : named)
        if (!slot) slot = forEvery;
    return named;
}

}  // namespace

std::optional<std::vector<PortLink>> parsePortLinks(const PortLinkValues& values,
                                                    const std::vector<ProbePortArgument>& ports, int defaultBaud,
                                                    QString& error)
{
    const auto protocols = shareOut(QStringLiteral("protocol"), values.protocols, ports, error);
    if (!protocols) return std::nullopt;
    const auto bauds = shareOut(QStringLiteral("baud"), values.bauds, ports, error);
    if (!bauds) return std::nullopt;
    const auto rates = shareOut(QStringLiteral("rate"), values.rates, ports, error);
    if (!rates) return std::nullopt;
    std::vector<PortLink> links(ports.size());
    for (std::size_t i = 0; i < ports.size(); ++i) {
        PortLink& link = links[i];
        const auto protocol = parseWireProtocol((*protocols)[i].value_or(QString()));
        if (!protocol) {
            error = QStringLiteral("--protocol must be binary or text");
            return std::nullopt;
        }
        link.options.protocol = *protocol;
        link.baud = defaultBaud;
        if (const auto& baud = (*bauds)[i]) {
            bool ok = false;
            link.baud = baud->toInt(&ok);
            if (!ok || link.baud <= 0) {
                error = QStringLiteral("--baud must be a positive whole number");
                return std::nullopt;
            }
        }
        if (const auto& text = (*rates)[i]) {
            const auto rate = numberInRange(QStringLiteral("rate"), *text, core::kSampleRateRange, error);
            if (!rate) return std::nullopt;
            (link.options.protocol == devices::WireProtocol::Text ? link.options.textRate_hz
                                                                  : link.options.requestRate_hz) = rate;
        }
    }
    return links;
}

}  // namespace tactiscope::cli
