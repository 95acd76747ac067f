// What `compliance` found, printed as text or one JSON object: the presses
// and their combination (with each part of the uncertainty), or the steps
// of the paper's procedure, and where the value lies among reference
// tissues.
#pragma once

#include "core/compliance/ReferenceTissues.h"
#include "core/compliance/StepProcedure.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/sensors/SensorProfile.h"

#include <QString>

#include <optional>
#include <vector>

namespace tactiscope::cli {

struct ComplianceOutput {
    explicit ComplianceOutput(const core::sensors::CompliancePairProfile& probe);
    const core::sensors::CompliancePair& pair() const { return m_pair; }

    // The forces form: rows below contact, one press of all the others.
    struct Rows {
        std::size_t skipped = 0;
    };
    std::optional<Rows> rows;
    std::vector<core::compliance::PressReading> presses;
    std::optional<core::compliance::StepProcedureReading> steps;
    QString basis;   // the profile and gauge factors, for a raw recording
    QString source;  // where the zero came from
    bool recordedZeros = false;
    std::optional<double> sampleRate_hz;
    std::optional<std::pair<double, double>> usableRange_n_per_m;  // the probe's, from its beams' converters
    std::vector<core::compliance::ReferenceTissue> tissues;

    // Prints to stdout; returns the exit code (2 when nothing was read).
    int print(bool json) const;

private:
    core::sensors::CompliancePair m_pair;
};

}  // namespace tactiscope::cli
