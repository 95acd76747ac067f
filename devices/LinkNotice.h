// Something the link saw that the record must keep (a device restart, a
// sequence number its clock contradicted): when, in the source's stream
// time, and one sentence. The live session stores each as an alarm event
// while recording and tells the operator.
#pragma once

#include <string>

namespace tactiscope::devices {

struct LinkNotice {
    double time_s = 0.0;
    std::string text;
};

}  // namespace tactiscope::devices
