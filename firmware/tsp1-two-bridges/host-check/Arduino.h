// Just enough of the Arduino/Teensy API, on a PC, to compile the sketch's
// framing, command handling and detector: Serial records what is written
// and plays back what the host sends; pins and the buzzer record their
// state; SPI plays back the ADC codes a test queues; the timer does nothing.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#define MSBFIRST 1
#define SPI_MODE1 1
#define OUTPUT 1
#define LOW 0
#define HIGH 1

inline uint32_t HW_OCOTP_CFG1 = 0x1234ABCD;
inline uint32_t fakeMicros = 0;
inline uint32_t micros()
{
    return fakeMicros;
}
inline uint32_t millis()
{
    return fakeMicros / 1000;
}
inline void delay(int) {}
inline void pinMode(int, int) {}
inline int pinLevel[64] = {};
inline void digitalWrite(int pin, int level)
{
    pinLevel[pin] = level;
}
inline unsigned toneHz[64] = {};
inline void tone(int pin, unsigned hz)
{
    toneHz[pin] = hz;
}
inline void noTone(int pin)
{
    toneHz[pin] = 0;
}

struct SPISettings {
    SPISettings(uint32_t, int, int) {}
};
struct SPIClass {
    void begin() {}
    void beginTransaction(const SPISettings&) {}
    void endTransaction() {}
    // The bytes the ADCs answer with, in order; 0 when none are queued.
    std::vector<uint8_t> answers;
    uint8_t transfer(uint8_t)
    {
        if (answers.empty()) return 0;
        const uint8_t b = answers.front();
        answers.erase(answers.begin());
        return b;
    }
} SPI;

struct SerialClass {
    std::vector<uint8_t> out, in;
    void begin(int) {}
    void write(const uint8_t* p, size_t n) { out.insert(out.end(), p, p + n); }
    int available() { return static_cast<int>(in.size()); }
    int read()
    {
        const int c = in.front();
        in.erase(in.begin());
        return c;
    }
} Serial;

struct IntervalTimer {
    void begin(void (*)(), float) {}
};
