// ReportDocument: the report's HTML, its plot resource, and the PDF.
#include "ui/report/ReportDocument.h"

#include "core/modes/ModeDefinition.h"
#include "ui/calibration/CalibrationText.h"
#include "ui/common/DateText.h"
#include "ui/common/NumberText.h"
#include "ui/common/VocabularyText.h"

#include "core/Version.h"
#include "core/report/DetectorHum.h"
#include "core/report/VerdictTrail.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/SafeOutput.h"
#include "ui/modes/ModeUi.h"
#include "ui/report/ReportHtml.h"
#include "ui/report/ReportPages.h"
#include "ui/report/ReportPlot.h"
#include "ui/report/SignalQualityHtml.h"

#include <QBuffer>
#include <QFileInfo>
#include <QLocale>
#include <QPdfWriter>
#include <QTextDocument>
#include <QUrl>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace tactiscope::ui {
namespace {

using namespace reporthtml;

// The pages have 2 cm margins (ReportPages): an A4 page has 170 mm of text
// width, 642 px of the document's 96 dpi.
constexpr int kTextWidth_px = 640;
constexpr int kLaneHeight_px = 130;  // four lanes and the header fit on the first page

// The page count of a PDF as written: its page tree's root says
// "/Count N" after "/Type /Pages" (Qt's writer makes one root, no subtrees).
int pageCountOf(const QByteArray& pdf)
{
    const qsizetype root = pdf.indexOf("/Type /Pages");
    const qsizetype count = root < 0 ? -1 : pdf.indexOf("/Count ", root);
    int pages = 0;
    for (qsizetype at = count < 0 ? pdf.size() : count + 7;
         at < pdf.size() && std::isdigit(static_cast<unsigned char>(pdf[at])); ++at)
        pages = pages * 10 + (pdf[at] - '0');
    if (pages < 1) throw std::runtime_error("the report was laid out without a page tree");
    return pages;
}

QString calibrationText(const core::calibration::CalibrationRecord& record)
{
    // Its values in words with units, a row each; R² is said with the
    // fit's points below.
    QStringList values;
    for (const QString& value : calibrationValueTexts(record))
        if (!(record.fit.points > 0 && value.startsWith(QStringLiteral("R² ")))) values << value.toHtmlEscaped();
    QString line = QObject::tr("%1 of %2, %3 by %4")
                       .arg(text(record.kind), text(record.sensorName), fileDateTime(record.timestampUtc),
                            orDash(record.operatorName));
    if (record.fit.points > 0)
        line += QObject::tr(" (R² = %1, %2 points)").arg(number(record.fit.rSquared, 5)).arg(record.fit.points);
    return line + QStringLiteral("<br><small>") + values.join(QStringLiteral("<br>")) + QStringLiteral("</small>");
}

QString header(const core::report::ReportData& data)
{
    const auto& s = data.session;
    const auto& m = s.metadata;
    QString device = orDash(m.deviceModel);
    if (!m.deviceSerial.empty()) device += QObject::tr(", serial %1").arg(text(m.deviceSerial));
    if (!m.deviceFirmware.empty()) device += QObject::tr(", firmware %1").arg(text(m.deviceFirmware));
    QStringList calibrations;
    for (const auto& record : data.calibrations) calibrations << calibrationText(record);
    const QString range = data.wholeSession()
                              ? QObject::tr("the whole session, %1 s").arg(number(s.duration_s(), 1))
                              : QObject::tr("%1 s to %2 s of %3 s")
                                    .arg(number(data.from_s, 2), number(data.to_s, 2), number(s.duration_s(), 1));
    qulonglong lost = 0;
    for (const auto& gap : data.gaps) lost += gap.count;
    QString html = QStringLiteral("<table class=header cellspacing=0 cellpadding=2>");
    html += row(QObject::tr("Subject"), orDash(m.subject));
    html += row(QObject::tr("Operator"), orDash(m.operatorName));
    html += row(QObject::tr("Mode"), wordText(m.mode));
    if (!m.site.empty()) html += row(QObject::tr("Site"), text(m.site));
    if (!m.trigger.empty()) html += row(QObject::tr("Triggered on"), text(m.trigger));
    html += row(QObject::tr("Started"), fileDateTime(s.startedUtc).toHtmlEscaped());
    html += row(QObject::tr("Covered"), range);
    html += row(QObject::tr("Device"), device);
    html += row(QObject::tr("Sensor"), orDash(data.sensorName));
    if (!data.derivedBasis.empty())
        html +=
            row(QObject::tr("Computed from"),
                text(data.derivedBasis) +
                    (core::definitionOf(m.mode).noZero.empty() ? QObject::tr(" and the zeros recorded") : QString()));
    else if (!data.derivedProblem.empty())
        html += row(QObject::tr("Physical quantities"),
                    QObject::tr("not computed: %1; the plot shows the raw channels").arg(text(data.derivedProblem)));
    html += row(QObject::tr("Calibration"), calibrations.isEmpty() ? QObject::tr("none recorded with the session")
                                                                   : calibrations.join(QStringLiteral("<br>")));
    const QString losses = lost == 0
                               ? QObject::tr("none lost")
                               : QObject::tr("%1 lost in %2")
                                     .arg(QLocale().toString(lost), countText(static_cast<long long>(data.gaps.size()),
                                                                              QObject::tr("gap"), QObject::tr("gaps")));
    html += row(QObject::tr("Samples"), QObject::tr("%1 Hz, %2 per channel; %3")
                                            .arg(number(s.sampleRate_hz, 1))
                                            .arg(QLocale().toString(static_cast<qulonglong>(s.sampleCount)))
                                            .arg(losses));
    html += row(QObject::tr("Session"), QObject::tr("%1 (%2), %3").arg(s.id).arg(text(s.uuid), wordText(s.status)));
    if (data.tracesLeftOut > 0)
        html += row(QObject::tr("Plotted"),
                    QObject::tr("the first %1 lanes; %2 more are not plotted (every channel is in the session's "
                                "export: tactiscope-cli sessions export)")
                        .arg(data.traces.size())
                        .arg(QLocale().toString(static_cast<qulonglong>(data.tracesLeftOut))));
    if (!m.notes.empty()) html += row(QObject::tr("Notes"), text(m.notes));
    return html + QStringLiteral("</table>");
}

// The largest of a plotted derived quantity over the range, in SI.
std::optional<double> peakOf(const core::report::ReportData& data, const std::string& name)
{
    std::optional<double> peak;
    for (const auto& trace : data.traces) {
        if (trace.channel.descriptor.name != name) continue;
        for (const auto& p : trace.points)
            if (!std::isnan(p.max)) peak = std::max(peak.value_or(p.max), p.max);
    }
    return peak;
}

// A capacitive session's heading: the largest force and deflection read.
QString capacitivePeaks(const core::report::ReportData& data)
{
    if (!data.capacitive) return {};
    const auto force = peakOf(data, "force"), deflection = peakOf(data, "deflection");
    if (!force || !deflection) return {};
    return QObject::tr("Peak tip force %1 µN, deflection %2 mm")
        .arg(number(*force * 1e6, 1), number(*deflection * 1e3, 3));
}

// Said beside the verdict or readings when the mode read the channels as
// stored though the session was recorded through filters: a reader who
// sees the notch in the setup would otherwise think the detector saw it.
QString unfilteredAnalysisNote(const core::report::ReportData& data)
{
    // A mode whose processor reads no channel roles (general) analyses nothing.
    if (core::definitionOf(data.session.metadata.mode).roles.empty()) return {};
    try {
        const auto setup = core::signal::signalSetupFromJson(data.session.metadata.signalSetup);
        if (setup.filters.empty() || setup.analysisFiltered) return {};
    } catch (const std::invalid_argument&) {
        return {};  // the signal-quality section says it is unreadable
    }
    return QStringLiteral("<p class=trail>%1</p>")
        .arg(QObject::tr("The mode's analysis read the channels as stored, not through the filters the session was "
                         "recorded with (those were for the view and the watched values): whatever they took out, "
                         "such as mains hum, was analysed with the signal. See Signal quality."));
}

QString verdictOrReadings(const core::report::ReportData& data)
{
    if (const auto verdict = data.session.verdict) {
        const bool pass = *verdict == core::Verdict::Pass;
        QString html = QStringLiteral("<p class=verdict style='color:%1'>%2 %3</p>")
                           .arg(pass ? QStringLiteral("#2e7d32") : QStringLiteral("#c62828"), QObject::tr("Verdict:"),
                                wordText(*verdict).toUpper());
        QStringList trail;
        if (!data.session.unjudged.empty()) trail << text(core::report::unjudgedTrailLine(data.session.unjudged));
        for (const auto& line : core::report::verdictTrailLines(
                 data.verdicts, [](const std::string& utc) { return fileDateTime(utc).toStdString(); }))
            trail << text(line);
        if (trail.isEmpty())
            trail << QObject::tr("Recorded before verdicts kept a trail: who decided it is not known.");
        return html + QStringLiteral("<p class=trail>%1</p>").arg(trail.join(QStringLiteral("<br>")));
    }
    // Why its readings were not judged (past a critical limit) beside them.
    const QString unjudged =
        data.session.unjudged.empty()
            ? QString()
            : QStringLiteral("<p class=trail>%1</p>")
                  .arg(QObject::tr("No verdict: %1").arg(text(core::storage::unjudgedReason(data.session.unjudged))));
    if (!data.readings.empty()) {
        double sum = 0.0;
        for (const auto& r : data.readings) sum += r.value;
        const auto count = data.readings.size();
        const QString readings =
            countText(static_cast<long long>(count), QObject::tr("reading"), QObject::tr("readings"));
        return QStringLiteral("<p class=verdict>%1</p>")
                   .arg(QObject::tr("%1, mean %2 %3")
                            .arg(readings, number(sum / static_cast<double>(count), 1), text(data.readings[0].unit))) +
               unjudged;
    }
    if (const QString peaks = capacitivePeaks(data); !peaks.isEmpty())
        return QStringLiteral("<p class=verdict>%1</p>").arg(peaks) + unjudged;
    if (!data.session.unjudged.empty())
        return QStringLiteral("<p class=verdict>%1</p>")
            .arg(QObject::tr("No verdict: %1").arg(text(core::storage::unjudgedReason(data.session.unjudged))));
    return QStringLiteral("<p class=verdict>%1</p>").arg(QObject::tr("No verdict recorded"));
}

// A hum the detector read its cantilevers through, which may have made
// its verdict (a PASS with every crossing lost under it).
QString detectorHumNote(const core::report::ReportData& data)
{
    const auto note = core::report::sessionDetectorHum(data.quality.channels, data.session);
    return note ? QStringLiteral("<p class=trail>%1</p>").arg(text(note->text + ".")) : QString();
}

QString verdict(const core::report::ReportData& data)
{
    return verdictOrReadings(data) + unfilteredAnalysisNote(data) + detectorHumNote(data);
}

// The defects as sites (a defect crossed in every stroke is one), then each
// crossing with the site it belongs to.
QString defectTables(const core::report::ReportData& data)
{
    const auto defects = core::storage::defectEventsOf(data.events);
    const QString source = data.analysis == core::storage::kLiveAnalysis
                               ? QObject::tr("the events recorded live")
                               : QObject::tr("the saved re-analysis \"%1\"").arg(text(data.analysis));
    QString html = QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Defect sites (%1)").arg(data.sites.sites.size()));
    html += QStringLiteral("<p>%1</p>").arg(QObject::tr("From %1.").arg(source));
    if (defects.empty()) return html + QStringLiteral("<p>%1</p>").arg(QObject::tr("None found."));
    std::vector<int> siteOf(defects.size());
    std::vector<QStringList> sites;
    for (std::size_t k = 0; k < data.sites.sites.size(); ++k) {
        const auto& site = data.sites.sites[k];
        for (const std::size_t i : site.crossings) siteOf[i] = static_cast<int>(k + 1);
        for (const std::size_t i : site.parts) siteOf[i] = static_cast<int>(k + 1);
        // Each site's place with its standard uncertainty (the value to the
        // uncertainty's decimals, so never "± 0"), a span's ends, or why it
        // has no place, short enough for the column.
        const QString position = text(core::detector::sitePlaceText(site, false));
        sites.push_back({QString::number(k + 1), position, QString::number(site.crossings.size()),
                         QObject::tr("%1 A→B, %2 B→A").arg(site.forward).arg(site.backward),
                         QStringLiteral("%1 – %2").arg(number(site.first_s, 2), number(site.last_s, 2))});
    }
    html += table({QObject::tr("Site"), QObject::tr("Position (mm)"), QObject::tr("Crossings"),
                   QObject::tr("Directions"), QObject::tr("Time (s)")},
                  sites);
    // The method, or why no crossing could be placed ("not placed: no whole
    // stroke between two reversals"), which reads as a sentence of its own.
    const bool placed = data.sites.method.rfind("not placed", 0) != 0;
    const bool byChannel = data.sites.method == "from the position channel";
    html += QStringLiteral("<p><small>%1</small></p>")
                .arg(byChannel ? QObject::tr("Position where the session's position channel had the probe's centre, ± "
                                             "its standard uncertainty (k = 1); see docs/detector.md.")
                     : placed  ? QObject::tr("Position along the stroke from its centre, ± its standard uncertainty "
                                              "(k = 1), from each crossing's time between reversals; the stroke: %1. "
                                              "See docs/detector.md.")
                                    .arg(text(data.sites.method))
                              : QObject::tr("Positions %1; see docs/detector.md.").arg(text(data.sites.method)));
    std::vector<QStringList> crossings;
    for (std::size_t i = 0; i < defects.size(); ++i) {
        const auto& e = defects[i];
        crossings.push_back({number(e.start_s, 3), QString::number(siteOf[i]),
                             e.direction > 0 ? QObject::tr("A then B") : QObject::tr("B then A"), number(e.peakR, 3),
                             number(e.peakLag_s * 1e3, 0),
                             e.speed_m_per_s ? number(*e.speed_m_per_s * 1e3, 0) : QStringLiteral("—")});
    }
    html += QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Crossings (%1)").arg(defects.size()));
    return html + table({QObject::tr("Time (s)"), QObject::tr("Site"), QObject::tr("Order"), QObject::tr("Peak R"),
                         QObject::tr("Lag (ms)"), QObject::tr("Speed (mm/s)")},
                        crossings);
}

QString eventTables(const core::report::ReportData& data, QTextDocument& document)
{
    // The mode's own section (ui/modes/ModeUi.h) first; without one, its readings as a table.
    const auto section = modeUi(data.session.metadata.mode).reportSection;
    QString html = section ? section(data, document) : QString();
    std::vector<QStringList> others;
    bool anyDefect = false;
    for (const auto& e : data.events) {
        anyDefect = anyDefect || e.kind == core::EventKind::Defect;
        // An alarm lasts: from its raise to its clear.
        if (e.kind != core::EventKind::Defect)
            others.push_back({e.end_s > e.start_s ? number(e.start_s, 3) + QStringLiteral("–") + number(e.end_s, 3)
                                                  : number(e.start_s, 3),
                              wordText(e.kind), orDash(e.note)});
    }
    if (core::definitionOf(data.session.metadata.mode).detectsDefects || anyDefect) html += defectTables(data);
    if (!section && !data.readings.empty()) {
        std::vector<QStringList> rows;
        for (const auto& r : data.readings) {
            QString value = number(r.value, 2);
            if (r.standardError) value += QStringLiteral(" ± ") + number(*r.standardError, 2);
            rows.push_back(
                {number(r.start_s, 2), text(r.quantity), value + QStringLiteral(" ") + text(r.unit), orDash(r.site)});
        }
        html += QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Readings (%1)").arg(data.readings.size()));
        html +=
            table({QObject::tr("Time (s)"), QObject::tr("Quantity"), QObject::tr("Value"), QObject::tr("Site")}, rows);
    }
    if (!others.empty()) {
        html += QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Markers, triggers and alarms"));
        html += table({QObject::tr("Time (s)"), QObject::tr("Kind"), QObject::tr("Note")}, others);
    }
    if (!data.annotations.empty()) {
        std::vector<QStringList> rows;
        for (const auto& a : data.annotations) rows.push_back({number(a.time_s, 2), orDash(a.author), text(a.text)});
        html += QStringLiteral("<h2>%1</h2>").arg(QObject::tr("Notes"));
        html += table({QObject::tr("Time (s)"), QObject::tr("By"), QObject::tr("Note")}, rows);
    }
    return html;
}

const char* kStyle = "body { font-family: 'DejaVu Sans'; font-size: 9pt; }"
                     "h1 { font-size: 16pt; margin-bottom: 2px; }"
                     "h2 { font-size: 11pt; margin-top: 14px; margin-bottom: 4px; }"
                     "table.header th { padding-right: 12px; color: #555; font-weight: normal; }"
                     "table.list th { background-color: #eeeeee; }"
                     "table.list td { border-bottom: 1px solid #dddddd; }"
                     "p.verdict { font-size: 14pt; font-weight: bold; margin-top: 10px; margin-bottom: 2px; }"
                     "p.trail { color: #444; }"
                     "p.footer { color: #777; font-size: 7pt; }";

}  // namespace

