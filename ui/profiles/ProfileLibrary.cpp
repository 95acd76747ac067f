// ProfileLibrary: listing, atomic writes and file names from profile names.
#include "ui/profiles/ProfileLibrary.h"

#include "ui/profiles/ActiveProfiles.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>

namespace tactiscope::ui {
namespace {

ProfileEntry readEntry(const QString& path, bool builtIn)
{
    ProfileEntry entry{path, QFileInfo(path).fileName(), builtIn, std::nullopt, {}};
    try {
        entry.profile = readProfile(path);
        entry.name = QString::fromStdString(core::sensors::profileName(*entry.profile));
    } catch (const core::sensors::ProfileError& e) {
        entry.error = QString::fromStdString(e.what());
    }
    return entry;
}

// Unreadable files are listed for every mode: which one they were meant
// for cannot be told.
bool belongsTo(const ProfileEntry& entry, const QString& mode)
{
    return !entry.profile || profileFitsMode(*entry.profile, mode);
}

}  // namespace

ProfileLibrary::ProfileLibrary(QString directory)
    : m_directory(std::move(directory))
{
}

QString ProfileLibrary::defaultDirectory()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("profiles"));
}

std::vector<ProfileEntry> ProfileLibrary::entries(const QString& mode, const QString& activePath) const
{
    std::vector<ProfileEntry> entries{readEntry(builtInProfilePath(mode), true)};
    std::vector<ProfileEntry> library;
    const QDir directory(m_directory);
    for (const QString& file : directory.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        ProfileEntry entry = readEntry(directory.filePath(file), false);
        if (belongsTo(entry, mode)) library.push_back(std::move(entry));
    }
    std::sort(library.begin(), library.end(), [](const ProfileEntry& a, const ProfileEntry& b) {
        return a.name.compare(b.name, Qt::CaseInsensitive) < 0;
    });
    std::move(library.begin(), library.end(), std::back_inserter(entries));
    const bool listed = std::any_of(entries.begin(), entries.end(), [&](const ProfileEntry& entry) {
        return QFileInfo(entry.path) == QFileInfo(activePath);
    });
    if (!listed && !activePath.isEmpty()) {
        ProfileEntry active = readEntry(activePath, false);
        if (belongsTo(active, mode)) entries.push_back(std::move(active));
    }
    return entries;
}

bool ProfileLibrary::contains(const QString& path) const
{
    return !path.isEmpty() && QFileInfo(path).absolutePath() == QFileInfo(m_directory).absoluteFilePath();
}

QString ProfileLibrary::save(const core::sensors::SensorProfile& profile, const QString& path) const
{
    const QString target = contains(path) ? path : newFilePath(profile);
    if (!QDir().mkpath(m_directory))
        throw core::sensors::ProfileError(m_directory.toStdString() + ": cannot create the profile folder");
    writeProfile(profile, target);
    return target;
}

void ProfileLibrary::remove(const QString& path) const
{
    if (!contains(path)) throw core::sensors::ProfileError(path.toStdString() + ": not in the profile library");
    QFile file(path);
    if (!file.remove())
        throw core::sensors::ProfileError(path.toStdString() + ": cannot delete (" + file.errorString().toStdString() +
                                          ")");
}

// "Perspex two-beam probe (3 mm / 1 mm)" → perspex-two-beam-probe-3-mm-1-mm.json,
// with -2, -3… when that name is taken.
QString ProfileLibrary::newFilePath(const core::sensors::SensorProfile& profile) const
{
    static const QRegularExpression separators(QStringLiteral("[^a-z0-9]+"));
    QString stem = QString::fromStdString(core::sensors::profileName(profile)).toLower();
    stem.replace(separators, QStringLiteral("-"));
    stem = stem.left(60);
    while (stem.startsWith(QLatin1Char('-'))) stem.remove(0, 1);
    while (stem.endsWith(QLatin1Char('-'))) stem.chop(1);
    if (stem.isEmpty()) stem = QStringLiteral("profile");
    const QDir directory(m_directory);
    QString path = directory.filePath(stem + QStringLiteral(".json"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = directory.filePath(QStringLiteral("%1-%2.json").arg(stem).arg(n));
    return path;
}

void writeProfile(const core::sensors::SensorProfile& profile, const QString& path)
{
    QSaveFile file(path);
    const QByteArray json = QByteArray::fromStdString(core::sensors::toJson(profile) + "\n");
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit())
        throw core::sensors::ProfileError(path.toStdString() + ": cannot write (" + file.errorString().toStdString() +
                                          ")");
}

}  // namespace tactiscope::ui
