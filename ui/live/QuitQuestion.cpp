// QuitQuestion: the box, the stop, and the quit once the verdict is answered.
#include "ui/live/QuitQuestion.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/live/LiveStation.h"
#include "ui/live/VerdictDialog.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>

#include <utility>

namespace tactiscope::ui {

QuitQuestion::QuitQuestion(LiveStation& station, QMainWindow* window)
    : QObject(window),
      m_station(station),
      m_window(window)
{
}

bool QuitQuestion::mayClose()
{
    if (!m_station.isRecording()) return true;
    ask();
    return false;
}

void QuitQuestion::ask()
{
    if (m_window->findChild<QMessageBox*>(QStringLiteral("quitWhileRecordingBox"))) return;  // asked already
    auto* box =
        new QMessageBox(QMessageBox::Question, tr("Recording"),
                        tr("Session %1 is recording. Stop it before quitting?").arg(m_station.pipeline().sessionId()),
                        QMessageBox::NoButton, m_window);
    box->setObjectName(QStringLiteral("quitWhileRecordingBox"));
    // Only the modes that judge ask for a verdict at the stop.
    const bool judges = core::definitionOf(m_station.device()->recordingMetadata().mode).detectsDefects;
    box->setInformativeText(judges ? tr("Stopping ends the session and asks for its verdict, then quits.")
                                   : tr("Stopping ends the session and keeps every sample, then quits."));
    QPushButton* stop = box->addButton(tr("Stop recording"), QMessageBox::AcceptRole);
    stop->setObjectName(QStringLiteral("stopForQuitButton"));
    QPushButton* keep = box->addButton(tr("Keep recording"), QMessageBox::RejectRole);
    keep->setObjectName(QStringLiteral("keepRecordingButton"));
    box->setDefaultButton(keep);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(stop, &QPushButton::clicked, this, [this] {
        m_quitAfterStop = true;
        m_station.stopRecording();
        // No verdict was asked (recordingEnded() took the quit otherwise): quit now.
        if (std::exchange(m_quitAfterStop, false)) QTimer::singleShot(0, m_window, &QMainWindow::close);
    });
    box->open();
}

void QuitQuestion::recordingEnded(VerdictDialog* asked)
{
    if (!asked || !m_quitAfterStop) return;
    m_quitAfterStop = false;
    connect(asked, &QDialog::finished, m_window,
            [window = m_window] { QTimer::singleShot(0, window, &QMainWindow::close); });
}

}  // namespace tactiscope::ui
