// The model subcommand.
#include "ModelCommand.h"

#include "CliSupport.h"
#include "core/sensors/CompliancePair.h"
#include "core/sensors/SensorProfile.h"
#include "core/text/JsonWriter.h"

#include <iostream>

namespace tactiscope::cli {
namespace {

using namespace core::sensors;

void writeCantilever(core::text::JsonWriter& json, const CantileverBeam& beam)
{
    json.key("stiffness_n_per_m").value(beam.stiffness_n_per_m());
    json.key("strain_per_newton").value(beam.rootStrainPerNewton());
    json.key("deflection_m_per_newton").value(beam.tipDeflectionPerNewton_m());
}

const char* rangeName(ComplianceRange range)
{
    return range == ComplianceRange::Below ? "below" : "above";
}

}  // namespace

int runModel(const QStringList& arguments)
{
    const QString name = QStringLiteral("model");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Print what the sensor model gives for a profile, as JSON."));
    parser.addPositionalArgument(QStringLiteral("PROFILE.json"), QStringLiteral("A sensor profile."));
    parser.addOptions({
        {QStringLiteral("q"), QStringLiteral("compliance_pair: the object stiffness for this force ratio F_H/F_L."),
         QStringLiteral("Q")},
        {QStringLiteral("object-stiffness"), QStringLiteral("compliance_pair: Q and dQ/dk_o for an object of K N/m."),
         QStringLiteral("K")},
    });
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (parser.positionalArguments().size() != 1)
        return usageError(QStringLiteral("model needs exactly one PROFILE.json"), usage);

    std::optional<double> q, objectStiffness;
    if (parser.isSet(QStringLiteral("q"))) {
        q = parseNumber(parser.value(QStringLiteral("q")));
        if (!q) return usageError(QStringLiteral("--q must be a number"), usage);
    }
    if (parser.isSet(QStringLiteral("object-stiffness"))) {
        objectStiffness = parseNumber(parser.value(QStringLiteral("object-stiffness")));
        if (!objectStiffness || *objectStiffness < 0.0)
            return usageError(QStringLiteral("--object-stiffness must be a non-negative number of N/m"), usage);
    }

    SensorProfile profile;
    try {
        profile = loadSensorProfile(parser.positionalArguments().front().toStdString());
    } catch (const ProfileError& e) {
        printError(QString::fromStdString(e.what()));
        return kExitUsage;
    }

    core::text::JsonWriter json;
    json.beginObject();
    json.key("name").value(profileName(profile));
    if (const auto* cantilever = std::get_if<CantileverProfile>(&profile)) {
        if (q || objectStiffness) {
            printError(QStringLiteral("--q and --object-stiffness apply to compliance_pair profiles"));
            return kExitUsage;
        }
        json.key("kind").value("cantilever");
        writeCantilever(json, CantileverBeam(cantilever->geometry));
    } else if (const auto* pairProfile = std::get_if<CompliancePairProfile>(&profile)) {
        const CompliancePair pair{CantileverBeam(pairProfile->high), CantileverBeam(pairProfile->low)};
        json.key("kind").value("compliance_pair");
        json.key("k_high_n_per_m").value(pair.kHigh_n_per_m());
        json.key("k_low_n_per_m").value(pair.kLow_n_per_m());
        json.key("q_max").value(pair.qMax());
        if (q) {
            const StiffnessReading reading = pair.objectStiffness(*q);
            if (reading.range == ComplianceRange::InRange)
                json.key("object_stiffness_n_per_m").value(reading.objectStiffness_n_per_m);
            else
                json.key("range").value(rangeName(reading.range));
        }
        if (objectStiffness) {
            json.key("q").value(pair.forceRatio(*objectStiffness));
            json.key("dq_dk_m_per_n").value(pair.sensitivity_m_per_n(*objectStiffness));
        }
    } else if (const auto* capacitiveProfile = std::get_if<CapacitiveBeamProfile>(&profile)) {
        if (q || objectStiffness) {
            printError(QStringLiteral("--q and --object-stiffness apply to compliance_pair profiles"));
            return kExitUsage;
        }
        const CapacitiveBeam beam(capacitiveProfile->geometry);
        json.key("kind").value("capacitive_beam");
        json.key("stiffness_n_per_m").value(beam.stiffness_n_per_m());
        json.key("compliance_m_per_n").value(beam.tipDeflectionPerNewton_m());
        json.key("sheet_strain_per_newton").value(beam.sheetStrainPerNewton());
        json.key("force_sensitivity_pf_per_mn").value(beam.capacitancePerNewton_f_per_n() * 1e9);
        json.key("displacement_sensitivity_pf_per_mm").value(beam.capacitancePerMetre_f_per_m() * 1e9);
        json.key("neutral_axis_m").value(beam.segment1().neutralAxis_m);
        json.key("bending_stiffness_segment1_n_m").value(beam.segment1().bendingStiffnessPerWidth_n_m);
        json.key("bending_stiffness_segment2_n_m").value(beam.segment2().bendingStiffnessPerWidth_n_m);
    }
    json.endObject();
    std::cout << json.str() << '\n';
    return kExitOk;
}

}  // namespace tactiscope::cli
