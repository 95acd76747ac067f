// `tactiscope-cli compliance PROFILE.json READINGS.csv`: a stiffness reading
// from recorded forces of a compliance probe (seed 001), as a press reading:
// rows below the contact threshold are skipped, the rest give k_o row by
// row, robustly averaged, with the displacement-dependence check.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runCompliance(const QStringList& arguments);

}  // namespace tactiscope::cli
