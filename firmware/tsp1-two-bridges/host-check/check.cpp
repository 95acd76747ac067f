// The reference sketch's framing, compiled on a PC against the worked
// examples of docs/protocol.md: a DATA frame byte for byte, the CRC check
// value, commands found after noise, and a streamed frame's layout; and its
// detector (firmware/probe-detector, linked in): a dent passing A then B
// lights the LED, sounds the buzzer and is sent as decision +1, the same
// decisions the kernel gives run directly on the same strains.
#include "../tsp1-two-bridges.ino"

#include <cassert>
#include <cmath>
#include <string>
#include <utility>

namespace {

// Queues one sample's ADC answers: RDATA's echo byte, then 24 bits, MSB first.
void queueCodes(int32_t a, int32_t b)
{
    for (int32_t code : {a, b}) {
        const uint32_t raw = static_cast<uint32_t>(code) & 0xFFFFFF;
        SPI.answers.insert(SPI.answers.end(), {0x00, static_cast<uint8_t>(raw >> 16), static_cast<uint8_t>(raw >> 8),
                                               static_cast<uint8_t>(raw)});
    }
}

// A dent under A at sample 500 and under B 25 samples (50 ms) later: a
// bipolar bump of 60 µε, σ 6.7 samples (4 mm at 0.3 m/s), in ADC codes, with about 0.3 µε of
// noise (a fixed linear congruential sequence, so the run is the same on
// every machine).
int32_t dentCode(int sample, int at, uint32_t& noise)
{
    const double u = (sample - at) / (20.0 / 3.0);
    noise = noise * 1664525u + 1013904223u;
    const double uniform = static_cast<double>(noise >> 8) / 16777216.0 - 0.5;  // σ ≈ 0.29 of its span
    return static_cast<int32_t>(std::lround((60e-6 * u * std::exp(-0.5 * u * u) + 1e-6 * uniform) / kStrainPerCount));
}

int32_t i32At(const std::vector<uint8_t>& f, size_t at)
{
    return static_cast<int32_t>(f[at] | f[at + 1] << 8 | f[at + 2] << 16 | static_cast<uint32_t>(f[at + 3]) << 24);
}

}  // namespace

