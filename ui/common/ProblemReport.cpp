// ProblemReport: the log line and the non-modal box.
#include "ui/common/ProblemReport.h"

#include <QMessageBox>

namespace tactiscope::ui {

Q_LOGGING_CATEGORY(problemLog, "tactiscope.problem")

void logProblem(const Problem& problem)
{
    qCWarning(problemLog, "%s: %s %s", qPrintable(problem.title), qPrintable(problem.what), qPrintable(problem.detail));
}

QMessageBox* reportProblem(QWidget* parent, const Problem& problem)
{
    logProblem(problem);
    auto* box = new QMessageBox(QMessageBox::Warning, problem.title, problem.what, QMessageBox::Ok, parent);
    box->setObjectName(problem.objectName);
    QStringList lines;
    if (!problem.detail.isEmpty()) lines << problem.detail;
    if (!problem.remedy.isEmpty()) lines << problem.remedy;
    box->setInformativeText(lines.join(QStringLiteral("\n\n")));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
    return box;
}

void reportAnalysisProblems(QWidget* parent, const std::vector<std::string>& problems)
{
    for (const auto& problem : problems)
        reportProblem(parent,
                      {QObject::tr("Analysis not available"),
                       QObject::tr("Part of the analysis cannot run on this device."), QString::fromStdString(problem),
                       QObject::tr("The live view and recording go on; check the probe's profile and "
                                   "calibrations.")});
}

}  // namespace tactiscope::ui
