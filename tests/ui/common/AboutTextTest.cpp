// Help → About names the version the build was made from, the three papers
// and the licence.
#include "ui/common/AboutText.h"

#include "core/Version.h"

#include <gtest/gtest.h>

using namespace tactiscope;

TEST(AboutText, NamesTheBuildThePapersAndTheLicence)
{
    const QString text = ui::aboutText();
    const QString version = QString::fromUtf8(core::versionString());
    EXPECT_FALSE(version.isEmpty());
    EXPECT_TRUE(text.contains(version)) << version.toStdString();
    for (const char* title : {"use as a surface deflection detector", "Tactile Sensor for Compliance Detection",
                              "Based on a Uniform Strength Beam"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(title))) << title;
    EXPECT_TRUE(text.contains(QStringLiteral("GNU General Public License, version 3 or later")));
}
