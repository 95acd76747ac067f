// CentralStoreDialog: the address form and the live sending state.
#include "ui/central/CentralStoreDialog.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"

#include "core/storage/central/PgConnection.h"
#include "ui/calibration/WizardText.h"
#include "ui/central/CentralSyncController.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {

CentralStoreDialog::CentralStoreDialog(CentralSyncController* controller, QWidget* parent)
    : QDialog(parent),
      m_controller(controller),
      m_server(new QLineEdit(controller->server(), this)),
      m_station(new QLineEdit(controller->station(), this)),
      m_addressProblem(wrappedLabel({}, this)),
      m_waiting(new QLabel(this)),
      m_last(wrappedLabel({}, this)),
      m_error(wrappedLabel({}, this)),
      m_send(new QPushButton(tr("&Save and send now"), this)),
      m_browse(new QPushButton(tr("&Browse the central store…"), this))
{
    setWindowTitle(tr("Central store"));
    setObjectName(QStringLiteral("centralStoreDialog"));
    m_server->setObjectName(QStringLiteral("serverEdit"));
    m_station->setObjectName(QStringLiteral("stationEdit"));
    m_waiting->setObjectName(QStringLiteral("waitingText"));
    m_last->setObjectName(QStringLiteral("lastSyncText"));
    m_error->setObjectName(QStringLiteral("lastErrorText"));
    m_send->setObjectName(QStringLiteral("sendButton"));
    m_browse->setObjectName(QStringLiteral("browseCentralButton"));
    m_addressProblem->setStyleSheet(QStringLiteral("color: #b00020"));

    m_server->setPlaceholderText(QStringLiteral("postgresql://press-a@central.example/tactiscope?sslmode=verify-full"));
    m_server->setMinimumWidth(m_server->fontMetrics().horizontalAdvance(m_server->placeholderText()) + 24);
    m_station->setPlaceholderText(tr("the server role's name"));

    auto* intro = wrappedLabel(tr("Sessions recorded here are sent to your site's central store in the background "
                                  "once they end, and stay in this station's store as well. A station offline "
                                  "for days loses nothing: it catches up when the server is back."),
                               this);
    auto* form = new QFormLayout;
    form->addRow(tr("&Server:"), m_server);
    form->addRow(QString(), m_addressProblem);
    form->addRow(tr("S&tation:"), m_station);
    form->addRow(QString(), wrappedLabel(tr("Passwords are never kept here: libpq reads them from ~/.pgpass (or "
                                            "PGPASSFILE, a service file). Leave the server empty to send nothing."),
                                         this));
    auto* status = new QGroupBox(tr("Sending"), this);
    auto* statusForm = new QFormLayout(status);
    statusForm->addRow(tr("Waiting to be sent:"), m_waiting);
    statusForm->addRow(tr("Last sync:"), m_last);
    statusForm->addRow(tr("Last error:"), m_error);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_send, QDialogButtonBox::ActionRole);
    buttons->addButton(m_browse, QDialogButtonBox::ActionRole);

    // As wide as the server's address and as tall as its texts: a long
    // error or outcome wraps and is never clipped, and the dialog keeps its
    // width whatever it says (it went from 640 to 515 px with its text).
    for (QLabel* label : findChildren<QLabel*>())
        if (label->wordWrap()) label->setSizePolicy(QSizePolicy::Ignored, label->sizePolicy().verticalPolicy());
    auto* layout = new QVBoxLayout(this);
    layout->setSizeConstraint(QLayout::SetFixedSize);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(status);
    layout->addWidget(buttons);

    connect(m_server, &QLineEdit::textChanged, this, &CentralStoreDialog::checkAddress);
    connect(m_send, &QPushButton::clicked, this, &CentralStoreDialog::save);
    connect(m_browse, &QPushButton::clicked, this, [this] {
        save();
        if (m_controller->configured()) emit browseRequested(m_controller->server());
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(m_controller, &CentralSyncController::stateChanged, this, &CentralStoreDialog::showState);
    checkAddress();
    showState();
}

void CentralStoreDialog::checkAddress()
{
    const QString address = m_server->text().trimmed();
    const auto problem =
        address.isEmpty() ? std::nullopt : core::storage::central::connectionStringProblem(address.toStdString());
    m_addressProblem->setText(problem ? tr("Not usable: %1.").arg(QString::fromStdString(*problem)) : QString());
    m_addressProblem->setVisible(problem.has_value());
    m_send->setEnabled(!problem);
    m_browse->setEnabled(!problem && !address.isEmpty());
}

void CentralStoreDialog::save()
{
    if (!m_send->isEnabled()) return;
    m_controller->setServer(m_server->text().trimmed(), m_station->text().trimmed());
    m_controller->syncNow();
}

void CentralStoreDialog::showState()
{
    // The address as set elsewhere, unless the user is typing another.
    if (!m_server->isModified() && m_server->text() != m_controller->server()) {
        m_server->setText(m_controller->server());
        m_station->setText(m_controller->station());
    }
    const CentralSyncState& s = m_controller->state();
    if (!m_controller->configured())
        m_waiting->setText(tr("nothing is sent: no server is set"));
    else if (!s.waiting)
        m_waiting->setText(tr("not counted yet (the server has not been reached)"));
    else
        m_waiting->setText(*s.waiting == 0 ? tr("none") : countText(*s.waiting, tr("session"), tr("sessions")));
    if (s.running)
        m_last->setText(s.total > 0 ? tr("sending… %1 of %2 sessions looked at").arg(s.done).arg(s.total)
                                    : tr("connecting…"));
    else if (s.lastAttempt.isValid())
        m_last->setText(tr("%1 — %2").arg(screenDateTime(s.lastAttempt),
                                          s.lastOutcome.isEmpty() ? tr("nothing sent") : s.lastOutcome));
    else
        m_last->setText(tr("not yet"));
    if (s.lastError.isEmpty())
        m_error->setText(tr("none"));
    else
        m_error->setText(
            tr("%1\nTries again every %2 minutes.").arg(s.lastError).arg(CentralSyncController::kRetryMinutes));
    m_error->setStyleSheet(s.lastError.isEmpty() ? QString() : QStringLiteral("color: #b00020"));
    adjustSize();  // room for a longer text now, not at the next event
}

}  // namespace tactiscope::ui
