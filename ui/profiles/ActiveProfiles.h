// Which sensor profile each mode uses: a JSON file chosen by the user
// (remembered in QSettings under "profiles/<mode>"), or the paper's probe
// built into the program. A profile that cannot be read, or is of the wrong
// kind for the mode, falls back to the built-in one and says why, so a bad
// file never leaves a mode without a probe.
#pragma once

#include "core/sensors/SensorProfile.h"
#include "ui/common/ProblemReport.h"

#include <QString>
#include <QStringList>

namespace tactiscope::ui {

struct ActiveProfile {
    core::sensors::SensorProfile profile;
    QString path;   // where it came from (":/…" for a built-in one)
    QString error;  // why the chosen file was not used; empty when it was
};

// The modes that run on a sensor profile, and whether a profile is a probe
// for one: a compliance pair for "palpation", a capacitive beam for
// "capacitive".
const QStringList& profileModes();
bool profileFitsMode(const core::sensors::SensorProfile& profile, const QString& mode);

// The built-in profile of a mode ("palpation", "capacitive").
QString builtInProfilePath(const QString& mode);
ActiveProfile activeProfile(const QString& mode);
// What the user is told when a mode's chosen profile was not used (`error`).
Problem badProfile(const QString& mode, const QString& error);
void setActiveProfilePath(const QString& mode, const QString& path);
// The line a mode view shows its probe in (rich text): the profile's name
// and a "Change…" link that asks for the profile dialog.
QString probeLine(const QString& profileName);
// Reads a profile through Qt's file system (so ":/" paths work). Throws
// core::sensors::ProfileError.
core::sensors::SensorProfile readProfile(const QString& path);

}  // namespace tactiscope::ui