int main()
{
    // DATA, sequence 7, t = 1000 µs, 2 channels of int16: 100/−100, 101/−99.
    txSequence = 7;
    Payload p;
    p.u32(1000), p.u8(2), p.u8(1), p.u16(2);
    for (int16_t v : {100, -100, 101, -99}) p.u16(static_cast<uint16_t>(v));
    sendFrame(kData, p);
    assert((Serial.out == std::vector<uint8_t>{0xA5, 0x5A, 0x01, 0x02, 0x10, 0x00, 0x07, 0x00, 0xE8,
                                               0x03, 0x00, 0x00, 0x02, 0x01, 0x02, 0x00, 0x64, 0x00,
                                               0x9C, 0xFF, 0x65, 0x00, 0x9D, 0xFF, 0x0E, 0x6A}));
    assert(crc16Ccitt(reinterpret_cast<const uint8_t*>("123456789"), 9) == 0x29B1);

    // COMMAND start (sequence 0) after three bytes of noise, one a false sync.
    setup();
    Serial.out.clear();
    Serial.in = {0x00, 0xA5, 0x13, 0xA5, 0x5A, 0x01, 0x10, 0x01, 0x00, 0x00, 0x00, 0x01, 0x5B, 0xE9};
    pollCommands();
    assert(streaming && Serial.in.empty());
    // COMMAND set rate 2 kHz: above this board's 1 kHz, so kept, with a
    // warning and the INFO of the rate in force.
    Serial.in = {0xA5, 0x5A, 0x01, 0x10, 0x05, 0x00, 0x01, 0x00, 0x03, 0x80, 0x84, 0x1E, 0x00, 0x71, 0xA3};
    pollCommands();
    assert(rate_mHz == 500000);
    assert(Serial.out.size() > 8 && Serial.out[3] == kStatus);

    // COMMAND shunt on channel b (6, 1, 1): pin 5 high, "shunt on b"; off
    // again; channel 2 has no bridge and says so.
    const auto command = [](std::vector<uint8_t> payload) {
        std::vector<uint8_t> frame{0xA5, 0x5A, 0x01, 0x10, static_cast<uint8_t>(payload.size()), 0x00, 0x09, 0x00};
        frame.insert(frame.end(), payload.begin(), payload.end());
        const uint16_t check = crc16Ccitt(frame.data() + 2, 6 + payload.size());
        frame.push_back(static_cast<uint8_t>(check));
        frame.push_back(static_cast<uint8_t>(check >> 8));
        Serial.out.clear();
        Serial.in = frame;
        pollCommands();
        // The STATUS's level and message.
        assert(Serial.out.size() > 10 && Serial.out[3] == kStatus);
        return std::pair{Serial.out[8], std::string(Serial.out.begin() + 10, Serial.out.begin() + 10 + Serial.out[9])};
    };
    assert(pinLevel[kShunt[1]] == LOW);
    assert((command({6, 1, 1}) == std::pair{uint8_t{0}, std::string("shunt on b")}));
    assert(pinLevel[kShunt[1]] == HIGH && pinLevel[kShunt[0]] == LOW);
    assert((command({6, 1, 0}) == std::pair{uint8_t{0}, std::string("shunt off b")}));
    assert(pinLevel[kShunt[1]] == LOW);
    const auto noBridge = command({6, 2, 1});
    assert(noBridge.first == 2 && noBridge.second.rfind("shunt: ", 0) == 0);

    // Ten samples make one DATA frame: 2 channels of int32, stamped with the
    // clock at its first sample.
    Serial.out.clear();
    for (uint32_t i = 0; i < 10; ++i) {
        fakeMicros = 5000 + 2000 * i;
        sampleDue = true;
        loop();
    }
    const auto& f = Serial.out;
    // Seven channels a sample: a, b, and the detector's out, rab, rba, lag_ab, lag_ba.
    assert(f.size() == 8 + 8 + 10 * 7 * 4 + 2);
    assert(f[3] == kData && (f[4] | f[5] << 8) == 288);
    assert((f[8] | f[9] << 8) == 5000 && f[12] == 7 && f[13] == 2 && (f[14] | f[15] << 8) == 10);
    assert(crc16Ccitt(f.data() + 2, 6 + 288) == (f[296] | f[297] << 8));

    // The INFO declares the decisions as kind 5.
    Serial.out.clear();
    sendInfo();
    const std::vector<uint8_t> info = Serial.out;
    const auto named = [&](const char* name) {
        const size_t n = strlen(name);
        for (size_t i = 0; i + n + 3 < info.size(); ++i)
            if (info[i] == n && memcmp(&info[i + 1], name, n) == 0 && info[i + 1 + n] == 0) return info[i + 2 + n];
        return uint8_t{0xFF};
    };
    assert(named("a") == 0 && named("out") == 5 && named("rab") == 5 && named("rba") == 5);

    // A dent passing A then B: the sketch's detector against the kernel run directly.
    Serial.in = {0xA5, 0x5A, 0x01, 0x10, 0x01, 0x00, 0x02, 0x00, 0x01, 0x00, 0x00};  // start, CRC below
    const uint16_t crc = crc16Ccitt(Serial.in.data() + 2, 7);
    Serial.in.back() = static_cast<uint8_t>(crc >> 8), Serial.in[Serial.in.size() - 2] = static_cast<uint8_t>(crc);
    pollCommands();
    assert(streaming);
    pd_detector reference = detector;  // the configuration the sketch set up, from silence
    pd_reset(&reference);
    Serial.out.clear();
    int decided = 0, first = -1;
    bool lit = false;
    uint32_t noiseA = 1, noiseB = 2;
    for (int i = 0; i < 1500; ++i) {
        const int32_t a = dentCode(i, 500, noiseA), b = dentCode(i, 525, noiseB);
        queueCodes(a, b);
        fakeMicros = 1000000 + 2000 * static_cast<uint32_t>(i);
        sampleDue = true;
        loop();
        pd_output o;
        pd_step(&reference, static_cast<float>(a) * kStrainPerCount, static_cast<float>(b) * kStrainPerCount, &o);
        if (o.decision != 0) {
            assert(o.decision == 1);  // A then B
            ++decided;
            if (first < 0) first = i;
            lit = lit || (pinLevel[kDefectLed] == HIGH && toneHz[kBuzzer] == kBuzzer_hz);
        }
    }
    assert(decided > 0 && first > 525 && first < 600);
    assert(lit);
    // 200 ms after the last defect sample, LED and buzzer are off again.
    assert(pinLevel[kDefectLed] == LOW && toneHz[kBuzzer] == 0);
    // Every DATA frame's out column holds the kernel's decisions, in order.
    int sent = 0;
    for (size_t at = 0; at + 8 < Serial.out.size();) {
        const size_t size = Serial.out[at + 4] | Serial.out[at + 5] << 8;
        if (Serial.out[at + 3] == kData)
            for (size_t s = 0; s < 10; ++s) {
                const size_t sample = at + 8 + 8 + s * 7 * 4;
                if (i32At(Serial.out, sample + 2 * 4) != 1) continue;
                ++sent;
                assert(i32At(Serial.out, sample + 5 * 4) == 50000);  // lag_ab: 25 samples at 2 ms, in µs
            }
        at += 10 + size;
    }
    assert(sent == decided);
    std::printf("host-check: the sketch's frames match docs/protocol.md; its detector found the dent A then B "
                "(%d samples from sample %d), as the kernel does\n",
                decided, first);
}
