// ActiveProfiles: settings key, built-in fallback and the kind check.
#include "ui/profiles/ActiveProfiles.h"

#include "core/modes/ModeDefinition.h"
#include "core/sensors/BuiltInProfiles.h"
#include "ui/common/VocabularyText.h"

#include <QFile>
#include <QFileInfo>
#include <QObject>
#include <QSettings>

#include <variant>

namespace tactiscope::ui {
namespace {

QString settingsKey(const QString& mode)
{
    return QStringLiteral("profiles/%1").arg(mode);
}

}  // namespace

bool profileFitsMode(const core::sensors::SensorProfile& profile, const QString& mode)
{
    const auto parsed = core::modeFromString(mode.toStdString());
    return parsed && core::sensors::profileFitsMode(profile, *parsed);
}

const QStringList& profileModes()
{
    static const QStringList modes = [] {
        QStringList names;
        for (const auto& definition : core::modeDefinitions())
            if (!core::sensors::builtInProfileJson(definition.mode).empty()) names << wordText(definition.mode);
        return names;
    }();
    return modes;
}

QString builtInProfilePath(const QString& mode)
{
    const auto known = core::modeFromString(mode.toStdString());
    if (known && core::definitionOf(*known).profile == core::ProfileType::CapacitiveBeam)
        return QStringLiteral(":/tactiscope/profiles/capacitive-beam-paper-no1.json");
    return QStringLiteral(":/tactiscope/profiles/compliance-probe-paper.json");
}

core::sensors::SensorProfile readProfile(const QString& path)
{
    QFile file(path);
    const std::string source = QFileInfo(path).fileName().toStdString();
    if (!file.open(QIODevice::ReadOnly))
        throw core::sensors::ProfileError(source + ": " + file.errorString().toStdString());
    core::sensors::refuseOversizedProfile(static_cast<std::uintmax_t>(file.size()), source);  // before reading it
    return core::sensors::parseSensorProfile(file.readAll().toStdString(), source);
}

ActiveProfile activeProfile(const QString& mode)
{
    const QString builtIn = builtInProfilePath(mode);
    const QString chosen = QSettings().value(settingsKey(mode), builtIn).toString();
    QString error;
    if (chosen != builtIn) {
        try {
            auto profile = readProfile(chosen);
            if (profileFitsMode(profile, mode)) return {std::move(profile), chosen, {}};
            error = QStringLiteral("%1: not a profile for the %2 mode").arg(QFileInfo(chosen).fileName(), mode);
        } catch (const core::sensors::ProfileError& e) {
            error = QString::fromStdString(e.what());
        }
    }
    return {readProfile(builtIn), builtIn, error};
}

QString probeLine(const QString& profileName)
{
    return QObject::tr("Probe: %1 · <a href=\"profiles\">Change…</a>").arg(profileName.toHtmlEscaped());
}

void setActiveProfilePath(const QString& mode, const QString& path)
{
    QSettings().setValue(settingsKey(mode), path);
}

Problem badProfile(const QString& mode, const QString& error)
{
    return {QObject::tr("Bad profile"),
            QObject::tr("The %1 profile could not be used; the paper's sensor is used instead.").arg(mode), error,
            QObject::tr("Fix or choose another profile in Session ▸ Sensor profiles.")};
}

}  // namespace tactiscope::ui
