// PortLinks: each link option's values shared out to the ports.
#include "PortLinks.h"

#include "CliSupport.h"

namespace tactiscope::cli {

namespace {

// Each port's value of --OPTION (CliSupport.h: valuesByName).
std::optional<std::vector<std::optional<QString>>> shareOut(const QString& option, const QStringList& values,
                                                            const std::vector<ProbePortArgument>& ports, QString& error)
{
    std::vector<std::string> names;
    for (const ProbePortArgument& port : ports) names.push_back(port.name);
    return valuesByName(option, values, names, QStringLiteral("port"), QStringLiteral("name one with --port NAME=PATH"),
                        error);
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
