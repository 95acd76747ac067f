// The sites of a phantom as a grid of rows × columns (A1, A2, … B1, …) and
// the one the next press is taken at. The live session keeps it, so the
// site a press is stored with and the site the grid map shows are one:
// only a press that went into the recording moves the selection on, row by
// row, wrapping at the end.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::compliance {

struct SiteCell {
    int row = 0;
    int column = 0;
    friend bool operator==(const SiteCell&, const SiteCell&) = default;
};

class SiteGrid {
public:
    static constexpr int kMaxRows = 26;  // rows are letters
    static constexpr int kMaxColumns = 40;

    // Throws std::invalid_argument outside 1…kMaxRows × 1…kMaxColumns.
    SiteGrid(int rows, int columns);

    int rows() const { return m_rows; }
    int columns() const { return m_columns; }
    SiteCell current() const { return m_current; }
    std::string currentName() const { return name(m_current); }
    // A cell outside the grid is ignored.
    void select(SiteCell cell);
    void advance();

    // (1, 2) → "B3"; and back (none for a name that is not a cell).
    static std::string name(SiteCell cell);
    static std::optional<SiteCell> cellOf(std::string_view name);

private:
    int m_rows, m_columns;
    SiteCell m_current;
};

}  // namespace tactiscope::core::compliance
