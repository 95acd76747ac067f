// What a station requires before it records. A site sets it for all its
// stations in the system-wide settings file (on Linux
// /etc/xdg/Tactiscope/Tactiscope.conf: [recording] requireSubjectAndOperator=true),
// which a user cannot loosen; without a site rule, the user's own setting
// (Settings dialog) applies.
#pragma once

#include <QString>

class QWidget;

namespace tactiscope::ui {

struct RecordingPolicy {
    bool requireSubjectAndOperator = false;
    bool setBySite = false;  // the site's file requires it
};

RecordingPolicy recordingPolicy();
void setRequireSubjectAndOperator(bool required);  // the user's own setting

// Why a recording with this subject and operator may not start under the
// policy, or empty when it may.
QString recordingRefusal(const RecordingPolicy& policy, const QString& subject, const QString& operatorName);

// The Settings dialog (non-modal): the policy, the site's rule shown as such.
void showSettingsDialog(QWidget* parent);

}  // namespace tactiscope::ui
