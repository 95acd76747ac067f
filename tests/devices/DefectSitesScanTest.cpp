// Defect sites on the simulator's reciprocating scan, whose dent position is
// known: every crossing of the one dent groups into one site, placed where
// the dent is.
#include "core/SampleBlock.h"
#include "core/detector/DefectSites.h"
#include "core/detector/OfflineDetection.h"
#include "devices/simulator/PanelScanScenario.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ranges>

using namespace tactiscope;

namespace {

std::vector<core::detector::DefectEvent> detectScan(const devices::simulator::PanelScanParameters& p, double seconds,
                                                    double threshold = 0.85)
{
    devices::simulator::PanelScanScenario scenario(p);
    core::SampleBlock block(2, static_cast<std::size_t>(seconds * p.sampleRate_hz), 0.0, 1.0 / p.sampleRate_hz);
    scenario.generate(block);
    const std::vector<std::vector<double>> cantilevers{{block.channel(0).begin(), block.channel(0).end()},
                                                       {block.channel(1).begin(), block.channel(1).end()}};
    core::detector::StretchSettings settings;
    settings.spacing_m = p.cantileverSpacing_m;
    settings.parameters.faceToFace = p.faceToFace;
    settings.parameters.threshold = threshold;
    return core::detector::detectStretches(cantilevers, settings).events;
}

// The simulator's dent position is measured along cantilever A's stroke;
// sites are placed along the stroke of the probe's centre, half a spacing
// behind A: its stroke's centre lies half a spacing behind A's, so the dent
// is half a spacing further from it.
double dentFromCentreStroke_m(const devices::simulator::PanelScanParameters& p)
{
    return p.defectPosition_m + 0.5 * p.cantileverSpacing_m;
}

}  // namespace

TEST(DefectSitesScan, OneDentCrossedInEveryStrokeIsOneSiteWhereTheDentIs)
{
    for (const double dent_m : {0.030, -0.050, 0.0}) {
        devices::simulator::PanelScanParameters p;
        p.defectPosition_m = dent_m;
        p.seed = 7;
        const auto events = detectScan(p, 30.0);
        ASSERT_GE(events.size(), 28u) << "dent at " << dent_m;
        const auto places = core::detector::placeCrossings(events);
        for (std::size_t i = 0; i < events.size(); ++i)
            if (places.position_m[i]) {
                EXPECT_NEAR(*places.position_m[i], dentFromCentreStroke_m(p), 0.010)
                    << "event at " << events[i].start_s << " s";
            }
        const auto grouping = core::detector::scanSites(events);
        ASSERT_EQ(grouping.sites.size(), 1u) << "dent at " << dent_m;
        const auto& site = grouping.sites.front();
        EXPECT_EQ(site.crossings.size() + site.parts.size(), events.size());
        EXPECT_LE(std::max(site.forward, site.backward) - std::min(site.forward, site.backward), 1u);
        ASSERT_TRUE(site.position_m);
        EXPECT_NEAR(*site.position_m, dentFromCentreStroke_m(p), 0.010) << "dent at " << dent_m;
        EXPECT_EQ(grouping.method.rfind("scan speed, harmonic strokes", 0), 0u) << grouping.method;
    }
}

