// VerdictDialog: three answers and a note, and storing what was decided.
#include "ui/VerdictDialog.h"

#include "core/storage/SessionStore.h"
#include "ui/ProblemReport.h"
#include "ui/StoreJobs.h"
#include "ui/VocabularyText.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {

VerdictDialog::VerdictDialog(int defects, core::Verdict verdict, QWidget* parent)
    : QDialog(parent),
      m_note(new QLineEdit(this))
{
    setObjectName(QStringLiteral("verdictBox"));
    setWindowTitle(tr("Panel verdict"));
    setAttribute(Qt::WA_DeleteOnClose);
    setModal(false);
    auto* summary =
        new QLabel(tr("%1 found: the verdict is \"%2\".").arg(defectCountText(defects), wordText(verdict)), this);
    QFont bold = summary->font();
    bold.setBold(true);
    summary->setFont(bold);
    auto* hint = new QLabel(tr("Keep it, or override it if the probe was wrong."), this);
    m_note->setObjectName(QStringLiteral("verdictNote"));
    m_note->setPlaceholderText(tr("Note (optional): what was seen on the panel"));
    m_note->setMinimumWidth(380);

    auto* buttons = new QDialogButtonBox(this);
    QPushButton* pass = buttons->addButton(tr("Pass"), QDialogButtonBox::ActionRole);
    QPushButton* defective = buttons->addButton(tr("Defects found"), QDialogButtonBox::ActionRole);
    QPushButton* keep = buttons->addButton(tr("Keep \"%1\"").arg(wordText(verdict)), QDialogButtonBox::AcceptRole);
    pass->setObjectName(QStringLiteral("passButton"));
    defective->setObjectName(QStringLiteral("defectsButton"));
    keep->setObjectName(QStringLiteral("keepButton"));
    keep->setDefault(true);
    connect(pass, &QPushButton::clicked, this, [this] { decide(core::Verdict::Pass); });
    connect(defective, &QPushButton::clicked, this, [this] { decide(core::Verdict::DefectsFound); });
    connect(keep, &QPushButton::clicked, this, [this, verdict] { decide(verdict); });

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary);
    layout->addWidget(hint);
    layout->addWidget(m_note);
    layout->addWidget(buttons);
}

QString defectCountText(int defects)
{
    return defects == 1 ? VerdictDialog::tr("1 defect") : VerdictDialog::tr("%1 defects").arg(defects);
}

void VerdictDialog::decide(core::Verdict verdict)
{
    emit decided(verdict, m_note->text().trimmed());
    close();
}

void askVerdict(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store, const VerdictQuestion& question,
                std::function<void(const QString& message)> saved)
{
    auto* dialog = new VerdictDialog(question.defects, question.automatic, parent);
    QObject::connect(
        dialog, &VerdictDialog::decided, parent,
        [parent, store, question, saved](core::Verdict chosen, const QString& note) {
            const std::int64_t session = question.session;
            const auto failed = [parent, session](const QString& what) {
                return [parent, session, what](const QString& error) {
                    reportProblem(parent, {VerdictDialog::tr("Not saved"), what, error,
                                           VerdictDialog::tr("Session %1 keeps its automatic verdict; "
                                                             "add the note as an annotation in its "
                                                             "review window.")
                                               .arg(session)});
                };
            };
            if (chosen != question.automatic)
                runOnStore(
                    *store, parent,
                    [session, chosen](core::storage::SessionStore& s) { s.setVerdict(session, chosen); },
                    [saved, session, chosen] {
                        saved(VerdictDialog::tr("Session %1: verdict \"%2\"").arg(session).arg(wordText(chosen)));
                    },
                    failed(VerdictDialog::tr("The verdict could not be saved.")));
            if (note.isEmpty()) return;
            core::storage::Annotation annotation;
            annotation.time_s = question.end_s;
            annotation.author = question.author;
            annotation.text = VerdictDialog::tr("Verdict \"%1\": %2").arg(wordText(chosen), note).toStdString();
            runOnStore(
                *store, parent,
                [session, annotation](core::storage::SessionStore& s) { s.addAnnotation(session, annotation); }, [] {},
                failed(VerdictDialog::tr("The verdict's note could not be saved.")));
        });
    dialog->show();
}

}  // namespace tactiscope::ui
