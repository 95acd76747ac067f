// A field for one physical quantity: the number in a display unit (mm, GPa,
// pF…) with the unit beside it, the value handed out in SI. A line edit
// rather than a spin box, so a value keeps every digit it was given
// (0.000462 m stays 0.462 mm) and none are padded on. What is not a number
// in the allowed range turns the field red and reads as no value.
#pragma once

#include "ui/common/DisplayUnits.h"

#include <QWidget>

#include <optional>

class QLabel;
class QLineEdit;

namespace tactiscope::ui {

class QuantityEdit : public QWidget {
    Q_OBJECT

public:
    // Values must lie in (minimum, maximum), in SI. `unit.symbol` may be
    // empty for a pure number.
    QuantityEdit(const DisplayUnit& unit, double minimum_si, double maximum_si, QWidget* parent = nullptr);

    void setValue(double si);
    void clear();
    // The value in SI; none when the text is not a number in range.
    std::optional<double> value() const;
    // "must be a number between 0 and 1000 mm" when value() is none.
    QString problem() const;
    QLineEdit* lineEdit() const { return m_edit; }

signals:
    void edited();  // by the user, not by setValue()

protected:
    void changeEvent(QEvent* event) override;

private:
    void showValidity();

    DisplayUnit m_unit;
    double m_minimum;
    double m_maximum;
    QLineEdit* m_edit;
    QLabel* m_symbol;
};

}  // namespace tactiscope::ui
