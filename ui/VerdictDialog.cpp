// VerdictDialog: three answers and a note.
#include "ui/VerdictDialog.h"

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

}  // namespace tactiscope::ui