// Two and three dents 30–80 mm apart on strokes at 0.5–1 Hz, with gauges
// side by side and face to face, through the detector: a site per dent,
// each where its dent is, none outside the ±100 mm stroke.
TEST(DefectSitesScan, DentsThirtyMillimetresApartAreSitesOfTheirOwn)
{
    struct Case {
        double hz;
        std::vector<double> dents_m;
        bool faceToFace;
    };
    const std::vector<Case> cases{{0.5, {-0.020, 0.010}, false},
                                  {1.0, {0.000, 0.030}, true},
                                  {0.75, {-0.050, 0.030}, false},
                                  {0.5, {-0.060, 0.000, 0.050}, true}};
    for (const Case& c : cases) {
        devices::simulator::PanelScanParameters p;
        p.strokeFrequency_hz = c.hz;
        p.defectPosition_m = c.dents_m.front();
        p.moreDefects_m.assign(c.dents_m.begin() + 1, c.dents_m.end());
        p.faceToFace = c.faceToFace;
        p.seed = 11;
        const auto events = detectScan(p, 30.0);
        const auto grouping = core::detector::scanSites(events);
        SCOPED_TRACE(std::to_string(c.hz) + " Hz, " + std::to_string(c.dents_m.size()) + " dents, " + grouping.method);
        ASSERT_EQ(grouping.sites.size(), c.dents_m.size());
        for (std::size_t k = 0; k < c.dents_m.size(); ++k) {
            ASSERT_TRUE(grouping.sites[k].position_m);
            EXPECT_NEAR(*grouping.sites[k].position_m, c.dents_m[k] + 0.5 * p.cantileverSpacing_m, 0.010) << k;
        }
        for (const auto& x : core::detector::placeCrossings(events).position_m)
            if (x) {
                EXPECT_LE(std::abs(*x), p.strokeAmplitude_m + p.cantileverSpacing_m);
            }
    }
}

// Scans that went wrong before, through the detector: a dent 60 mm out at
// 1 Hz, whose backward crossings the detector gives as 1–4-sample runs
// (were folded away, merging strokes: sites at −583 and +488 mm on a
// ±100 mm stroke), and two dents 25 mm apart seen at a lower threshold,
// where some strokes show nothing. No site lies outside the stroke.
TEST(DefectSitesScan, WeakAndMissedCrossingsPlaceNothingOutsideTheStroke)
{
    struct Case {
        double hz;
        std::vector<double> dents_m;
        double threshold;
    };
    for (const Case& c : {Case{1.0, {-0.060}, 0.85}, Case{0.5, {0.030, 0.055}, 0.80}, Case{1.0, {0.030, 0.055}, 0.80}})
        for (const std::uint64_t seed : {1u, 2u}) {
            devices::simulator::PanelScanParameters p;
            p.strokeFrequency_hz = c.hz;
            p.defectPosition_m = c.dents_m.front();
            p.moreDefects_m.assign(c.dents_m.begin() + 1, c.dents_m.end());
            p.seed = seed;
            const auto events = detectScan(p, 20.0, c.threshold);
            ASSERT_GE(events.size(), 15u);
            const auto grouping = core::detector::scanSites(events);
            SCOPED_TRACE(std::to_string(c.hz) + " Hz, seed " + std::to_string(seed) + ", " + grouping.method);
            for (const auto& site : grouping.sites)
                if (site.position_m) {
                    EXPECT_LE(std::abs(*site.position_m), p.strokeAmplitude_m + p.cantileverSpacing_m);
                }
            if (c.dents_m.size() == 1) {
                ASSERT_EQ(grouping.sites.size(), 1u);
                EXPECT_NEAR(*grouping.sites.front().position_m, dentFromCentreStroke_m(p), 0.010);
            }
        }
}

// Two dents 70 mm apart at 0.5 Hz: the detector misses the outer one
// backwards, so the reversal at that end lies between crossings of
// different dents. It is retaken from the reversals beside it, the method
// says so, and both dents are placed within their ± (were scattered by
// 10–20 mm, flagged only).
TEST(DefectSitesScan, ReversalsBetweenDifferentDentsAreRetakenAndSaid)
{
    devices::simulator::PanelScanParameters p;
    p.defectPosition_m = -0.070;
    p.moreDefects_m = {0.0};
    const auto grouping = core::detector::scanSites(detectScan(p, 20.0));
    EXPECT_NE(grouping.method.find("reversals lay between crossings of different dents"), std::string::npos)
        << grouping.method;
    ASSERT_EQ(grouping.sites.size(), 2u) << grouping.method;
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& site = grouping.sites[k];
        ASSERT_TRUE(site.position_m) << core::detector::siteText(site);
        const double dent = k == 0 ? -0.070 : 0.0;
        EXPECT_LE(std::abs(*site.position_m - dent - 0.5 * p.cantileverSpacing_m), 2.0 * site.position_u_m)
            << core::detector::siteText(site);
    }
}

