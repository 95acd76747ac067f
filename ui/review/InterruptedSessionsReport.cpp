// InterruptedSessionsReport: finding the sessions, the message and the export.
#include "ui/review/InterruptedSessionsReport.h"
#include "ui/common/DateText.h"

#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/common/VocabularyText.h"

#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"

#include <QDir>
#include <QFileDialog>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>

namespace tactiscope::ui {
namespace {

QString describe(const core::storage::SessionSummary& s)
{
    const QString subject =
        s.metadata.subject.empty() ? QObject::tr("no subject") : QString::fromStdString(s.metadata.subject);
    return QObject::tr("Session %1 (%2, %3), started %4: %5 s kept")
        .arg(s.id)
        .arg(wordText(s.metadata.mode), subject, screenDateTime(s.startedUtc))
        .arg(fixedText(s.duration_s(), 1));
}

// Each session as session-N.csv with session-N.meta.json beside it.
void exportSessions(core::storage::SessionSource& store, const std::vector<std::int64_t>& sessions,
                    const QString& folder)
{
    for (const std::int64_t id : sessions) {
        const QString csv = QDir(folder).filePath(QStringLiteral("session-%1.csv").arg(id));
        core::storage::exportSession(store, id, core::storage::ExportFormat::Csv, csv.toStdString());
    }
}

}  // namespace

std::vector<core::storage::SessionSummary> interruptedSessionsAfter(core::storage::SessionSource& store,
                                                                    std::int64_t afterId)
{
    std::vector<core::storage::SessionSummary> found;
    for (auto& s : store.sessions())
        if (s.id > afterId && s.status == core::SessionStatus::Interrupted) found.push_back(std::move(s));
    std::ranges::sort(found, {}, &core::storage::SessionSummary::id);
    return found;
}

void showInterruptedSessionsReport(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store,
                                   const std::vector<core::storage::SessionSummary>& sessions,
                                   const std::function<void(const std::vector<std::int64_t>&)>& review)
{
    if (sessions.empty()) return;
    QStringList lines;
    std::vector<std::int64_t> ids;
    for (const auto& s : sessions) {
        lines << describe(s);
        ids.push_back(s.id);
    }
    auto* box =
        new QMessageBox(QMessageBox::Information, QObject::tr("Interrupted sessions"),
                        (ids.size() == 1 ? QObject::tr("A recording ended without being stopped")
                                         : QObject::tr("%1 recordings ended without being stopped").arg(ids.size())) +
                            QObject::tr(" (a crash, a power cut or a full disk). Everything written "
                                        "before that was kept."),
                        QMessageBox::Close, parent);
    box->setObjectName(QStringLiteral("interruptedBox"));
    box->setInformativeText(lines.join(QLatin1Char('\n')));
    QPushButton* reviewButton = box->addButton(QObject::tr("Review…"), QMessageBox::ActionRole);
    reviewButton->setObjectName(QStringLiteral("reviewInterruptedButton"));
    QObject::connect(reviewButton, &QPushButton::clicked, parent, [review, ids] { review(ids); });
    QPushButton* exportButton = box->addButton(QObject::tr("Export to CSV…"), QMessageBox::ActionRole);
    exportButton->setObjectName(QStringLiteral("exportInterruptedButton"));
    // The box closes on any button, so the export talks to the parent.
    QObject::connect(exportButton, &QPushButton::clicked, parent, [parent, store, ids] {
        const QString folder =
            QFileDialog::getExistingDirectory(parent, QObject::tr("Export the interrupted sessions to"));
        if (folder.isEmpty()) return;
        runOnStore(
            *store, parent, [ids, folder](core::storage::SessionSource& s) { exportSessions(s, ids, folder); }, [] {},
            [parent](const QString& error) {
                reportProblem(parent, {QObject::tr("Export failed"),
                                       QObject::tr("Not every interrupted session was exported."), error,
                                       QObject::tr("Choose a folder with space that you may write to, and export "
                                                   "again.")});
            });
    });
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
}

}  // namespace tactiscope::ui
