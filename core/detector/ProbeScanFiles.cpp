// ProbeScanFiles: scan_format.h's little-endian records, from and to a scan
// read as detect reads it.
#include "core/detector/ProbeScanFiles.h"

#include "core/detector/CsvDetection.h"
#include "core/detector/FirmwarePairDetector.h"
#include "scan_format.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace tactiscope::core::detector {
namespace {

void putU32(std::ostream& out, std::uint32_t v)
{
    const std::array<char, 4> bytes{static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                                    static_cast<char>(v >> 24)};
    out.write(bytes.data(), bytes.size());
}

void putF64(std::ostream& out, double v)
{
    const auto bits = std::bit_cast<std::uint64_t>(v);
    putU32(out, static_cast<std::uint32_t>(bits));
    putU32(out, static_cast<std::uint32_t>(bits >> 32));
}

void putF32(std::ostream& out, float v)
{
    putU32(out, std::bit_cast<std::uint32_t>(v));
}

std::uint32_t u32At(const unsigned char* p)
{
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}

void needPair(const std::vector<std::string>& columns)
{
    if (columns.size() != 3)
        throw std::invalid_argument("the probe's detector takes one pair of cantilevers: a time column and two");
}

}  // namespace

std::size_t writeProbeInput(const std::string& scan, const std::vector<std::string>& columns,
                            DetectorParameters parameters, std::ostream& out)
{
    needPair(columns);
    CheckedScan checked(scan, columns);
    parameters.sampleInterval_s = checked.interval_s();
    const ProbeLags lags = FirmwarePairDetector::probeLags(parameters);
    out.write(PD_SCAN_MAGIC, 4);
    putU32(out, static_cast<std::uint32_t>(lags.lags.size()));
    putU32(out, parameters.faceToFace ? 1 : 0);
    putU32(out, static_cast<std::uint32_t>(checked.rows()));
    putF64(out, parameters.sampleInterval_s);
    putF64(out, parameters.epsilon);
    putF64(out, parameters.threshold);
    for (std::size_t i = 0; i < lags.lags.size(); ++i) {
        putU32(out, lags.lags[i]);
        putF64(out, lags.lambda_s[i]);
    }
    std::vector<std::vector<double>> block;
    while (const std::size_t n = checked.read(block))
        for (std::size_t i = 0; i < n; ++i) {
            putF32(out, static_cast<float>(block[1][i]));
            putF32(out, static_cast<float>(block[2][i]));
        }
    return checked.rows();
}

std::size_t writeProbeDecisionRows(const std::string& scan, const std::vector<std::string>& columns,
                                   const std::string& decisions, std::ostream& out)
{
    needPair(columns);
    CheckedScan checked(scan, columns);
    std::ifstream in(decisions, std::ios::binary);
    char magic[4] = {};
    if (!in.read(magic, 4) || std::memcmp(magic, PD_DECISIONS_MAGIC, 4) != 0)
        throw CsvDetectionError("'" + decisions + "' is not an emulated probe's decisions file");
    out << kSampleRowsHeader;
    std::vector<std::vector<double>> block;
    std::vector<ProbeOutput> outputs;
    std::string rows;
    std::size_t written = 0;
    while (const std::size_t n = checked.read(block)) {
        outputs.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            std::array<unsigned char, PD_DECISION_RECORD_BYTES> record{};
            if (!in.read(reinterpret_cast<char*>(record.data()), record.size()))
                throw CsvDetectionError("'" + decisions + "' holds decisions for " + std::to_string(written + i) +
                                        " samples; the scan has " + std::to_string(checked.rows()));
            DetectorOutput& o = outputs[i].combined;
            outputs[i].t_s = block[0][i];
            o.decision = static_cast<std::int8_t>(static_cast<std::int32_t>(u32At(record.data())));
            o.lagAb = u32At(record.data() + 4);
            o.lagBa = u32At(record.data() + 8);
            o.rab = std::bit_cast<float>(u32At(record.data() + 12));
            o.rba = std::bit_cast<float>(u32At(record.data() + 16));
        }
        appendSampleRows(rows, outputs, checked.interval_s());
        out << rows;
        written += n;
    }
    if (in.peek() != std::ifstream::traits_type::eof())
        throw CsvDetectionError("'" + decisions + "' holds more decisions than the scan has samples (" +
                                std::to_string(checked.rows()) + ")");
    return written;
}

}  // namespace tactiscope::core::detector
