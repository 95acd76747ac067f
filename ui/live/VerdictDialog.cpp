// VerdictDialog: three answers and a note, and storing what was decided.
#include "ui/live/VerdictDialog.h"
#include "ui/common/NumberText.h"

#include "core/storage/SessionStore.h"
#include "ui/common/ProblemReport.h"
#include "ui/common/StoreJobs.h"
#include "ui/common/VocabularyText.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {

VerdictDialog::VerdictDialog(const QString& summaryText, const QStringList& findings, const QStringList& trail,
                             core::Verdict verdict, QWidget* parent)
    : QDialog(parent),
      m_note(new QLineEdit(this))
{
    setObjectName(QStringLiteral("verdictBox"));
    setWindowTitle(tr("Panel verdict"));
    setAttribute(Qt::WA_DeleteOnClose);
    setModal(false);
    auto* summary = new QLabel(summaryText, this);
    QFont bold = summary->font();
    bold.setBold(true);
    summary->setFont(bold);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary);
    // The panel's own sites: the live view behind may already show the next
    // panel's. A long list is cut with the count of the rest.
    if (!findings.isEmpty()) {
        constexpr qsizetype kShown = 8;
        QStringList shown = findings.mid(0, kShown);
        if (findings.size() > kShown) shown << tr("… and %1 more").arg(findings.size() - kShown);
        auto* list = new QLabel(shown.join(QLatin1Char('\n')), this);
        list->setObjectName(QStringLiteral("verdictFindings"));
        list->setWordWrap(true);
        list->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(list);
    }
    if (!trail.isEmpty()) {
        auto* history = new QLabel(trail.join(QLatin1Char('\n')), this);
        history->setObjectName(QStringLiteral("verdictTrail"));
        history->setStyleSheet(QStringLiteral("color: #555"));
        history->setWordWrap(true);
        layout->addWidget(history);
    }
    auto* hint = new QLabel(tr("Keep it, or override it if the probe was wrong; the note says why."), this);
    m_note->setObjectName(QStringLiteral("verdictNote"));
    m_note->setPlaceholderText(tr("Note (optional): what was seen on the panel"));
    m_note->setMinimumWidth(420);

    // Keep the automatic verdict or change it to the other: two buttons, not
    // "Keep 'defects found'" beside "Defects found".
    auto* buttons = new QDialogButtonBox(this);
    const core::Verdict other = verdict == core::Verdict::Pass ? core::Verdict::DefectsFound : core::Verdict::Pass;
    QPushButton* change = buttons->addButton(tr("Change to \"%1\"").arg(wordText(other)), QDialogButtonBox::ActionRole);
    QPushButton* keep = buttons->addButton(tr("Keep \"%1\"").arg(wordText(verdict)), QDialogButtonBox::AcceptRole);
    change->setObjectName(other == core::Verdict::Pass ? QStringLiteral("passButton")
                                                       : QStringLiteral("defectsButton"));
    keep->setObjectName(QStringLiteral("keepButton"));
    keep->setDefault(true);
    connect(change, &QPushButton::clicked, this, [this, other] { decide(other); });
    connect(keep, &QPushButton::clicked, this, [this, verdict] { decide(verdict); });

    layout->addWidget(hint);
    layout->addWidget(m_note);
    layout->addWidget(buttons);
}

QString defectCountText(int defects)
{
    return countText(defects, VerdictDialog::tr("defect"), VerdictDialog::tr("defects"));
}

QString siteCountText(int sites)
{
    return countText(sites, VerdictDialog::tr("site"), VerdictDialog::tr("sites"));
}

void VerdictDialog::decide(core::Verdict verdict)
{
    emit decided(verdict, m_note->text().trimmed());
    close();
}

VerdictDialog* askVerdict(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store,
                          const VerdictQuestion& question, std::function<void(const QString& message)> saved)
{
    const QString found = question.crossings == 0
                              ? VerdictDialog::tr("No defect found")
                              : VerdictDialog::tr("%1 at %2 found")
                                    .arg(defectCountText(question.crossings), siteCountText(question.sites));
    auto* dialog =
        new VerdictDialog(VerdictDialog::tr("Session %1, %2: the verdict is \"%3\".")
                              .arg(question.session)
                              .arg(question.crossings == 0 ? found.toLower() : found, wordText(question.automatic)),
                          question.findings, {}, question.automatic, parent);
    QObject::connect(
        dialog, &VerdictDialog::decided, parent,
        [parent, store, question, saved](core::Verdict chosen, const QString& note) {
            const std::int64_t session = question.session;
            core::storage::VerdictDecision decision;
            decision.role = core::VerdictRole::Operator;
            decision.verdict = chosen;
            decision.decidedBy = question.operatorName;
            decision.note = note.toStdString();
            runOnStore(
                *store, parent,
                [session, decision](core::storage::SessionSource& s) { s.decideVerdict(session, decision); },
                [saved, session, chosen] {
                    saved(VerdictDialog::tr("Session %1: verdict \"%2\"").arg(session).arg(wordText(chosen)));
                },
                [parent, session](const QString& error) {
                    reportProblem(parent, {VerdictDialog::tr("Not saved"),
                                           VerdictDialog::tr("The operator's verdict could not be saved."), error,
                                           VerdictDialog::tr("Session %1 keeps its automatic verdict; set it in "
                                                             "its review window.")
                                               .arg(session)});
                });
        });
    dialog->show();
    return dialog;
}

}  // namespace tactiscope::ui
