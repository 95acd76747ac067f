// The compliance subcommand.
#include "ComplianceCommand.h"

#include "CliSupport.h"
#include "core/compliance/ReferenceTissues.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/io/CsvColumns.h"
#include "core/sensors/SensorProfile.h"
#include "core/text/JsonWriter.h"

#include <QTextStream>

#include <iostream>

namespace tactiscope::cli {

int runCompliance(const QStringList& arguments)
{
    using namespace core;
    const QString name = QStringLiteral("compliance");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Object stiffness from the forces of a two-beam compliance probe (seed 001).\n"
                       "READINGS.csv has columns displacement_m,force_high_n,force_low_n."));
    parser.addPositionalArgument(QStringLiteral("PROFILE.json"), QStringLiteral("A compliance_pair profile."));
    parser.addPositionalArgument(QStringLiteral("READINGS.csv"), QStringLiteral("The recorded forces."));
    parser.addOptions({
        {QStringLiteral("contact-n"), QStringLiteral("Contact threshold on both forces in N (default 0.01)."),
         QStringLiteral("F")},
        {QStringLiteral("tissues"), QStringLiteral("Place the reading against the reference tissues in FILE."),
         QStringLiteral("FILE")},
        {QStringLiteral("json"), QStringLiteral("Print one JSON object.")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2)
        return usageError(QStringLiteral("compliance needs PROFILE.json and READINGS.csv"), usage);
    double contact_n = 0.01;
    if (parser.isSet(QStringLiteral("contact-n"))) {
        const auto value = parseNumber(parser.value(QStringLiteral("contact-n")));
        if (!value || *value <= 0.0)
            return usageError(QStringLiteral("--contact-n must be a positive number of newtons"), usage);
        contact_n = *value;
    }

    std::optional<sensors::CompliancePair> pair;
    io::CsvColumns csv;
    std::vector<compliance::ReferenceTissue> tissues;
    try {
        const auto profile = sensors::loadSensorProfile(positional[0].toStdString());
        const auto* pairProfile = std::get_if<sensors::CompliancePairProfile>(&profile);
        if (!pairProfile) {
            printError(QStringLiteral("%1: kind: a compliance_pair profile is needed").arg(positional[0]));
            return kExitUsage;
        }
        pair.emplace(sensors::CantileverBeam(pairProfile->high), sensors::CantileverBeam(pairProfile->low));
        csv = io::readCsvColumns(positional[1].toStdString(), {"displacement_m", "force_high_n", "force_low_n"});
        if (parser.isSet(QStringLiteral("tissues")))
            tissues = compliance::loadReferenceTissues(parser.value(QStringLiteral("tissues")).toStdString());
    } catch (const std::runtime_error& e) {  // profile, CSV and tissue errors
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    std::vector<double> displacement, high, low;
    for (std::size_t i = 0; i < csv.rowCount(); ++i) {
        if (csv.columns[1][i] > contact_n && csv.columns[2][i] > contact_n) {
            displacement.push_back(csv.columns[0][i]);
            high.push_back(csv.columns[1][i]);
            low.push_back(csv.columns[2][i]);
        }
    }
    if (displacement.empty()) {
        printError(QStringLiteral("%1: no row has both forces above the contact threshold of %2 N")
                       .arg(positional[1])
                       .arg(contact_n));
        return kExitUsage;
    }
    const auto reading = compliance::readPress(*pair, displacement, high, low);
    const bool inRange = reading.stiffness.range == sensors::ComplianceRange::InRange;
    const std::size_t skipped = csv.rowCount() - displacement.size();

    text::JsonWriter json;
    json.beginObject();
    if (inRange) {
        json.key("object_stiffness_n_per_m").value(reading.stiffness.objectStiffness_n_per_m);
        json.key("standard_error_n_per_m").value(reading.standardError_n_per_m);
    } else {
        json.key("range").value(reading.stiffness.range == sensors::ComplianceRange::Below ? "below" : "above");
    }
    json.key("rows_used").value(static_cast<long long>(reading.samplesUsed));
    json.key("rows_rejected").value(static_cast<long long>(reading.samplesRejected + reading.samplesOutOfRange));
    json.key("rows_skipped").value(static_cast<long long>(skipped));
    if (inRange) {
        json.key("displacement_slope_n_per_m_per_m").value(reading.displacementSlope_n_per_m_per_m);
        json.key("displacement_slope_standard_error").value(reading.displacementSlopeStandardError);
        json.key("displacement_min_m").value(reading.displacementMin_m);
        json.key("displacement_max_m").value(reading.displacementMax_m);
    }
    const auto placed = inRange ? compliance::placeReading(tissues, reading.stiffness.objectStiffness_n_per_m)
                                : std::vector<compliance::TissuePlacement>{};
    if (!placed.empty()) {
        json.key("nearest_tissues").beginArray();
        for (std::size_t i = 0; i < std::min<std::size_t>(3, placed.size()); ++i) {
            json.beginObject();
            json.key("name").value(placed[i].tissue->name);
            json.key("distance_n_per_m").value(placed[i].distance_n_per_m);
            json.endObject();
        }
        json.endArray();
    }
    json.endObject();

    if (parser.isSet(QStringLiteral("json"))) {
        std::cout << json.str() << '\n';
        return kExitOk;
    }
    QTextStream out(stdout);
    if (inRange) {
        out << "object stiffness: " << QString::number(reading.stiffness.objectStiffness_n_per_m, 'f', 1) << " ± "
            << QString::number(reading.standardError_n_per_m, 'f', 1) << " N/m (standard error)\n";
        out << "rows: " << reading.samplesUsed << " used, " << reading.samplesRejected + reading.samplesOutOfRange
            << " rejected, " << skipped << " below contact\n";
        out << "displacement " << QString::number(reading.displacementMin_m * 1e3, 'f', 2) << "–"
            << QString::number(reading.displacementMax_m * 1e3, 'f', 2) << " mm, slope "
            << QString::number(reading.displacementSlope_n_per_m_per_m * 1e-3, 'f', 2) << " N/m per mm\n";
        for (std::size_t i = 0; i < std::min<std::size_t>(3, placed.size()); ++i)
            out << "  near " << QString::fromStdString(placed[i].tissue->name) << " ("
                << QString::number(placed[i].distance_n_per_m, 'f', 0) << " N/m away)\n";
    } else {
        out << "object stiffness out of range: "
            << (reading.stiffness.range == sensors::ComplianceRange::Below ? "below" : "above")
            << " the probe's range (" << reading.samplesOutOfRange << " of " << displacement.size()
            << " rows out of range)\n";
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
