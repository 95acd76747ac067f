// Just enough of the Arduino/Teensy API, on a PC, to compile the sketch's
// framing and command handling: Serial records what is written and plays
// back what the host sends; SPI, pins and the timer do nothing.
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
inline void delay(int) {}
inline void pinMode(int, int) {}
inline void digitalWrite(int, int) {}

struct SPISettings {
    SPISettings(uint32_t, int, int) {}
};
struct SPIClass {
    void begin() {}
    void beginTransaction(const SPISettings&) {}
    void endTransaction() {}
    uint8_t transfer(uint8_t) { return 0; }
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
