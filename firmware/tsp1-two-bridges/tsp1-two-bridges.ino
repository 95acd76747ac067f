// Reference firmware for a Tactiscope probe: two strain-gauge bridges (the
// two cantilevers of a panel-scan or compliance probe), each read by a TI
// ADS1220 24-bit bridge ADC, streamed in the TSP/1 binary protocol
// (docs/protocol.md) over USB serial at 500 samples per second and channel.
//
// Board: PJRC Teensy 4.0 (any Arduino-compatible board with SPI and native
// USB works; pins below). Build with the Arduino IDE or arduino-cli and
// Teensyduino. The test suite compiles it on a PC with the detector
// (host-check/); docs/firmware.md says how to test a board against
// `tactiscope-cli record`.
//
// It also runs the surface-deflection detector of seed 000 itself
// (firmware/probe-detector, single precision: src/ links to it), lights an
// LED and sounds a buzzer on a defect, and sends its decisions as three
// channels of kind "decision" (out, rab, rba) beside the two strains, so
// the workstation can check them against its own (docs/firmware.md), with
// the lags of those R (lag_ab, lag_ba).
//
// Wiring (both ADS1220 on the same SPI bus, each with its own chip select):
//   SCLK 13, DOUT/MISO 12, DIN/MOSI 11; bridge A: CS 10; bridge B: CS 8;
//   defect LED on pin 2 (through 330 Ω to ground), a piezo buzzer on pin 3.
//   Shunt calibration: pins 4 (bridge A) and 5 (bridge B) each drive a
//   reed relay (or a photo-MOS switch) that puts a 100 kΩ 0.1 % resistor
//   across the bridge's first active gauge (TSP/1 command 6): Tactiscope's
//   shunt check compares the step with the shunt, gauge and bridge.
//   Each bridge: excitation from the board's 3.3 V
//   (AVDD), signal on AIN0/AIN1, the excitation also on REFP0/REFN0 so the
//   reading is ratiometric (supply drift cancels).

#include <SPI.h>

#include "src/probe_detector.h"

