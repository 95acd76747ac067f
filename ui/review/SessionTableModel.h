// The sessions of a store as a table: date, mode, subject, operator,
// duration, status, verdict, event count and (on a central store) station. Each cell also gives a sort
// key (Qt::UserRole) so a proxy sorts dates and durations as numbers, not
// as text; interrupted sessions are marked with an icon and a colour.
#pragma once

#include "core/storage/SessionSource.h"

#include <QAbstractTableModel>

#include <cstdint>
#include <vector>

namespace tactiscope::ui {

class SessionTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Started, Mode, Subject, Operator, Duration, Status, Verdict, Events, Station, ColumnCount };
    static constexpr int kSortRole = Qt::UserRole;
    static constexpr int kIdRole = Qt::UserRole + 1;

    using QAbstractTableModel::QAbstractTableModel;

    void setSessions(std::vector<core::storage::SessionSummary> sessions);
    const core::storage::SessionSummary* summaryAt(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    std::vector<core::storage::SessionSummary> m_sessions;
};

}  // namespace tactiscope::ui
