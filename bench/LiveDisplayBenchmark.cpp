// Live display speed on the offscreen platform, in a 10 s window on a
// 1600 × 900 plot, at 8 channels × 2 kHz (issue 8's target: a frame under
// 16 ms, the GUI thread under 25 % of a core, no display samples lost) and
// at 16 channels × 10 kHz (issue 40's: the same, and memory flat over an
// hour), both in the same run:
//  - one frame of LivePlotWidget (take 25 ms of new samples, min/max
//    decimate to the pixel columns, replot), against the baseline of handing
//    QCustomPlot every sample of the 8 × 2 kHz window and replotting;
//  - the traces alone drawn as pixel columns into an opaque image, against
//    QCustomPlot's polylines on its transparent buffer;
//  - 10 s of real time with a feeder thread writing 5 ms blocks into the
//    LiveBuffer, as the acquisition does, and the widget on its own frame
//    timer: the GUI thread's CPU time over wall time, frames drawn, and the
//    samples the display missed;
//  - the same at 16 × 10 kHz with a mains notch and a low-pass on every
//    channel (issue 57): the signal chain on the feeder's thread and the
//    traces drawn as filtered (or as they came, with the 16 filtered
//    channels on a second plot); the GUI thread and the filtering's share
//    of a core, against the traces alone in the same run;
//  - an hour of 16 × 10 kHz through the buffer and the widget (as fast as
//    it goes, a frame every 10 s of stream time): the resident memory after
//    the first minute and after the hour.
// Run: tactiscope_display_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "EightChannelStream.h"
#include "core/LiveBuffer.h"
#include "core/SampleBlock.h"
#include "core/signal/SignalChain.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/plot/OpaqueCustomPlot.h"
#include "ui/plot/PixelColumnGraph.h"

#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace tactiscope;
using bench::eightChannelBlock;
using bench::kChannels;
using bench::kRate_hz;
using bench::strainChannels;
using bench::streamBlock;

constexpr double kWindow_s = 10.0;
constexpr double kFrame_s = 0.025;         // one frame's worth of samples at 40 frames/s
constexpr std::size_t kFrameSamples = 50;  // that at 2 kHz

double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// The widget as every benchmark here shows it: 1600 × 900, on `buffer`.
void showOn(ui::LivePlotWidget& plot, const std::shared_ptr<core::LiveBuffer>& buffer, std::size_t channels,
            double rate_hz)
{
    plot.resize(1600, 900);
    plot.show();
    plot.setSource(buffer, strainChannels(channels), rate_hz);
}

// Args: channels, rate in Hz.
void BM_LivePlotFrame(benchmark::State& state)
{
    const auto channels = static_cast<std::size_t>(state.range(0));
    const auto rate_hz = static_cast<double>(state.range(1));
    const auto frame = static_cast<std::size_t>(kFrame_s * rate_hz);
    auto buffer = std::make_shared<core::LiveBuffer>(channels, static_cast<std::size_t>(2 * kWindow_s * rate_hz));
    std::uint64_t next = 0;
    for (; next < static_cast<std::uint64_t>(kWindow_s * rate_hz); next += frame)
        buffer->consume(streamBlock(channels, rate_hz, next, frame));
    ui::LivePlotWidget plot;
    showOn(plot, buffer, channels, rate_hz);
    QMetaObject::invokeMethod(&plot, "refresh", Qt::DirectConnection);  // the full window once
    for (auto _ : state) {
        state.PauseTiming();  // making the samples is the acquisition's work, not the display's
        auto block = streamBlock(channels, rate_hz, next, frame);
        state.ResumeTiming();
        buffer->consume(block);
        next += frame;
        QMetaObject::invokeMethod(&plot, "refresh", Qt::DirectConnection);
    }
    state.counters["points_drawn_per_channel"] = plot.drawnPointCount(0);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(frame * channels));
}
BENCHMARK(BM_LivePlotFrame)->Args({8, 2000})->Args({16, 10000})->Unit(benchmark::kMillisecond);

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

