// Session ▸ Limits…: the limit alarms watched on the live stream, each with
// where it comes from (the sensor profile, the sensor model's safe range,
// or set here), in the quantities' display units; and an editor that sets
// a warning and a critical level on any channel or quantity of the mode,
// above or below a level or inside or outside a window, with a hold time,
// replacing the probe's own limit on that quantity and side. The limits set here are the session's
// (LiveSession::setLimits) and are remembered per mode by the main window.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "core/sensors/SensorLimits.h"
#include "core/trigger/LimitWatch.h"

#include <QDialog>

#include <functional>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace tactiscope::ui {

class LimitsDialog : public QDialog {
    Q_OBJECT

public:
    struct Session {
        std::vector<core::ChannelDescriptor> watchable;
        core::Mode mode = core::Mode::General;  // whose units they are shown in
        // The limits watched now, and those set here before.
        std::function<std::vector<core::sensors::SensorLimit>()> limits;
        std::vector<core::trigger::LimitSpec> given;
        // Sets the limits given here; the refusal, or none.
        std::function<std::optional<std::string>(const std::vector<core::trigger::LimitSpec>&)> apply;
    };
    explicit LimitsDialog(Session session, QWidget* parent = nullptr);

    const std::vector<core::trigger::LimitSpec>& given() const { return m_session.given; }

private:
    void refreshTable();
    void setLimit();
    void removeLimit();
    void sideChanged();
    // The level typed in one row (empty: none; a number that is not, or a
    // half-typed window: the problem).
    struct Typed {
        std::optional<core::trigger::LimitLevel> level;
        bool bad = false;
    };
    Typed typed(const QLineEdit* low, const QLineEdit* high) const;
    double toSi(const QLineEdit* edit, bool& ok) const;

    Session m_session;
    QTableWidget* m_table;
    QComboBox* m_quantity;
    QComboBox* m_side;
    QLineEdit* m_warning;  // the level, or a window's low end
    QLineEdit* m_warningHigh;
    QLineEdit* m_critical;
    QLineEdit* m_criticalHigh;
    QLineEdit* m_hold;
    std::vector<QWidget*> m_windowOnly;  // shown for inside and outside
    QLabel* m_warningUnit;
    QLabel* m_criticalUnit;
    QLabel* m_problem;
    QPushButton* m_remove;
};

}  // namespace tactiscope::ui