// A sweep of dent layouts (one to three dents, −70…+80 mm, 0.5 and 1 Hz,
// both gauge mountings, two seeds) at the paper's threshold: no site lies
// outside the stroke, and each placed site lies within 2u of its dent,
// but for what 2u may miss (5 %, within binomial limits; before, 12 of 72
// scans held a site more than 10 mm off, flagged only in their method).
TEST(DefectSitesScan, AcrossDentLayoutsEverySiteIsWithinItsUncertaintyOfItsDent)
{
    const std::vector<std::vector<double>> layouts{{0.030},       {-0.060},       {0.080},
                                                   {0.0, 0.030},  {0.030, 0.055}, {-0.050, 0.030},
                                                   {-0.070, 0.0}, {0.020, 0.070}, {-0.060, 0.0, 0.050}};
    int scans = 0, placed = 0, beyond2u = 0;
    for (const double hz : {0.5, 1.0})
        for (const bool faceToFace : {false, true})
            for (const auto& dents : layouts)
                for (const std::uint64_t seed : {1u, 2u}) {
                    devices::simulator::PanelScanParameters p;
                    p.strokeFrequency_hz = hz;
                    p.faceToFace = faceToFace;
                    p.defectPosition_m = dents.front();
                    p.moreDefects_m.assign(dents.begin() + 1, dents.end());
                    p.seed = seed;
                    const auto grouping = core::detector::scanSites(detectScan(p, 20.0));
                    SCOPED_TRACE(std::to_string(hz) + " Hz, dent " + std::to_string(dents.front()) + " and " +
                                 std::to_string(dents.size() - 1) + " more, " + grouping.method);
                    ++scans;
                    for (const auto& site : grouping.sites) {
                        if (site.kind != core::detector::SiteKind::Site) continue;
                        ++placed;
                        EXPECT_LE(std::abs(*site.position_m), p.strokeAmplitude_m + p.cantileverSpacing_m);
                        const double off =
                            std::ranges::min(dents | std::views::transform([&](double dent) {
                                                 return std::abs(*site.position_m - dent - 0.5 * p.cantileverSpacing_m);
                                             }));
                        if (off > 2.0 * site.position_u_m) {
                            ++beyond2u;
                            std::printf("%s is %.1f mm off\n", core::detector::siteText(site).c_str(), off * 1e3);
                        }
                    }
                }
    EXPECT_EQ(scans, 72);
    EXPECT_GE(placed, 70);  // of 128 dents: the rest are in spans or unplaced sites, which say why
    // 2u misses 4.6 % of a normal scatter; three binomial standard
    // deviations above (measured: 8 of 80, the two mountings alike).
    const double expected = 0.046 * placed;
    EXPECT_LE(beyond2u, expected + 3.0 * std::sqrt(expected * (1.0 - 0.046)));
}

// A panel line strokes each panel once, out and back, then rests (the
// scenario "panel-line"): one panel's recording holds each dent's crossing
// out and its crossing back, and nothing else. Through the detector, each
// dent is one site, whatever the number of dents.
TEST(DefectSitesScan, APanelStrokedOnceOutAndBackHasOneSitePerDent)
{
    for (const std::vector<double>& dents : std::vector<std::vector<double>>{{0.030}, {-0.050}, {-0.040, 0.030}}) {
        devices::simulator::PanelScanParameters p;
        p.restBetweenPanels_s = 3.0;
        p.defectPosition_m = dents.front();
        p.moreDefects_m.assign(dents.begin() + 1, dents.end());
        p.seed = 11;
        const auto events = detectScan(p, 5.0);  // one panel: 2 s stroke, 3 s at rest
        const auto grouping = core::detector::scanSites(events);
        ASSERT_EQ(grouping.sites.size(), dents.size()) << grouping.method << ", " << events.size() << " events";
        for (const auto& site : grouping.sites) {
            EXPECT_EQ(site.forward, 1u);
            EXPECT_EQ(site.backward, 1u);
        }
    }
}

