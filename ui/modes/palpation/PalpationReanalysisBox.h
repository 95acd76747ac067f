// Re-analysis of a stored palpation session: its presses read again
// through another probe profile (the session's own, the built-in one or
// any in the profile library) and other gauge factors (as recorded with the
// session, the store's newest calibration of each beam, or the profile's
// nominal one), by core::derived::reanalysePalpation — the live reading's
// code. The new readings are shown beside the recorded ones and never
// replace them; "Save as…" stores them as an analysis of their own.
#pragma once

#include "core/derived/PalpationReanalysis.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"

#include <QWidget>

#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;

namespace tactiscope::ui {

class PalpationReanalysisBox : public QWidget {
    Q_OBJECT

public:
    enum class GaugeFactors { AsRecorded, NewestInStore, Nominal };

    PalpationReanalysisBox(core::storage::SessionSource& store, const core::storage::SessionSummary& session,
                           QWidget* parent);

    QComboBox* profileBox() const { return m_profile; }
    QComboBox* gaugeFactorBox() const { return m_gaugeFactors; }
    // Reads the presses again with the choices made; returns an error, or empty.
    QString run();
    // The last result until it is saved (then it shows as its analysis).
    const core::derived::PalpationReanalysis* unsaved() const { return m_result && !m_saved ? &*m_result : nullptr; }
    // Stores the last result as an analysis; returns an error, or empty.
    QString saveAs(const QString& name);

signals:
    void analysed();
    void saved(const QString& name);

private:
    std::vector<core::calibration::CalibrationRecord> calibrationsFor(const core::sensors::CompliancePairProfile& probe,
                                                                      GaugeFactors choice);
    void askNameAndSave();

    core::storage::SessionSource& m_store;
    core::storage::SessionSummary m_session;
    std::vector<core::sensors::CompliancePairProfile> m_profiles;  // in the box's order, the session's first
    QComboBox* m_profile;
    QComboBox* m_gaugeFactors;
    QPushButton* m_save;
    QLabel* m_status;
    std::optional<core::derived::PalpationReanalysis> m_result;
    bool m_saved = false;
};

}  // namespace tactiscope::ui
