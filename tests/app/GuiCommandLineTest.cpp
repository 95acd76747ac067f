// `tactiscope --help` and `--version` answer where there is no display (a
// script, ssh, CI): before, the QApplication aborted (exit 134).
#include <QProcess>
#include <QProcessEnvironment>

#include <gtest/gtest.h>

namespace {

struct GuiRun {
    int exitCode = -1;
    QString out;
};

GuiRun runWithoutDisplay(const QStringList& arguments)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) environment.remove(name);
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(TACTISCOPE_GUI), arguments);
    process.waitForFinished(30000);
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromUtf8(process.readAllStandardOutput())};
}

}  // namespace

TEST(GuiCommandLine, HelpAndVersionNeedNoDisplay)
{
    const GuiRun help = runWithoutDisplay({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_TRUE(help.out.contains("--scenario")) << help.out.toStdString();
    EXPECT_TRUE(help.out.contains("--mode")) << help.out.toStdString();
    const GuiRun version = runWithoutDisplay({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_TRUE(version.out.startsWith("Tactiscope ")) << version.out.toStdString();
}
