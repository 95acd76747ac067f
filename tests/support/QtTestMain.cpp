// main() for GoogleTest binaries that need real Qt widgets: defaults to the
// offscreen platform so tests run without a display, then creates the
// QApplication that widgets require.
#include <QApplication>

#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char* argv[])
{
    setenv("QT_QPA_PLATFORM", "offscreen", 0);  // keep an explicit choice
    ::testing::InitGoogleTest(&argc, argv);
    QApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
