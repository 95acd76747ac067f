// Tools ▸ Shunt check…: a strain channel's bridge checked with the probe's
// shunt (devices/session/ShuntCheckRun.h): the bridge type, the gauges'
// resistance and factor and the shunt's resistance, the tolerance; Run
// shows its progress, then PASS or FAIL with the expected and measured
// steps and the deviation, or why the probe could not (an older probe, a
// channel without a bridge, a probe that moved). The result goes into the
// store's calibration history and, while recording, into the session as a
// marker that explains the step in its samples.
#pragma once

#include "devices/session/ShuntCheckRun.h"

#include <QDialog>
#include <QTimer>

#include <functional>
#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace tactiscope::ui {

class ShuntCheckDialog : public QDialog {
    Q_OBJECT

public:
    struct Context {
        std::function<devices::session::LiveSession*()> session;  // null once disconnected
        QString storePath;
        QString operatorName;
    };
    explicit ShuntCheckDialog(Context context, QWidget* parent = nullptr);
    ~ShuntCheckDialog() override;

    void run();
    bool running() const { return m_run != nullptr; }
    QString resultText() const;

private:
    void advance();
    void finished();

    Context m_context;
    std::vector<std::size_t> m_channels;  // the strain channels offered, by their place
    QComboBox* m_channel;
    QComboBox* m_bridge;
    QDoubleSpinBox* m_gauge;
    QDoubleSpinBox* m_shunt;
    QDoubleSpinBox* m_factor;
    QDoubleSpinBox* m_tolerance;
    QLabel* m_expected;
    QProgressBar* m_progress;
    QLabel* m_result;
    QPushButton* m_runButton;
    QTimer m_timer;
    std::unique_ptr<devices::session::ShuntCheckRun> m_run;
    devices::session::ShuntCheckSettings m_settings;
};

}  // namespace tactiscope::ui
