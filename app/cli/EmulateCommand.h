// `tactiscope-cli emulate --link PATH …`: a simulated probe behind a
// pseudo-terminal, so anyone can try the serial path without hardware.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runEmulate(const QStringList& arguments);

}  // namespace tactiscope::cli
