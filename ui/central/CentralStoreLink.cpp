// CentralStoreLink: the controller, its status-bar field and its dialog.
#include "ui/central/CentralStoreLink.h"
#include "ui/common/DateText.h"

#include "ui/central/CentralStoreDialog.h"
#include "ui/central/CentralSyncController.h"

#include <QLabel>
#include <QStatusBar>

namespace tactiscope::ui {

CentralStoreLink::CentralStoreLink(QStatusBar* bar, QWidget* window)
    : QObject(window),
      m_window(window),
      m_controller(new CentralSyncController(this)),
      m_field(new QLabel(bar))
{
    m_field->setObjectName(QStringLiteral("centralStoreLabel"));
    m_field->setContentsMargins(10, 0, 10, 0);
    m_field->setTextFormat(Qt::RichText);
    connect(m_field, &QLabel::linkActivated, this, [this] { showDialog(); });
    bar->addPermanentWidget(m_field);
    connect(m_controller, &CentralSyncController::stateChanged, this, &CentralStoreLink::showState);
    showState();
}

void CentralStoreLink::setStorePath(const QString& path) const
{
    m_controller->setStorePath(path);
}

void CentralStoreLink::sessionRecorded() const
{
    m_controller->sessionRecorded();
}

void CentralStoreLink::syncNow() const
{
    m_controller->syncNow();
}

CentralStoreDialog* CentralStoreLink::showDialog()
{
    if (!m_dialog) {
        m_dialog = new CentralStoreDialog(m_controller, m_window);
        m_dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_dialog, &CentralStoreDialog::browseRequested, this, &CentralStoreLink::browseRequested);
    }
    m_dialog->show();
    m_dialog->raise();
    m_dialog->activateWindow();
    return m_dialog;
}

void CentralStoreLink::showState()
{
    m_field->setVisible(m_controller->configured());
    const CentralSyncState& s = m_controller->state();
    // While the minute's look runs, the last word stands.
    if (s.running && s.checking) return;
    QString state;
    if (s.running)
        state = tr("sending…");
    else if (s.unreachable)
        state = s.waiting && *s.waiting > 0 ? tr("server unreachable, %1 waiting").arg(*s.waiting)
                                            : tr("server unreachable");
    else if (!s.lastError.isEmpty())
        state = s.waiting ? tr("cannot send, %1 waiting").arg(*s.waiting) : tr("cannot send");
    else if (s.waiting)
        state = *s.waiting == 0 ? tr("up to date") : tr("%1 waiting").arg(*s.waiting);
    else
        state = tr("not reached yet");
    m_field->setText(tr("Central store: <a href=\"central\">%1</a>").arg(state.toHtmlEscaped()));
    const QString reached = s.lastReached.isValid()
                                ? tr("The server last answered at %1.").arg(screenTime(s.lastReached.time()))
                                : tr("The server has not answered yet.");
    m_field->setToolTip(s.lastError.isEmpty()
                            ? tr("Where this station's sessions are sent (Session ▸ Central store…). %1").arg(reached)
                            : s.lastError + QLatin1Char('\n') + reached);
    m_field->setStyleSheet(s.lastError.isEmpty() ? QString() : QStringLiteral("color: #b00020"));
}

}  // namespace tactiscope::ui