// A session of several panels on a panel line: each panel stroked once out
// and back, the probe at rest 3 s between them. The crossings' times and
// speeds alone fit a stroke of half a metre and more with the dent near its
// end (the review and the PDF placed it at 448 mm on a ±100 mm stroke);
// such a stroke is no panel probe's, so the dent is one site, not placed,
// and the method says why.
TEST(DefectSitesScan, APanelLineOfSeveralPanelsPlacesNoDentOutsideAPanelProbesStroke)
{
    devices::simulator::PanelScanParameters p;
    p.restBetweenPanels_s = 3.0;
    p.defectPosition_m = 0.030;
    p.seed = 3;
    const auto grouping = core::detector::scanSites(detectScan(p, 30.0));
    ASSERT_EQ(grouping.sites.size(), 1u) << grouping.method;
    EXPECT_EQ(grouping.sites.front().kind, core::detector::SiteKind::Unplaced);
    EXPECT_GE(grouping.sites.front().crossings.size(), 10u);
    EXPECT_NE(grouping.method.find("as on a panel line"), std::string::npos) << grouping.method;
}

// With the rig's position channel (the simulator's encoder "x": the probe's
// centre), each crossing is placed where the probe was when its centre was
// over the dent: every site within 1 mm of its dent, on a panel line (whose
// phases place nothing) and on a hand's reciprocating scan alike.
TEST(DefectSitesScan, APositionChannelPlacesEverySiteWithinAMillimetre)
{
    for (const double rest_s : {3.0, 0.0})
        for (const std::vector<double>& dents :
             std::vector<std::vector<double>>{{0.030}, {-0.050}, {-0.040, 0.030}, {-0.060, 0.0, 0.050}}) {
            devices::simulator::PanelScanParameters p;
            p.restBetweenPanels_s = rest_s;
            p.positionChannel = true;
            p.defectPosition_m = dents.front();
            p.moreDefects_m.assign(dents.begin() + 1, dents.end());
            p.seed = 5;
            devices::simulator::PanelScanScenario scenario(p);
            const auto n = static_cast<std::size_t>(30.0 * p.sampleRate_hz);
            core::SampleBlock block(3, n, 0.0, 1.0 / p.sampleRate_hz);
            scenario.generate(block);
            const std::vector<std::vector<double>> cantilevers{{block.channel(0).begin(), block.channel(0).end()},
                                                               {block.channel(1).begin(), block.channel(1).end()}};
            core::detector::StretchSettings settings;
            settings.spacing_m = p.cantileverSpacing_m;
            const auto events = core::detector::detectStretches(cantilevers, settings).events;
            const auto grouping = core::detector::scanSites(
                events, core::detector::positionFromSamples({block.channel(2).begin(), block.channel(2).end()}, 0.0,
                                                            1.0 / p.sampleRate_hz));
            SCOPED_TRACE("rest " + std::to_string(rest_s) + " s, " + std::to_string(dents.size()) + " dents");
            EXPECT_EQ(grouping.method, "from the position channel");
            ASSERT_EQ(grouping.sites.size(), dents.size());
            for (std::size_t k = 0; k < dents.size(); ++k) {
                const auto& site = grouping.sites[k];
                ASSERT_EQ(site.kind, core::detector::SiteKind::Site) << core::detector::siteText(site);
                EXPECT_NEAR(*site.position_m, dents[k], 0.001) << core::detector::siteText(site);
                EXPECT_LE(std::abs(*site.position_m - dents[k]), 2.0 * site.position_u_m)
                    << core::detector::siteText(site);
            }
        }
}
