// The emulated probe's two files (firmware/probe-detector/scan_format.h),
// written and read by the workstation: its input (a scan and the
// detector's settings) and, from its decisions, the rows `detect --output`
// writes. Both read the scan through CheckedScan, as `detect` does, so the
// emulated probe (qemu-detect.sh) refuses what detect refuses, in the same
// words; before, the firmware's own host tool read the scan with a laxer
// reader of its own and ran on a 1e300 sample, empty cells read as 0,
// times going back and "0.002s".
#pragma once

#include "core/detector/DetectorParameters.h"

#include <ostream>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

// The probe's input: the scan's samples as the floats a probe holds, the
// detector's settings with the scan's interval, the lags as the probe's
// kernel takes them (FirmwarePairDetector::probeLags). `columns`: time, A,
// B. Returns the samples written. Throws as detectCsv does, and
// std::invalid_argument for settings the probe cannot run.
std::size_t writeProbeInput(const std::string& scan, const std::vector<std::string>& columns,
                            DetectorParameters parameters, std::ostream& out);

// The rows of `detect --output` for that scan, each sample's decision, R
// and lags taken from the emulated probe's decisions file. Returns the rows
// written. Throws as detectCsv does, and CsvDetectionError when the
// decisions are not a decisions file or not one per sample of the scan.
std::size_t writeProbeDecisionRows(const std::string& scan, const std::vector<std::string>& columns,
                                   const std::string& decisions, std::ostream& out);

}  // namespace tactiscope::core::detector
