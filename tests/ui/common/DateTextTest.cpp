// How the UI writes dates and times (issue 37): the user's locale in local
// time on screen, ISO 8601 with the offset in files, a stored UTC text
// read back exactly and a text that is no time given back unchanged.
// Expected texts are written by hand for a fixed zone and locale.
#include "ui/common/DateText.h"

#include <QLocale>

#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

using namespace tactiscope::ui;

namespace {

// Central European time (UTC+1 in November) and a US English locale for
// the hand-written texts; the machine's own back after.
class DateText : public ::testing::Test {
protected:
    void SetUp() override
    {
        const char* tz = std::getenv("TZ");
        m_savedZone = tz ? std::optional<std::string>(tz) : std::nullopt;
        setZone("Europe/Berlin");
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }
    void TearDown() override
    {
        if (m_savedZone)
            setZone(m_savedZone->c_str());
        else {
            unsetenv("TZ");
            tzset();
        }
        QLocale::setDefault(m_savedLocale);
    }
    static void setZone(const char* zone)
    {
        setenv("TZ", zone, 1);
        tzset();
    }

private:
    std::optional<std::string> m_savedZone;
    QLocale m_savedLocale;
};

}  // namespace

TEST_F(DateText, AStoredUtcTimeReadsBackToTheMillisecond)
{
    const QDateTime t = storedTime("2026-11-24T21:49:56.890Z");
    ASSERT_TRUE(t.isValid());
    EXPECT_EQ(t.toMSecsSinceEpoch(), 1795556996890LL);  // 20 781 days × 86 400 s + 78 596.890 s, counted by hand
    EXPECT_FALSE(storedTime("yesterday").isValid());
    EXPECT_FALSE(storedTime("").isValid());
}

TEST_F(DateText, OnScreenTheLocalesDateAndLocalTimeWithSeconds)
{
    // 21:49:56 UTC is 22:49:56 in Berlin in November.
    EXPECT_EQ(screenDateTime(std::string("2026-11-24T21:49:56.890Z")), QStringLiteral("11/24/26 10:49:56 PM"));
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(screenDateTime(std::string("2026-11-24T21:49:56.890Z")), QStringLiteral("24.11.26 22:49:56"));
    EXPECT_EQ(screenDate(QDate(2026, 11, 24)), QStringLiteral("24.11.26"));
}

TEST_F(DateText, InFilesIso8601InLocalTimeWithItsOffset)
{
    EXPECT_EQ(fileDateTime(std::string("2026-11-24T21:49:56.890Z")), QStringLiteral("2026-11-24T22:49:56+01:00"));
    EXPECT_EQ(fileDateTime(std::string("2026-07-01T12:00:00Z")), QStringLiteral("2026-07-01T14:00:00+02:00"));
}

TEST_F(DateText, ATextThatIsNoTimeIsGivenBackAsItIs)
{
    EXPECT_EQ(screenDateTime(std::string("not a time")), QStringLiteral("not a time"));
    EXPECT_EQ(fileDateTime(std::string("")), QString());
}
