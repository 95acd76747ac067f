// Something the link saw that the record must keep (a device restart, a
// sequence number its clock contradicted, a board's new layout): when, in
// the source's stream time, and one sentence. The live session stores each
// as an event while recording (an alarm, or a note where nothing went
// wrong) and tells the operator.
#pragma once

#include <string>

namespace tactiscope::devices {

struct LinkNotice {
    double time_s = 0.0;
    std::string text;
    bool alarm = true;
    // What it says holds on after it (a board's new layout: a channel no
    // longer printed is holes from then on), so a recording that begins
    // later keeps it as a note at its start.
    bool lasting = false;
};

}  // namespace tactiscope::devices
