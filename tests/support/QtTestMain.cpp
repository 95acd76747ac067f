// main() for GoogleTest binaries that need real Qt widgets: defaults to the
// offscreen platform so tests run without a display, then creates the
// QApplication that widgets require. QStandardPaths' test mode keeps the
// tests' settings and session stores out of the user's own.
#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char* argv[])
{
    setenv("QT_QPA_PLATFORM", "offscreen", 0);  // keep an explicit choice
    ::testing::InitGoogleTest(&argc, argv);
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName(QStringLiteral("Tactiscope"));
    QApplication::setApplicationName(QStringLiteral("Tactiscope tests"));
    return RUN_ALL_TESTS();
}
