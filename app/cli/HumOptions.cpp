// Parsing the simulated hum's options.
#include "HumOptions.h"

#include "CliSupport.h"

#include <cmath>

namespace tactiscope::cli {
namespace {

// A hum larger than a gauge's whole range (1 % strain, 10 N, 1 µF) is a
// typing mistake, not a press line.
constexpr double kLargestHum = 1e-2;

}  // namespace

void addHumOptions(QCommandLineParser& parser)
{
    parser.addOptions({
        {QStringLiteral("hum"),
         QStringLiteral("Add mains hum: its common part on every gauge and, after a comma, a differential part of "
                        "opposite sign on alternate channels, in the channels' stored unit (strain: 20e-6 is 20 µε), "
                        "each with its 3rd harmonic at 30 %."),
         QStringLiteral("COMMON[,DIFFERENTIAL]")},
        {QStringLiteral("hum-hz"), QStringLiteral("The hum's mains frequency: 50 (default) or 60."),
         QStringLiteral("50|60")},
    });
}

std::optional<devices::simulator::MainsHumSettings> parseHumOptions(const QCommandLineParser& parser, QString& error)
{
    devices::simulator::MainsHumSettings hum;
    const bool given = parser.isSet(QStringLiteral("hum"));
    if (parser.isSet(QStringLiteral("hum-hz"))) {
        const auto hz = parseMainsFrequency(QStringLiteral("hum-hz"), parser.value(QStringLiteral("hum-hz")), error);
        if (!hz) return std::nullopt;
        if (!given) {
            error = QStringLiteral("--hum-hz goes with --hum COMMON[,DIFFERENTIAL]");
            return std::nullopt;
        }
        hum.mains_hz = *hz;
    }
    if (!given) return hum;
    const QStringList parts = parser.value(QStringLiteral("hum")).split(QLatin1Char(','));
    std::optional<double> values[2] = {0.0, 0.0};
    for (qsizetype i = 0; i < parts.size(); ++i) {
        if (i > 1)
            values[0] = std::nullopt;
        else
            values[i] = parseNumber(parts[i].trimmed());
    }
    if (parts.size() > 2 || !values[0] || !values[1] || std::abs(*values[0]) > kLargestHum ||
        std::abs(*values[1]) > kLargestHum) {
        error = QStringLiteral("--hum is COMMON[,DIFFERENTIAL], amplitudes of at most 0.01 in the channels' unit "
                               "(20e-6,5e-6 for 20 and 5 µε), not %1")
                    .arg(quoted(parser.value(QStringLiteral("hum"))));
        return std::nullopt;
    }
    hum.common = *values[0];
    hum.differential = *values[1];
    return hum;
}

}  // namespace tactiscope::cli
