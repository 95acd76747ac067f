// main() for GoogleTest binaries that need real Qt widgets: defaults to the
// offscreen platform so tests run without a display, then creates the
// QApplication that widgets require. QStandardPaths' test mode keeps the
// tests' settings and session stores out of the user's own, and a home of
// its own per process keeps them from the other test processes ctest runs
// at the same time (a profile one test made active was read by another).
#include <QApplication>
#include <QDir>
#include <QStandardPaths>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char* argv[])
{
    setenv("QT_QPA_PLATFORM", "offscreen", 0);  // keep an explicit choice
    char home[] = "/tmp/tactiscope-ui-test-XXXXXX";
    if (!mkdtemp(home)) {
        std::perror("tactiscope tests: a home of their own");
        return 1;
    }
    setenv("HOME", home, 1);
    ::testing::InitGoogleTest(&argc, argv);
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName(QStringLiteral("Tactiscope"));
    QApplication::setApplicationName(QStringLiteral("Tactiscope tests"));
    const int result = RUN_ALL_TESTS();
    QDir(QString::fromLocal8Bit(home)).removeRecursively();
    return result;
}
