// AboutText: the About box's text.
#include "ui/common/AboutText.h"

#include "core/Version.h"

#include <QObject>

namespace tactiscope::ui {

QString aboutText()
{
    return QObject::tr(
               "<h3>Tactiscope %1</h3>"
               "<p>An inspection workstation for cantilever tactile sensors.</p>"
               "<p>It implements three published sensors:</p><ol>"
               "<li><i>A tactile sensor capable of mechanical adaptation and its use as a surface deflection "
               "detector</i>: the viscous-capsule probe and its partial-correlation detector (panel scan).</li>"
               "<li><i>Tactile Sensor for Compliance Detection</i>: two cantilevers of different stiffness "
               "(palpation).</li>"
               "<li><i>Extra-Soft Tactile Sensor for Sensitive Force/Displacement Measurement with High Linearity "
               "Based on a Uniform Strength Beam</i>: the capacitive beam.</li></ol>"
               "<p>Licensed under the GNU General Public License, version 3 or later: you may share and change it "
               "under its terms. It comes with no warranty.</p>"
               "<p>Built with Qt %2, QCustomPlot, SQLite, Eigen, hidapi and libserialport.</p>")
        .arg(QString::fromUtf8(core::versionString()), QString::fromLatin1(qVersion()));
}

}  // namespace tactiscope::ui