// Drawing the traces alone, as a live frame has them: 16 traces of 3 024
// min/max points (two per pixel column) in one 1600 × 900 lane, replotted
// into QCustomPlot's paint buffer and painted onto the widget. Arg 0:
// QCustomPlot's graphs stroked as polylines on its transparent buffer, the
// baseline; 1: the live view's PixelColumnGraph on its OpaqueCustomPlot.
void BM_TraceDrawing(benchmark::State& state)
{
    const bool columns = state.range(0) != 0;
    std::unique_ptr<QCustomPlot> plot(columns ? new ui::OpaqueCustomPlot : new QCustomPlot);
    plot->resize(1600, 900);
    plot->show();
    plot->setPlottingHint(QCP::phFastPolylines, false);
    plot->setNotAntialiasedElements(QCP::aePlottables | QCP::aeGrid);
    constexpr int kTraces = 16;
    constexpr int kColumns = 1512;
    QVector<double> keys(2 * kColumns);
    for (int i = 0; i < 2 * kColumns; ++i) keys[i] = (i / 2) * kWindow_s / kColumns;
    for (int c = 0; c < kTraces; ++c) {
        QCPGraph* graph = columns ? new ui::PixelColumnGraph(plot->xAxis, plot->yAxis) : plot->addGraph();
        graph->setPen(QPen(QColor::fromHsv(c * 22, 255, 200), 1.0));
        graph->setAdaptiveSampling(false);
        QVector<double> values(2 * kColumns);
        for (int i = 0; i < 2 * kColumns; ++i) {  // a column's min then its max, as the decimation gives them
            const double t = keys[i];
            const double slow = 80.0 * std::sin(2.0 * M_PI * 0.318 * (c + 1) * t);
            values[i] = slow + (i % 2 == 0 ? -5.0 : 5.0);
        }
        graph->setData(keys, values, true);
    }
    plot->xAxis->setRange(0.0, kWindow_s);
    plot->yAxis->setRange(-110.0, 110.0);
    for (auto _ : state) plot->replot(QCustomPlot::rpImmediateRefresh);  // the paint onto the widget included
    state.SetItemsProcessed(state.iterations() * kTraces * 2 * kColumns);
}
BENCHMARK(BM_TraceDrawing)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Every channel through a mains notch and a 4th-order low-pass at a tenth
// of the rate, as a press line's operator would set them (issue 57).
core::signal::SignalSetup notchedAndLowPassed(const std::vector<core::ChannelDescriptor>& channels, double rate_hz)
{
    core::signal::SignalSetup setup;
    core::dsp::FilterSettings filter;
    filter.notch_hz = 50.0;
    filter.lowpass_hz = rate_hz / 10.0;
    for (const auto& channel : channels) setup.filters.push_back({channel.name, filter});
    return setup;
}

