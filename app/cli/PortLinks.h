// The link of each port `record` opens: --protocol, --baud and --rate,
// each given once for every port or as NAME=VALUE for the port given that
// name (--port NAME=PATH), so that a board printing lines and a TSP/1
// probe record into one session ("--protocol board=text").
#pragma once

#include "ProbePort.h"

#include "devices/PortSource.h"

#include <QStringList>

#include <optional>
#include <vector>

namespace tactiscope::cli {

struct PortLink {
    devices::PortSourceOptions options;  // its protocol, and its rate (a text board's, or asked of a probe)
    int baud = 0;
};

struct PortLinkValues {
    QStringList protocols, bauds, rates;  // each option's values, as given
};

// One link per port, in the ports' order; none, with `error` set, when a
// value does not read, names no port, or is given twice for one.
std::optional<std::vector<PortLink>> parsePortLinks(const PortLinkValues& values,
                                                    const std::vector<ProbePortArgument>& ports, int defaultBaud,
                                                    QString& error);

}  // namespace tactiscope::cli
