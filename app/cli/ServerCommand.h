// `tactiscope-cli server init CONNINFO`: creates or upgrades a site's
// central store on PostgreSQL, with its station and reviewer roles;
// `server maintain CONNINFO`: makes, detaches and attaches its months.
#pragma once

#include <QStringList>

namespace tactiscope::cli {

int runServer(const QStringList& arguments);

}  // namespace tactiscope::cli
