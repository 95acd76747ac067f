// CapacitiveBasisBox: the calibration a capacitive session is read through.
#include "ui/modes/capacitive/CapacitiveBasisBox.h"
#include "ui/common/DateText.h"

#include "core/report/ReportData.h"
#include "core/sensors/SensorProfile.h"
#include "ui/calibration/WizardText.h"
#include "ui/modes/capacitive/CapacitiveSummary.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace tactiscope::ui {

CapacitiveBasisBox::CapacitiveBasisBox(const ReviewAccountContext& context, QWidget* parent)
    : ReviewAccount(tr("Calibration used"), parent),
      m_store(context.store),
      m_session(context.session),
      m_changeLanes(context.changeLanes)
{
    setObjectName(QStringLiteral("capacitiveBasis"));
    // Another record of this beam, to read the session through (a re-analysis; nothing stored changes).
    auto* choice = new QComboBox(this);
    choice->setObjectName(QStringLiteral("capacitiveCalibrationChoice"));
    choice->addItem(tr("as recorded with the session"));
    try {
        const auto profile = core::sensors::parseSensorProfile(m_session.metadata.profileJson, "the session's");
        if (const auto* beam = std::get_if<core::sensors::CapacitiveBeamProfile>(&profile))
            for (const auto& stored : m_store.calibrations(beam->name))
                if (stored.record.kind == core::calibration::kCapacitiveKind) {
                    m_records.push_back(stored.record);
                    choice->addItem(tr("%1 by %2")
                                        .arg(screenDateTime(stored.record.timestampUtc),
                                             stored.record.operatorName.empty()
                                                 ? tr("(no name)")
                                                 : QString::fromStdString(stored.record.operatorName)));
                }
    } catch (const std::exception&) {
        // No profile or store records: the recorded basis is all there is.
    }
    choice->setEnabled(choice->count() > 1);
    choice->setToolTip(tr("Read the force and deflection through another calibration of this beam in the store"));
    m_basis = wrappedLabel({}, this);
    m_basis->setObjectName(QStringLiteral("capacitiveBasisText"));
    m_basis->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    try {
        const auto basis = core::report::capacitiveBasis(m_store, m_session, 0, m_session.sampleCount);
        m_basis->setText(basis
                             ? capacitiveBasisHtml(*basis)
                             : tr("Not known: %1").arg(QString::fromStdString(context.derivedProblem).toHtmlEscaped()));
    } catch (const core::storage::StorageError& e) {
        m_basis->setText(tr("The calibration cannot be read: %1").arg(QString::fromUtf8(e.what()).toHtmlEscaped()));
    }
    connect(choice, &QComboBox::currentIndexChanged, this, [this](int index) {
        const auto record = index > 0 ? std::optional(m_records[static_cast<std::size_t>(index - 1)]) : std::nullopt;
        const QString error = readThrough(record);
        if (!error.isEmpty()) emit problem(error);
    });
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Read through"), this));
    row->addWidget(choice, 1);
    layout->addLayout(row);
    layout->addWidget(m_basis);
    layout->addStretch(1);
}

QString CapacitiveBasisBox::readThrough(const std::optional<core::calibration::CalibrationRecord>& record)
{
    std::optional<core::report::CapacitiveBasis> basis;
    try {
        basis = core::report::capacitiveBasis(m_store, m_session, 0, m_session.sampleCount, record);
    } catch (const core::storage::StorageError& e) {
        return tr("The calibration cannot be read: %1").arg(QString::fromUtf8(e.what()));
    }
    if (!basis) return tr("This calibration cannot be used for session %1.").arg(m_session.id);
    const QString error =
        m_changeLanes([&record](core::derived::LaneOptions& options) { options.capacitiveCalibration = record; });
    if (!error.isEmpty()) return error;
    m_basis->setText(capacitiveBasisHtml(*basis));
    emit status(record ? tr("Force and deflection through the calibration of %1 (the recording's stays as it was).")
                             .arg(screenDateTime(record->timestampUtc))
                       : tr("Force and deflection through the calibration recorded with the session."));
    return {};
}

}  // namespace tactiscope::ui
