// SessionTableModel: one row per stored session.
#include "ui/review/SessionTableModel.h"
#include "ui/common/DateText.h"
#include "ui/common/VocabularyText.h"

#include <QApplication>
#include <QColor>
#include <QStyle>

namespace tactiscope::ui {
namespace {

QString text(const std::string& s)
{
    return QString::fromStdString(s);
}

bool isInterrupted(const core::storage::SessionSummary& s)
{
    return s.status == core::SessionStatus::Interrupted;
}

}  // namespace

void SessionTableModel::setSessions(std::vector<core::storage::SessionSummary> sessions)
{
    beginResetModel();
    m_sessions = std::move(sessions);
    endResetModel();
}

const core::storage::SessionSummary* SessionTableModel::summaryAt(int row) const
{
    if (row < 0 || row >= rowCount()) return nullptr;
    return &m_sessions[static_cast<std::size_t>(row)];
}

int SessionTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_sessions.size());
}

int SessionTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SessionTableModel::data(const QModelIndex& index, int role) const
{
    const auto* s = summaryAt(index.row());
    if (!s) return {};
    if (role == kIdRole) return QVariant::fromValue<qint64>(s->id);
    const bool interrupted = isInterrupted(*s);
    if (role == Qt::ForegroundRole && interrupted) return QColor(0xa0, 0x50, 0x00);
    if (role == Qt::DecorationRole && index.column() == Status && interrupted)
        return QApplication::style()->standardIcon(QStyle::SP_MessageBoxWarning);
    if (role == Qt::ToolTipRole && interrupted)
        return tr("The recording ended without being stopped (a crash, a power cut or a full disk); every sample "
                  "written before that was kept.");
    if (role == Qt::TextAlignmentRole && (index.column() == Duration || index.column() == Events))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != kSortRole) return {};

    const bool sortKey = role == kSortRole;
    switch (index.column()) {
    case Started:
        // Sessions started in the same millisecond keep the order they were written in.
        return sortKey ? QVariant(QStringLiteral("%1#%2").arg(text(s->startedUtc)).arg(s->id, 12, 10, QLatin1Char('0')))
                       : QVariant(screenDateTime(s->startedUtc));
    case Mode:
        return wordText(s->metadata.mode);
    case Subject:
        return text(s->metadata.subject);
    case Operator:
        return text(s->metadata.operatorName);
    case Duration:
        return sortKey ? QVariant(s->duration_s()) : QVariant(durationText(s->duration_s()));
    case Status:
        return wordText(s->status);
    case Verdict:
        return wordText(s->verdict);
    case Events:
        return QVariant::fromValue<qulonglong>(s->eventCount);
    case Station:
        return text(s->station);
    default:
        return {};
    }
}

QVariant SessionTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Started:
        return tr("Started");
    case Mode:
        return tr("Mode");
    case Subject:
        return tr("Subject");
    case Operator:
        return tr("Operator");
    case Duration:
        return tr("Duration");
    case Status:
        return tr("Status");
    case Verdict:
        return tr("Verdict");
    case Events:
        return tr("Events");
    case Station:
        return tr("Station");
    default:
        return {};
    }
}

}  // namespace tactiscope::ui
