// PalpationReanalysisBox: the choices, the run and the save.
#include "ui/modes/palpation/PalpationReanalysisBox.h"
#include "ui/common/NumberText.h"

#include "ui/profiles/ProfileLibrary.h"
#include "ui/review/AnalysisName.h"

#include "core/sensors/BuiltInProfiles.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>

namespace tactiscope::ui {
namespace {

void addProfile(std::vector<core::sensors::CompliancePairProfile>& profiles,
                const core::sensors::SensorProfile& profile)
{
    const auto* probe = std::get_if<core::sensors::CompliancePairProfile>(&profile);
    if (probe) profiles.push_back(*probe);
}

}  // namespace

PalpationReanalysisBox::PalpationReanalysisBox(core::storage::SessionSource& store,
                                               const core::storage::SessionSummary& session, QWidget* parent)
    : QWidget(parent),
      m_store(store),
      m_session(session),
      m_profile(new QComboBox(this)),
      m_gaugeFactors(new QComboBox(this)),
      m_save(new QPushButton(tr("Save as…"), this)),
      m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("palpationReanalysis"));
    m_profile->setObjectName(QStringLiteral("reanalysisProfile"));
    m_gaugeFactors->setObjectName(QStringLiteral("reanalysisGaugeFactors"));
    m_status->setObjectName(QStringLiteral("reanalysisStatus"));
    m_status->setWordWrap(true);
    // The session's own profile first, then the built-in one and the library's.
    if (!session.metadata.profileJson.empty()) {
        try {
            addProfile(m_profiles, core::sensors::parseSensorProfile(session.metadata.profileJson, "the session's"));
        } catch (const core::sensors::ProfileError&) {
            // Unreadable: the others can still be chosen.
        }
    }
    const bool hasOwn = !m_profiles.empty();
    if (const auto builtIn = core::sensors::builtInProfile(core::Mode::Palpation)) addProfile(m_profiles, *builtIn);
    for (const auto& entry :
         ProfileLibrary(ProfileLibrary::defaultDirectory()).entries(QStringLiteral("palpation"), {}))
        if (!entry.builtIn && entry.profile) addProfile(m_profiles, *entry.profile);
    for (std::size_t i = 0; i < m_profiles.size(); ++i)
        m_profile->addItem(i == 0 && hasOwn ? tr("%1 (the session's)").arg(QString::fromStdString(m_profiles[i].name))
                                            : QString::fromStdString(m_profiles[i].name));
    m_gaugeFactors->addItem(tr("as recorded with the session"), static_cast<int>(GaugeFactors::AsRecorded));
    m_gaugeFactors->addItem(tr("the store's newest calibration of each beam"),
                            static_cast<int>(GaugeFactors::NewestInStore));
    m_gaugeFactors->addItem(tr("the profile's nominal gauge factor"), static_cast<int>(GaugeFactors::Nominal));
    m_gaugeFactors->setToolTip(tr("kₒ depends on the ratio of the beams' gauge factors only"));

    auto* run = new QPushButton(tr("Read again"), this);
    run->setObjectName(QStringLiteral("reanalysisRun"));
    m_save->setObjectName(QStringLiteral("reanalysisSave"));
    m_save->setEnabled(false);
    auto* form = new QFormLayout(this);
    form->addRow(tr("Profile"), m_profile);
    form->addRow(tr("Gauge factors"), m_gaugeFactors);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(run);
    buttons->addWidget(m_save);
    buttons->addStretch(1);
    form->addRow(buttons);
    form->addRow(m_status);
    connect(run, &QPushButton::clicked, this, [this] {
        const QString error = this->run();
        if (!error.isEmpty()) m_status->setText(error);
    });
    connect(m_save, &QPushButton::clicked, this, &PalpationReanalysisBox::askNameAndSave);
    if (m_profiles.empty()) {
        run->setEnabled(false);
        m_status->setText(tr("No compliance-probe profile to read the presses with."));
    }
}

std::vector<core::calibration::CalibrationRecord>
PalpationReanalysisBox::calibrationsFor(const core::sensors::CompliancePairProfile& probe, GaugeFactors choice)
{
    switch (choice) {
    case GaugeFactors::AsRecorded:
        return core::calibration::recordsFromJsonArray(m_session.metadata.calibrationsJson);
    case GaugeFactors::NewestInStore: {
        std::vector<core::calibration::CalibrationRecord> records;
        for (const bool stiff : {true, false})
            if (const auto newest = m_store.newestCalibration(core::calibration::kGaugeFactorKind,
                                                              core::calibration::beamSensorName(probe.name, stiff)))
                records.push_back(newest->record);
        return records;
    }
    case GaugeFactors::Nominal:
        break;
    }
    return {};
}

QString PalpationReanalysisBox::run()
{
    if (m_profile->currentIndex() < 0) return tr("Choose a profile first.");
    const auto& probe = m_profiles[static_cast<std::size_t>(m_profile->currentIndex())];
    try {
        const auto choice = static_cast<GaugeFactors>(m_gaugeFactors->currentData().toInt());
        m_result = core::derived::reanalysePalpation(m_store, m_session.id, probe, calibrationsFor(probe, choice));
    } catch (const std::exception& e) {  // storage, or a profile the channels cannot be read with
        m_result.reset();
        emit analysed();
        return tr("The presses cannot be read this way: %1").arg(QString::fromStdString(e.what()));
    }
    m_saved = false;
    m_save->setEnabled(!m_result->readings.empty());
    const auto count = m_result->readings.size();
    QString text = tr("%1 read").arg(countText(static_cast<long long>(count), tr("press"), tr("presses"))) +
                   tr(" with %1.").arg(QString::fromStdString(m_result->basis));
    if (m_result->outOfRange > 0) text += tr(" %1 more out of the probe's range.").arg(m_result->outOfRange);
    m_status->setText(text + QLatin1Char(' ') + tr("The recorded readings are unchanged until you save these."));
    emit analysed();
    return {};
}

QString PalpationReanalysisBox::saveAs(const QString& name)
{
    const QString trimmed = name.trimmed();
    if (!m_result || m_saved) return tr("Read the presses again first: this result is saved already.");
    try {
        if (const QString problem = analysisNameProblem(m_store, m_session.id, trimmed); !problem.isEmpty())
            return problem;
        auto readings = m_result->readings;
        for (auto& reading : readings) reading.analysis = trimmed.toStdString();
        m_store.addReadings(m_session.id, readings);
    } catch (const core::storage::StorageError& e) {
        return tr("The analysis was not saved: %1").arg(QString::fromStdString(e.what()));
    }
    m_saved = true;
    m_save->setEnabled(false);
    m_status->setText(tr("Saved as the analysis \"%1\" (%2 readings).").arg(trimmed).arg(m_result->readings.size()));
    emit saved(trimmed);
    return {};
}

void PalpationReanalysisBox::askNameAndSave()
{
    askAnalysisName(this, tr("the recorded readings"), [this](const QString& name) {
        const QString error = saveAs(name);
        if (!error.isEmpty()) m_status->setText(error);
    });
}

}  // namespace tactiscope::ui
