// Session ▸ Trigger…: the condition that starts each hands-free recording
// (on a device channel or a quantity of the mode, in the quantity's
// display unit: µε, mN, mm), the time kept before the trigger and after
// the condition clears, the hold-off, and how many sessions (or re-arm
// until disarmed). It builds the settings the CLI's `record --trigger`
// builds (core/trigger) and shows that command's condition, so an
// operator can script what they tried here.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/trigger/TriggerMachine.h"
#include "ui/common/DisplayUnits.h"

#include <QDialog>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace tactiscope::ui {

// A condition as the operator reads it, in the quantity's display unit:
// "a > 20 µε", "force inside 0.2 mN … 0.6 mN".
QString conditionText(const core::trigger::TriggerCondition& condition,
                      const std::vector<core::ChannelDescriptor>& watchable, core::Mode mode);

class TriggerDialog : public QDialog {
    Q_OBJECT

public:
    // `watchable`: what the session can watch (LiveSession::watchableQuantities())
    // in `mode`, whose units it is shown in.
    TriggerDialog(std::vector<core::ChannelDescriptor> watchable, core::Mode mode, QWidget* parent = nullptr);

    // Starts from earlier settings (the last armed).
    void setSettings(const core::trigger::TriggerSettings& settings);
    // The settings as entered; none, with problem() saying why, when a
    // level is not a number.
    std::optional<core::trigger::TriggerSettings> settings() const;
    QString problem() const;

private:
    void quantityChanged();
    void refresh();
    const core::ChannelDescriptor& watched() const;
    DisplayUnit watchedUnitNow() const;
    std::optional<double> level(const QLineEdit* edit) const;

    std::vector<core::ChannelDescriptor> m_watchable;
    core::Mode m_mode;
    QComboBox* m_quantity;
    QComboBox* m_kind;
    QLineEdit* m_level;
    QLabel* m_and;
    QLineEdit* m_high;
    QLabel* m_unit;
    QLabel* m_highUnit;
    QDoubleSpinBox* m_pre;
    QDoubleSpinBox* m_post;
    QDoubleSpinBox* m_holdOff;
    QSpinBox* m_sessions;
    QCheckBox* m_rearm;
    QLabel* m_command;
    QLabel* m_problem;
    QPushButton* m_arm;
};

}  // namespace tactiscope::ui
