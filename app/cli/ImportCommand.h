// `tactiscope-cli import FILE.csv --db FILE [--rate HZ] [--time-column NAME]
// [--mode …] [--subject …]`: a CSV recording from another program as a new
// session. The contract is in issue 7.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runImport(const QStringList& arguments);

}  // namespace tactiscope::cli
