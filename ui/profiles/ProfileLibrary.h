// The sensor profiles a user can choose from for a mode: the paper's probe
// built into the program, then the JSON files in the profile library (a
// folder of the user's data, one file per probe), then the mode's active
// file when it lives elsewhere. Files that cannot be read are listed with
// their problem rather than hidden, so a broken probe file is noticed.
#pragma once

#include "core/sensors/SensorProfile.h"

#include <QString>

#include <optional>
#include <vector>

namespace tactiscope::ui {

struct ProfileEntry {
    QString path;
    QString name;  // the profile's own name, or the file name when unreadable
    bool builtIn = false;
    std::optional<core::sensors::SensorProfile> profile;  // none when unreadable
    QString error;                                        // why it is unreadable
};

class ProfileLibrary {
public:
    explicit ProfileLibrary(QString directory);
    // <app data>/profiles
    static QString defaultDirectory();
    const QString& directory() const { return m_directory; }

    // Built-in first, then the library by name, then `activePath` when it
    // is neither. Profiles of another mode's kind are left out.
    std::vector<ProfileEntry> entries(const QString& mode, const QString& activePath) const;
    bool contains(const QString& path) const;

    // Writes the profile atomically: over `path` when it is a library file,
    // else into a new file named after the profile. Returns the file's path;
    // throws core::sensors::ProfileError when it cannot be written.
    QString save(const core::sensors::SensorProfile& profile, const QString& path = {}) const;
    // Deletes a library file; throws core::sensors::ProfileError on failure.
    void remove(const QString& path) const;

private:
    QString newFilePath(const core::sensors::SensorProfile& profile) const;

    QString m_directory;
};

// Writes the profile as JSON to any path, atomically.
void writeProfile(const core::sensors::SensorProfile& profile, const QString& path);

}  // namespace tactiscope::ui
