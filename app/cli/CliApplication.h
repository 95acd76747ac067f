// tactiscope-cli's top level: global options (--help, --version) and the
// dispatch of the first argument to a subcommand.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

// `arguments` excludes the program name. Returns the process exit code.
int runCli(const QStringList& arguments);

}  // namespace tactiscope::cli
