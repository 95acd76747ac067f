// RecordingEndReport: the problem boxes, the triggered line and the verdict question.
#include "ui/live/RecordingEndReport.h"

#include "ui/common/NumberText.h"
#include "ui/common/ProblemReport.h"
#include "ui/live/VerdictDialog.h"

#include <QObject>

namespace tactiscope::ui {
namespace {

QString tr(const char* text)
{
    return QObject::tr(text);
}

// A device's end that was not a stop; `device` names it in a session of several.
void tellPartProblem(QWidget* window, const std::string& device, std::int64_t session,
                     const devices::session::RecordingSummary& summary)
{
    const QString who = device.empty() ? QString() : QString::fromStdString(device) + QStringLiteral(": ");
    if (!summary.stats.error.empty())
        reportProblem(window, {tr("Recording stopped"), who + tr("Recording stopped early."),
                               QString::fromStdString(summary.stats.error),
                               tr("The samples up to the stop are kept in session %1. Free space or choose another "
                                  "store, then record again.")
                                   .arg(session)});
    else if (summary.lostAt_s)
        reportProblem(window, {tr("Probe lost"),
                               who + (summary.stoppedBecause.empty()
                                          ? tr("The probe was lost at %1 s and did not come back before the stop.")
                                          : tr("The probe was lost at %1 s and was not taken back: the details say "
                                               "why."))
                                         .arg(fixedText(*summary.lostAt_s, 1)),
                               QString::fromStdString(summary.stoppedBecause),
                               tr("Session %1 keeps every sample up to the loss; the time after it is a gap with an "
                                  "alarm. Check the cable and the probe, then record again.")
                                   .arg(session)});
    else if (!summary.stoppedBecause.empty())
        reportProblem(window,
                      {tr("Recording stopped"), who + tr("The link to the probe failed, so the recording stopped."),
                       QString::fromStdString(summary.stoppedBecause),
                       tr("Session %1 keeps every sample up to then, with an alarm; nothing after it was "
                          "recorded. Connect the probe again and record to start a new session.")
                           .arg(session)});
}

bool endedWell(const devices::session::RecordingSummary& summary)
{
    return summary.stats.error.empty() && !summary.lostAt_s && summary.stoppedBecause.empty();
}

}  // namespace

VerdictDialog* tellRecordingEnd(const devices::session::RecordingEnd& end, const RecordingEndContext& context)
{
    bool well = true;
    for (const auto& [device, summary] : end.parts) {
        tellPartProblem(context.window, device, end.session, summary);
        well = well && endedWell(summary);
    }
    if (end.parts.empty()) return nullptr;
    if (end.triggered) {
        context.tell(
            tr("Session %1 (%2) recorded by the trigger: %3")
                .arg(end.session)
                .arg(QString::fromStdString(end.subject), QString::fromStdString(end.parts.front().what.analysis)));
        return nullptr;
    }
    if (!end.verdict || !well) return nullptr;
    // What the verdict was decided on: every part's defects and sites.
    VerdictQuestion question;
    question.session = end.session;
    question.automatic = *end.verdict;
    question.operatorName = context.operatorName;
    for (const auto& part : end.parts) {
        question.crossings += static_cast<int>(part.what.defects);
        question.sites += static_cast<int>(part.what.sites);
        // A part's lines say whose they are.
        const QString whose = part.device.empty() ? QString() : QString::fromStdString(part.device) + ": ";
        for (const auto& line : part.what.findings) question.findings << whose + QString::fromStdString(line);
    }
    return askVerdict(context.window, context.store, question, [context](const QString& message) {
        context.tell(message);
        context.verdictSaved();
    });
}

void tellPartEnded(QWidget* window, const std::string& device, const devices::session::RecordingSummary& summary)
{
    const std::string why = summary.stats.error.empty() ? summary.stoppedBecause : summary.stats.error;
    reportProblem(window, {tr("Device stopped"), tr("One device's part of the recording ended early."),
                           QString::fromStdString(device + ": " + why),
                           tr("Its samples up to then are kept in its part; the other devices record on.")});
}

}  // namespace tactiscope::ui