std::unique_ptr<QTextDocument> buildReportDocument(const core::report::ReportData& data)
{
    auto document = std::make_unique<QTextDocument>();
    document->setDefaultStyleSheet(QString::fromLatin1(kStyle));
    document->setDocumentMargin(0);
    const int plotHeight = kLaneHeight_px * static_cast<int>(std::max<std::size_t>(1, data.traces.size())) + 40;
    const QUrl plotUrl(QStringLiteral("tactiscope://plot.png"));
    document->addResource(QTextDocument::ImageResource, plotUrl,
                          renderReportPlot(data, QSize(kTextWidth_px, plotHeight), kReportImageScale));
    // Titled by its subject, or by its number where it has none (not "— —").
    const QString titled = data.session.metadata.subject.empty() ? QObject::tr("session %1").arg(data.session.id)
                                                                 : text(data.session.metadata.subject);
    QString html = QStringLiteral("<h1>%1</h1>").arg(QObject::tr("Inspection report — %1").arg(titled));
    html += header(data);
    html += verdict(data);
    html += QStringLiteral("<p><img src='%1' width=%2 height=%3></p>")
                .arg(plotUrl.toString())
                .arg(kTextWidth_px)
                .arg(plotHeight);
    const QString shaded = core::definitionOf(data.session.metadata.mode).detectsDefects
                               ? QObject::tr("Shaded: defects (orange A then B, purple B then A), lost samples "
                                             "(grey); dashed: markers; teal dashed: the detector's threshold.")
                               : QObject::tr("Shaded: readings (green), lost samples (grey); dashed: markers.");
    // The red bands of limit alarms, when the session has any.
    const bool alarms = std::ranges::any_of(data.events, [](const core::storage::SessionEvent& e) {
        return e.kind == core::EventKind::Alarm && e.end_s > e.start_s;
    });
    html += QStringLiteral("<p><small>%1 %2%3</small></p>")
                .arg(shaded, alarms ? QObject::tr("Red: a limit alarm, from its raise to its clear. ") : QString(),
                     QObject::tr("Bands show each stretch's minimum and maximum."));
    html += eventTables(data, *document);
    html += signalQualitySection(data.quality);
    html += QStringLiteral("<p class=footer>%1</p>")
                .arg(QObject::tr("Tactiscope %1 (recorded with %2), %3")
                         .arg(QString::fromUtf8(core::versionString()), orDash(data.session.appVersion),
                              fileDateTime(QDateTime::currentDateTime())));
    document->setHtml(html);
    return document;
}

int writeReportPdf(const core::report::ReportData& data, const QString& path)
{
    // Laid out in memory (a report is a few MB at most), then written
    // through core's atomic output, which checks every write and the close:
    // QSaveFile committed a truncated PDF on a full disk, as QPdfWriter does
    // not pass its write errors on.
    QByteArray pdf;
    {
        QBuffer buffer(&pdf);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setTitle(QObject::tr("Inspection report, session %1").arg(data.session.id));
        writer.setCreator(QStringLiteral("Tactiscope %1").arg(QString::fromUtf8(core::versionString())));
        printPages(*buildReportDocument(data), writer);
    }
    const int pages = pageCountOf(pdf);
    core::storage::writeAtomically(path.toStdString(), [&pdf](std::ostream& out) {  // throws StorageError
        out.write(pdf.constData(), static_cast<std::streamsize>(pdf.size()));
    });
    return pages;
}

}  // namespace tactiscope::ui
