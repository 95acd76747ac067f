// A simulator calibration rig streaming into a live buffer, as the main
// window would hold it, ten times faster than real time, with the context
// a calibration wizard needs; and keyboard helpers for driving a wizard.
#pragma once

#include "devices/Acquisition.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/WaitFor.h"
#include "ui/calibration/CalibrationContext.h"

#include <QAbstractButton>
#include <QDoubleSpinBox>
#include <QLocale>
#include <QPushButton>
#include <QTest>
#include <QWizard>

#include <algorithm>
#include <memory>
#include <optional>

namespace tactiscope::testing {

class SimulatedRig {
public:
    SimulatedRig(std::unique_ptr<devices::simulator::SimulatedScenario> scenario, const QString& storePath,
                 const QString& profileDirectory, const QString& operatorName)
    {
        m_rig = scenario->loadRig();
        context.channels = scenario->channels();
        context.sampleRate_hz = scenario->sampleRate_hz();
        devices::simulator::SimulatorOptions options;
        options.speed = 10.0;
        m_acquisition = std::make_unique<devices::Acquisition>(
            std::make_unique<devices::simulator::SimulatorSource>(std::move(scenario), options));
        auto buffer = std::make_shared<core::LiveBuffer>(context.channels.size(), 100000);
        m_acquisition->addSink(buffer);
        m_acquisition->start();
        context.buffer = buffer;
        context.rig = m_rig;
        context.store = std::make_shared<core::storage::StoreWorker>(storePath.toStdString());
        context.operatorName = operatorName;
        context.profileDirectory = profileDirectory;
    }
    ~SimulatedRig() { m_acquisition->stop(); }

    devices::simulator::LoadRig& rig() { return *m_rig; }
    QString storePath() const { return QString::fromStdString(context.store->path()); }

    ui::CalibrationContext context;

private:
    std::shared_ptr<devices::simulator::LoadRig> m_rig;
    std::unique_ptr<devices::Acquisition> m_acquisition;
};

// A mnemonic (Alt+letter) clicks its button with a short animation, during
// which the button is down: wait for it to come up and the click to land.
inline void pressMnemonic(QWidget& window, Qt::Key key)
{
    QTest::keyClick(&window, key, Qt::AltModifier);
    runEventLoopFor(50);
    waitFor(
        [&] {
            const auto buttons = window.findChildren<QAbstractButton*>();
            return std::none_of(buttons.begin(), buttons.end(), [](const QAbstractButton* b) { return b->isDown(); });
        },
        5000);
    QCoreApplication::processEvents();
}

inline bool pageComplete(const QWizard& wizard)
{
    return wizard.currentPage()->isComplete();
}

// Shows the wizard, active, on its first (complete) page.
inline bool showActive(QWizard& wizard)
{
    wizard.show();
    wizard.activateWindow();
    return QTest::qWaitForWindowActive(&wizard) && pageComplete(wizard);
}

// Types a load into the wizard's entry and captures it (Alt+C). When the
// operator's count is wrong, `actual_n` is what the rig really carries:
// it is hung right after the wizard's own handler hung the typed load.
// Returns whether the capture finished.
inline bool captureLoad(QWizard& wizard, devices::simulator::LoadRig& rig, double value,
                        std::optional<double> actual_n = std::nullopt)
{
    auto* entry = wizard.findChild<QDoubleSpinBox*>(QStringLiteral("loadValue"));
    auto* button = wizard.findChild<QPushButton*>(QStringLiteral("captureButton"));
    if (!entry || !button) return false;
    entry->setFocus();
    entry->selectAll();
    QTest::keyClicks(entry, QLocale().toString(value));
    QMetaObject::Connection swap;
    if (actual_n) swap = QObject::connect(button, &QPushButton::clicked, [&rig, actual_n] { rig.place(*actual_n); });
    pressMnemonic(wizard, Qt::Key_C);
    QObject::disconnect(swap);
    return waitFor([&] { return button->isEnabled(); }, 15000);
}

}  // namespace tactiscope::testing
