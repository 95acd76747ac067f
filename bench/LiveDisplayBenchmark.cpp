// Live display speed on the offscreen platform, 8 channels at 2 kHz in a
// 10 s window on a 1600 × 900 plot (issue 8's target: a frame under 16 ms,
// the GUI thread under 25 % of a core, no display samples lost):
//  - one frame of LivePlotWidget (take 25 ms of new samples, min/max
//    decimate to the pixel columns, replot), against the baseline of handing
//    QCustomPlot every sample of the window and replotting;
//  - 10 s of real time with a feeder thread writing 5 ms blocks into the
//    LiveBuffer, as the acquisition does, and the widget on its own frame
//    timer: the GUI thread's CPU time over wall time, frames drawn, and the
//    samples the display missed.
// Run: tactiscope_display_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "EightChannelStream.h"
#include "core/LiveBuffer.h"
#include "core/SampleBlock.h"
#include "ui/LivePlotWidget.h"

#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <atomic>
#include <cmath>
#include <ctime>
#include <thread>

namespace {

using namespace tactiscope;
using bench::eightChannelBlock;
using bench::eightChannels;
using bench::kChannels;
using bench::kRate_hz;

constexpr double kWindow_s = 10.0;
constexpr std::size_t kFrameSamples = 50;  // 25 ms: one frame's worth at 40 frames/s

double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

void BM_LivePlotFrame(benchmark::State& state)
{
    auto buffer = std::make_shared<core::LiveBuffer>(kChannels, static_cast<std::size_t>(2 * kWindow_s * kRate_hz));
    std::uint64_t next = 0;
    for (; next < static_cast<std::uint64_t>(kWindow_s * kRate_hz); next += kFrameSamples)
        buffer->consume(eightChannelBlock(next, kFrameSamples));
    ui::LivePlotWidget plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setSource(buffer, eightChannels(), kRate_hz);
    QMetaObject::invokeMethod(&plot, "refresh", Qt::DirectConnection);  // the full window once
    for (auto _ : state) {
        buffer->consume(eightChannelBlock(next, kFrameSamples));
        next += kFrameSamples;
        QMetaObject::invokeMethod(&plot, "refresh", Qt::DirectConnection);
    }
    state.counters["points_drawn_per_channel"] = plot.drawnPointCount(0);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kFrameSamples * kChannels));
}
BENCHMARK(BM_LivePlotFrame)->Unit(benchmark::kMillisecond);

// Baseline: every sample of the window to QCustomPlot, one graph per
// channel in one axis rect, then a replot.
void BM_RawQCustomPlotFrame(benchmark::State& state)
{
    QCustomPlot plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setPlottingHint(QCP::phFastPolylines, true);
    const auto n = static_cast<qsizetype>(kWindow_s * kRate_hz);
    const core::SampleBlock window = eightChannelBlock(0, static_cast<std::size_t>(n));
    QVector<double> t(n);
    for (qsizetype i = 0; i < n; ++i) t[i] = static_cast<double>(i) / kRate_hz;
    std::vector<QVector<double>> values(kChannels, QVector<double>(n));
    for (std::size_t c = 0; c < kChannels; ++c) {
        plot.addGraph();
        for (qsizetype i = 0; i < n; ++i) values[c][i] = window.value(c, static_cast<std::size_t>(i)) * 1e6;
    }
    plot.xAxis->setRange(0.0, kWindow_s);
    plot.yAxis->setRange(-110.0, 110.0);
    for (auto _ : state) {
        for (std::size_t c = 0; c < kChannels; ++c) plot.graph(static_cast<int>(c))->setData(t, values[c], true);
        plot.replot();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kFrameSamples * kChannels));
}
BENCHMARK(BM_RawQCustomPlotFrame)->Unit(benchmark::kMillisecond);

void BM_LiveDisplayRealTime(benchmark::State& state)
{
    for (auto _ : state) {
        auto buffer = std::make_shared<core::LiveBuffer>(kChannels, static_cast<std::size_t>(2.0 * kRate_hz));
        ui::LivePlotWidget plot;
        plot.resize(1600, 900);
        plot.show();
        plot.setSource(buffer, eightChannels(), kRate_hz);
        std::atomic<bool> running = true;
        // The acquisition's side: a 5 ms block every 5 ms.
        std::thread feeder([&] {
            const auto start = std::chrono::steady_clock::now();
            for (std::uint64_t first = 0; running; first += 10) {
                buffer->consume(eightChannelBlock(first, 10));
                std::this_thread::sleep_until(start + std::chrono::microseconds(5000 * (first / 10 + 1)));
            }
        });
        const double cpu0 = threadCpuSeconds();
        QElapsedTimer wall;
        wall.start();
        QEventLoop loop;  // the GUI thread idles between frames, as in the application
        QTimer::singleShot(10'000, &loop, &QEventLoop::quit);
        loop.exec();
        const double cpu = threadCpuSeconds() - cpu0;
        const double elapsed_s = static_cast<double>(wall.elapsed()) * 1e-3;
        running = false;
        feeder.join();
        state.counters["gui_cpu_percent"] = 100.0 * cpu / elapsed_s;
        state.counters["display_samples_missed"] = static_cast<double>(plot.samplesOverrun());
        state.counters["frames_per_s"] = static_cast<double>(plot.framesDrawn()) / elapsed_s;
        state.counters["samples_shown_per_channel"] = static_cast<double>(plot.samplesReceived());
    }
}
BENCHMARK(BM_LiveDisplayRealTime)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
