// SiteGrid: names of cells and the moving selection.
#include "core/compliance/SiteGrid.h"

#include <charconv>
#include <stdexcept>

namespace tactiscope::core::compliance {

SiteGrid::SiteGrid(int rows, int columns)
    : m_rows(rows),
      m_columns(columns)
{
    if (rows < 1 || rows > kMaxRows || columns < 1 || columns > kMaxColumns)
        throw std::invalid_argument("a site grid has 1 to " + std::to_string(kMaxRows) + " rows and 1 to " +
                                    std::to_string(kMaxColumns) + " columns, not " + std::to_string(rows) + " × " +
                                    std::to_string(columns));
}

void SiteGrid::select(SiteCell cell)
{
    if (cell.row < 0 || cell.row >= m_rows || cell.column < 0 || cell.column >= m_columns) return;
    m_current = cell;
}

void SiteGrid::advance()
{
    const int next = (m_current.row * m_columns + m_current.column + 1) % (m_rows * m_columns);
    m_current = {next / m_columns, next % m_columns};
}

std::string SiteGrid::name(SiteCell cell)
{
    return std::string(1, static_cast<char>('A' + cell.row)) + std::to_string(cell.column + 1);
}

std::optional<SiteCell> SiteGrid::cellOf(std::string_view name)
{
    if (name.size() < 2 || name.front() < 'A' || name.front() >= 'A' + kMaxRows) return std::nullopt;
    int column = 0;
    const auto* end = name.data() + name.size();
    const auto [rest, error] = std::from_chars(name.data() + 1, end, column);
    if (error != std::errc() || rest != end || column < 1 || column > kMaxColumns) return std::nullopt;
    return SiteCell{name.front() - 'A', column - 1};
}

}  // namespace tactiscope::core::compliance