namespace {

// ---- Probe identity and the bridges' conversion, reported in INFO --------

const char* const kVendor = "Tactiscope reference";
const char* const kModel = "TSP-2 two-bridge";
const char* const kFirmware = "1.0.0";
const char* const kChannelNames[2] = {"a", "b"};

// A half bridge in bending (two active gauges, +ε and −ε) gives
// V_out / V_ex = GF·ε/2. The ADS1220 with the excitation as its reference
// reads code = (V_out / V_ex)·gain·2^23, so ε = code · 2 / (GF·gain·2^23).
// Tactiscope's gauge-factor wizard then measures the true GF; this is only
// the nominal conversion.
constexpr float kGaugeFactor = 2.0f;
constexpr float kGain = 128.0f;
constexpr float kStrainPerCount = 2.0f / (kGaugeFactor * kGain * 8388608.0f);

// ---- Pins and timing -------------------------------------------------------

constexpr int kChipSelect[2] = {10, 8};
constexpr int kDefectLed = 2;
constexpr int kBuzzer = 3;
constexpr int kShunt[2] = {4, 5};  // a relay putting the shunt across bridge A's, B's first gauge
constexpr uint32_t kDefectShow_ms = 200;  // how long the LED and the buzzer tell a defect
constexpr unsigned kBuzzer_hz = 2700;     // a piezo's loudest
constexpr uint8_t kChannels = 7;          // a, b, then the detector's out, rab, rba, lag_ab, lag_ba
constexpr float kRPerCount = 1.0f / 1073741824.0f;  // R sent as int32 in steps of 2^-30
constexpr uint32_t kDefaultRate_mHz = 500000;  // 500 Hz
constexpr uint16_t kSamplesPerFrame = 10;      // 50 frames/s at 500 Hz

// ---- TSP/1 framing ---------------------------------------------------------

constexpr uint8_t kInfo = 0x01, kData = 0x02, kStatus = 0x03, kCommand = 0x10;
uint16_t txSequence = 0;

uint16_t crc16Ccitt(const uint8_t* p, size_t n, uint16_t crc = 0xFFFF)
{
    while (n--) {
        crc ^= static_cast<uint16_t>(*p++) << 8;
        for (int i = 0; i < 8; ++i) crc = (crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1;
    }
    return crc;
}

// A payload under construction: little-endian integers, floats and strings.
struct Payload {
    uint8_t bytes[512];
    uint16_t size = 0;
    void u8(uint8_t v) { bytes[size++] = v; }
    void u16(uint16_t v) { u8(v & 0xFF), u8(v >> 8); }
    void u32(uint32_t v) { u16(v & 0xFFFF), u16(v >> 16); }
    void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
    void f32(float v)
    {
        uint32_t bits;
        memcpy(&bits, &v, 4);
        u32(bits);
    }
    void str(const char* s)
    {
        const size_t n = strlen(s) > 255 ? 255 : strlen(s);
        u8(static_cast<uint8_t>(n));
        memcpy(bytes + size, s, n);
        size += n;
    }
};

// Header, payload and CRC (over everything after the sync) in one write, so
// a frame is never interleaved with another.
void sendFrame(uint8_t type, const Payload& payload)
{
    static uint8_t frame[8 + sizeof Payload::bytes + 2];
    frame[0] = 0xA5, frame[1] = 0x5A, frame[2] = 0x01, frame[3] = type;
    frame[4] = payload.size & 0xFF, frame[5] = payload.size >> 8;
    frame[6] = txSequence & 0xFF, frame[7] = txSequence >> 8;
    memcpy(frame + 8, payload.bytes, payload.size);
    const uint16_t crc = crc16Ccitt(frame + 2, 6 + payload.size);
    frame[8 + payload.size] = crc & 0xFF;
    frame[9 + payload.size] = crc >> 8;
    Serial.write(frame, 10 + payload.size);
    ++txSequence;  // wraps at 65536, as the protocol says
}

uint32_t rate_mHz = kDefaultRate_mHz;

void sendInfo()
{
    char serial[24];
    snprintf(serial, sizeof serial, "%08lX", static_cast<unsigned long>(HW_OCOTP_CFG1));  // the chip's unique id
    Payload p;
    p.u8(1);  // layout
    p.str(kVendor);
    p.str(kModel);
    p.str(serial);
    p.str(kFirmware);
    p.u32(rate_mHz);
    p.u8(kChannels);
    for (const char* name : kChannelNames) {
        p.str(name);
        p.str("");  // strain has no unit
        p.u8(0);    // kind: strain
        p.f32(kStrainPerCount);
        p.f32(0.0f);
    }
    // The detector's decisions: kind 5, "decision" (protocol.md § 1).
    const struct {
        const char* name;
        const char* unit;
        float scale;
    } decisions[5] = {
        {"out", "", 1.0f}, {"rab", "", kRPerCount}, {"rba", "", kRPerCount}, {"lag_ab", "s", 1e-6f}, {"lag_ba", "s", 1e-6f}};
    for (const auto& d : decisions) {
        p.str(d.name);
        p.str(d.unit);
        p.u8(5);
        p.f32(d.scale);
        p.f32(0.0f);
    }
    sendFrame(kInfo, p);
}

void sendStatus(uint8_t level, const char* message)
{
    Payload p;
    p.u8(level);
    p.str(message);
    sendFrame(kStatus, p);
}

// ---- ADS1220 ---------------------------------------------------------------

const SPISettings kAdcSpi(4000000, MSBFIRST, SPI_MODE1);

void adcCommand(int adc, uint8_t command)
{
    SPI.beginTransaction(kAdcSpi);
    digitalWrite(kChipSelect[adc], LOW);
    SPI.transfer(command);
    digitalWrite(kChipSelect[adc], HIGH);
    SPI.endTransaction();
}

// Register 0: AIN0−AIN1, gain 128, PGA on. Register 1: the data rate (turbo
// mode, continuous conversion). Register 2: external reference REFP0/REFN0,
// 50/60 Hz filter off (it limits the rate). Register 3: defaults.
void adcConfigure(int adc, uint8_t rateBits)
{
    const uint8_t registers[4] = {0x0E, static_cast<uint8_t>((rateBits << 5) | 0x14), 0x40, 0x00};
    SPI.beginTransaction(kAdcSpi);
    digitalWrite(kChipSelect[adc], LOW);
    SPI.transfer(0x43);  // WREG from register 0, 4 registers
    for (uint8_t r : registers) SPI.transfer(r);
    digitalWrite(kChipSelect[adc], HIGH);
    SPI.endTransaction();
    adcCommand(adc, 0x08);  // START/SYNC: continuous conversions from now
}

// RDATA: the newest complete conversion, whatever the conversion in progress.
int32_t adcRead(int adc)
{
    SPI.beginTransaction(kAdcSpi);
    digitalWrite(kChipSelect[adc], LOW);
    SPI.transfer(0x10);
    uint32_t raw = 0;
    for (int i = 0; i < 3; ++i) raw = (raw << 8) | SPI.transfer(0x00);
    digitalWrite(kChipSelect[adc], HIGH);
    SPI.endTransaction();
    return static_cast<int32_t>(raw << 8) >> 8;  // sign-extend the 24-bit code
}

// The ADC's turbo-mode rate at or above the one asked for (40 … 2000 SPS).
uint8_t rateBitsFor(uint32_t millihertz)
{
    const uint32_t turbo_hz[7] = {40, 90, 180, 350, 660, 1200, 2000};
    for (uint8_t bits = 0; bits < 7; ++bits)
        if (turbo_hz[bits] * 1000 >= millihertz) return bits;
    return 6;
}

// ---- The detector on the probe ----------------------------------------------

// The workstation's live lag set at this rate: one sample to 150 ms in
// steps of one sample, λ = c (the paper's at 500 Hz). Above 500 Hz that is
// more lags than this build holds: the detector is off and says so.
pd_detector detector;
bool detecting = false;
uint32_t defectShownAt_ms = 0;
bool defectShown = false;

void setUpDetector()
{
    const double dt = 1000.0 / static_cast<double>(rate_mHz);
    const unsigned lags = static_cast<unsigned>(0.150 / dt + 1e-9);
    static unsigned short lag[PD_MAX_LAGS];
    static double lambda[PD_MAX_LAGS];
    detecting = lags >= 1 && lags <= PD_MAX_LAGS;
    if (!detecting) return;
    for (unsigned i = 0; i < lags; ++i) {
        lag[i] = static_cast<unsigned short>(i + 1);
        lambda[i] = static_cast<double>(i + 1) * dt;
    }
    const pd_config config = {dt, lags, lag, lambda, 7e-6, 0.85, 0};
    detecting = pd_init(&detector, &config) == PD_OK;
}

// The LED and the buzzer on a defect, for kDefectShow_ms after the last
// sample that decided one.
void showDecision(signed char decision)
{
    const uint32_t now = millis();
    if (decision != 0) {
        if (!defectShown) {
            digitalWrite(kDefectLed, HIGH);
            tone(kBuzzer, kBuzzer_hz);
        }
        defectShown = true;
        defectShownAt_ms = now;
    } else if (defectShown && now - defectShownAt_ms >= kDefectShow_ms) {
        digitalWrite(kDefectLed, LOW);
        noTone(kBuzzer);
        defectShown = false;
    }
}

// ---- Sampling --------------------------------------------------------------

bool streaming = false;
int32_t tare[2] = {0, 0};
IntervalTimer sampleTimer;
volatile bool sampleDue = false;
void onSampleTimer() { sampleDue = true; }

Payload dataFrame;
uint16_t samplesInFrame = 0;

void startFrame()
{
    dataFrame.size = 0;
    samplesInFrame = 0;
}

// The frame's header goes in with its first sample, so the timestamp is the
// device clock at that sample.
void addSample(const int32_t (&values)[2])
{
    if (samplesInFrame == 0) {
        dataFrame.u32(micros());
        dataFrame.u8(kChannels);
        dataFrame.u8(2);  // format: int32
        dataFrame.u16(kSamplesPerFrame);
    }
    for (int32_t v : values) dataFrame.i32(v);
    // The detector on the strains the host receives (code × the INFO scale).
    pd_output o = {0, 0.0f, 0.0f, 0, 0, 0};
    if (detecting)
        pd_step(&detector, static_cast<float>(values[0]) * kStrainPerCount,
                static_cast<float>(values[1]) * kStrainPerCount, &o);
    showDecision(o.decision);
    dataFrame.i32(o.decision);
    dataFrame.i32(static_cast<int32_t>(o.rab / kRPerCount));
    dataFrame.i32(static_cast<int32_t>(o.rba / kRPerCount));
    // The lags of those R in microseconds (the INFO scales them to seconds).
    const uint32_t period_us = 1000000000u / rate_mHz;
    dataFrame.i32(static_cast<int32_t>(o.lag_ab * period_us));
    dataFrame.i32(static_cast<int32_t>(o.lag_ba * period_us));
    if (++samplesInFrame == kSamplesPerFrame) {
        sendFrame(kData, dataFrame);
        startFrame();
    }
}

void applyRate(uint32_t millihertz)
{
    if (millihertz < 1000 || millihertz > 1000000) {
        sendStatus(1, "rate out of range (1-1000 Hz); kept");
        return;
    }
    rate_mHz = millihertz;
    setUpDetector();
    if (!detecting) sendStatus(1, "the detector runs at up to 500 Hz: off at this rate");
    for (int adc = 0; adc < 2; ++adc) adcConfigure(adc, rateBitsFor(rate_mHz));
    sampleTimer.begin(onSampleTimer, 1e9f / static_cast<float>(rate_mHz));  // period in µs
    startFrame();
}

// ---- Commands from the host ------------------------------------------------

uint8_t rx[64];
uint16_t rxSize = 0;

void handleCommand(const uint8_t* payload, uint16_t size)
{
    if (size < 1) return;
    switch (payload[0]) {
    case 1:  // start
        startFrame();
        if (detecting) pd_reset(&detector);  // from silence, as the host's detector starts
        streaming = true;
        break;
    case 2:  // stop
        streaming = false;
        break;
    case 3:  // set rate, u32 millihertz
        if (size >= 5)
            applyRate(static_cast<uint32_t>(payload[1]) | static_cast<uint32_t>(payload[2]) << 8 |
                      static_cast<uint32_t>(payload[3]) << 16 | static_cast<uint32_t>(payload[4]) << 24);
        sendInfo();  // the host learns the rate now in force
        break;
    case 4:  // tare: the present readings become zero
        for (int adc = 0; adc < 2; ++adc) tare[adc] = adcRead(adc);
        sendStatus(0, "tared");
        break;
    case 5:  // request info
        sendInfo();
        break;
    case 6:  // shunt: u8 channel, u8 1 on / 0 off; answered either way
        if (size < 3 || payload[2] > 1) {
            sendStatus(2, "shunt: malformed command");
        } else if (payload[1] > 1) {
            sendStatus(2, "shunt: only channels a and b have a bridge");
        } else {
            digitalWrite(kShunt[payload[1]], payload[2] ? HIGH : LOW);
            sendStatus(0, payload[2] ? (payload[1] ? "shunt on b" : "shunt on a")
                                     : (payload[1] ? "shunt off b" : "shunt off a"));
        }
        break;
    default:
        sendStatus(1, "unknown command");
    }
}

// Collects bytes into frames; on a bad frame, drops one byte and searches
// for the next sync again, as the host does.
void pollCommands()
{
    while (Serial.available() && rxSize < sizeof rx) rx[rxSize++] = Serial.read();
    while (rxSize >= 2) {
        if (rx[0] != 0xA5 || rx[1] != 0x5A) {
            memmove(rx, rx + 1, --rxSize);
            continue;
        }
        if (rxSize < 8) return;
        const uint16_t length = rx[4] | rx[5] << 8;
        if (rx[2] != 0x01 || length > sizeof rx - 10) {
            memmove(rx, rx + 1, --rxSize);
            continue;
        }
        if (rxSize < 10 + length) return;
        const uint16_t crc = rx[8 + length] | rx[9 + length] << 8;
        if (crc != crc16Ccitt(rx + 2, 6 + length)) {
            memmove(rx, rx + 1, --rxSize);
            continue;
        }
        if (rx[3] == kCommand) handleCommand(rx + 8, length);
        rxSize -= 10 + length;
        memmove(rx, rx + 10 + length, rxSize);
    }
}

}  // namespace

void setup()
{
    Serial.begin(921600);  // USB serial ignores the baud rate; a UART would not
    SPI.begin();
    pinMode(kDefectLed, OUTPUT);
    pinMode(kBuzzer, OUTPUT);
    for (int shunt : kShunt) {
        pinMode(shunt, OUTPUT);
        digitalWrite(shunt, LOW);  // no shunt until the host asks
    }
    for (int adc = 0; adc < 2; ++adc) {
        pinMode(kChipSelect[adc], OUTPUT);
        digitalWrite(kChipSelect[adc], HIGH);
        adcCommand(adc, 0x06);  // RESET
    }
    delay(1);
    applyRate(kDefaultRate_mHz);
}

void loop()
{
    pollCommands();
    if (!sampleDue) return;
    sampleDue = false;
    if (!streaming) return;
    // Each ADC converts faster than the sample rate; the newest code is read.
    const int32_t values[2] = {adcRead(0) - tare[0], adcRead(1) - tare[1]};
    addSample(values);
}
