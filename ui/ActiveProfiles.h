// Which sensor profile each mode uses: a JSON file chosen by the user
// (remembered in QSettings under "profiles/<mode>"), or the paper's probe
// built into the program. A profile that cannot be read, or is of the wrong
// kind for the mode, falls back to the built-in one and says why, so a bad
// file never leaves a mode without a probe.
#pragma once

#include "core/sensors/SensorProfile.h"

#include <QString>

namespace tactiscope::ui {

struct ActiveProfile {
    core::sensors::SensorProfile profile;
    QString path;   // where it came from (":/…" for a built-in one)
    QString error;  // why the chosen file was not used; empty when it was
};

// The built-in profile of a mode ("palpation", "capacitive").
QString builtInProfilePath(const QString& mode);
ActiveProfile activeProfile(const QString& mode);
void setActiveProfilePath(const QString& mode, const QString& path);
// Reads a profile through Qt's file system (so ":/" paths work). Throws
// core::sensors::ProfileError.
core::sensors::SensorProfile readProfile(const QString& path);

}  // namespace tactiscope::ui