// Args: channels, rate in Hz, and 1 to filter every channel live (the
// signal chain on the feeder's thread, as on the acquisition's, and the
// traces drawn from its display as the window draws a filtered device:
// each channel once, as filtered), 2 to draw the filtered channels on a
// second plot under the traces as they came (View ▸ Traces as filtered
// unticked); 0 for the traces alone, the baseline.
void BM_LiveDisplayRealTime(benchmark::State& state)
{
    const auto channels = static_cast<std::size_t>(state.range(0));
    const auto rate_hz = static_cast<double>(state.range(1));
    const bool filtered = state.range(2) != 0;
    const bool besides = state.range(2) == 2;
    const auto block = static_cast<std::size_t>(0.005 * rate_hz);  // 5 ms
    // The blocks made before, so the feeder spends its time feeding.
    std::vector<core::SampleBlock> second;
    for (std::uint64_t first = 0; first < static_cast<std::uint64_t>(rate_hz); first += block)
        second.push_back(streamBlock(channels, rate_hz, first, block));
    for (auto _ : state) {
        const auto held = static_cast<std::size_t>(2.0 * rate_hz);
        auto buffer = std::make_shared<core::LiveBuffer>(channels, held);
        ui::LivePlotWidget plot;
        std::unique_ptr<core::signal::SignalChain> chain;
        ui::LivePlotWidget filteredPlot;
        if (filtered) {
            const auto names = strainChannels(channels);
            chain = std::make_unique<core::signal::SignalChain>(notchedAndLowPassed(names, rate_hz), names, rate_hz,
                                                                held, 0.0, held);
        }
        if (filtered && !besides) {
            plot.resize(1600, 900);
            plot.show();
            plot.setSource(chain->display(), strainChannels(channels), rate_hz);
        } else {
            showOn(plot, buffer, channels, rate_hz);
        }
        if (besides) {
            filteredPlot.resize(1600, 450);
            filteredPlot.setSource(chain->output(), chain->outputs(), rate_hz);
            filteredPlot.show();
        }
        std::atomic<bool> running = true;
        double filtering_s = 0.0;  // the chain's time on the feeder's thread
        // The acquisition's side: a 5 ms block every 5 ms.
        std::thread feeder([&] {
            const auto start = std::chrono::steady_clock::now();
            for (std::uint64_t k = 0; running; ++k) {
                core::SampleBlock next = second[k % second.size()];
                next.rebase(static_cast<double>(k / second.size()), (k / second.size()) * second.size() * block);
                buffer->consume(next);
                if (chain) {
                    const double before = threadCpuSeconds();
                    chain->consume(next);
                    filtering_s += threadCpuSeconds() - before;
                }
                std::this_thread::sleep_until(start + std::chrono::microseconds(5000 * (k + 1)));
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
        state.counters["filtering_cpu_percent"] = 100.0 * filtering_s / elapsed_s;
        if (filtered) state.counters["filtered_samples_missed"] = static_cast<double>(filteredPlot.samplesOverrun());
    }
}
BENCHMARK(BM_LiveDisplayRealTime)
    ->Args({8, 2000, 0})
    ->Args({16, 10000, 0})
    ->Args({16, 10000, 1})
    ->Args({16, 10000, 2})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

// Resident memory, in MB (Linux: /proc/self/statm's second field).
double residentMegabytes()
{
    long pages = 0, resident = 0;
    if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(statm);
    }
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

// An hour of 16 × 10 kHz through the buffer and the widget, as fast as it
// goes: what the display holds must not grow with the hour.
void BM_LiveDisplayHourMemory(benchmark::State& state)
{
    constexpr std::size_t channels = 16;
    constexpr double rate_hz = 10000.0;
    const auto block = static_cast<std::size_t>(0.1 * rate_hz);  // 100 ms blocks: the hour in 36 000
    const core::SampleBlock pattern = streamBlock(channels, rate_hz, 0, block);
    for (auto _ : state) {
        auto buffer = std::make_shared<core::LiveBuffer>(channels, static_cast<std::size_t>(2.0 * rate_hz));
        ui::LivePlotWidget plot;
        showOn(plot, buffer, channels, rate_hz);
        double afterMinute = 0.0;
        const auto blocks = static_cast<std::uint64_t>(3600.0 * rate_hz) / block;
        for (std::uint64_t k = 0; k < blocks; ++k) {
            core::SampleBlock next = pattern;
            next.rebase(static_cast<double>(k) * 0.1, k * block);
            buffer->consume(next);
            if (k % 100 == 99) QMetaObject::invokeMethod(&plot, "refresh", Qt::DirectConnection);  // every 10 s
            if (k == 599) afterMinute = residentMegabytes();
        }
        state.counters["rss_after_minute_MB"] = afterMinute;
        state.counters["rss_after_hour_MB"] = residentMegabytes();
        state.counters["samples_shown_per_channel"] = static_cast<double>(plot.samplesReceived());
    }
}
BENCHMARK(BM_LiveDisplayHourMemory)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

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
