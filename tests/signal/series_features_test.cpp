// Tests of the series features: each kind against numbers worked by hand, the presets against the
// datasets' published layouts, and every bad spec's error.
#include "signal/series_features.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "signal/series.h"

namespace echoplan::signal {
namespace {

using ::testing::HasSubstr;

// `channels` channels of `n` samples at `rate` Hz; channel c's sample i is (c + 1) * i.
Series ramps(int channels, int n, double rate) {
  Series s;
  for (int c = 0; c < channels; ++c) s.channels.push_back("j" + std::to_string(c + 1));
  s.values.resize(static_cast<std::size_t>(channels));
  for (int i = 0; i < n; ++i) {
    s.t.push_back(i / rate);
    for (int c = 0; c < channels; ++c)
      s.values[static_cast<std::size_t>(c)].push_back((c + 1.0) * i);
  }
  return s;
}

// CY101's haptics: 7 joint torques, 10 bins each the sum of its samples, stored bin by bin (the
// dataset's 70 values are 10 rows of 7 joints). With 100 samples of (c + 1) * i, bin k of channel
// c sums i = 10k .. 10k + 9: (c + 1) * (100k + 45), at entry 7k + c.
TEST(SeriesFeatures, Cy101PresetSumsTenBinsPerJointBinByBin) {
  const SeriesFeatures f = parse_series_features("cy101-haptic");
  const Series s = ramps(7, 100, 50);
  const std::vector<double> row = f.extract(s, "x");
  ASSERT_EQ(row.size(), 70u);
  EXPECT_EQ(f.row_length(7), 70u);
  for (int c = 0; c < 7; ++c)
    for (int k = 0; k < 10; ++k)
      EXPECT_DOUBLE_EQ(row[static_cast<std::size_t>(7 * k + c)], (c + 1.0) * (100 * k + 45));
  const auto names = f.feature_names(s.channels);
  EXPECT_EQ(names.front(), "j1_b1");
  EXPECT_EQ(names[1], "j2_b1");
  EXPECT_EQ(names[7], "j1_b2");
  EXPECT_EQ(names.back(), "j7_b10");
  // Without time-major, the same numbers channel by channel.
  const std::vector<double> by_channel = parse_series_features("bins(10,sum)").extract(s, "x");
  EXPECT_DOUBLE_EQ(by_channel[10], 1 * 45 * 2.0);  // j2's first bin
  EXPECT_EQ(parse_series_features("bins(10,sum)").feature_names(s.channels)[10], "j2_b1");
}

// 23 samples in 10 bins, as numpy's array_split deals them: three bins of 3, then seven of 2.
// Sums of i: 0+1+2, 3+4+5, 6+7+8, 9+10, 11+12, ..., 21+22.
TEST(SeriesFeatures, UnevenBinsAreDealtAsArraySplit) {
  const std::vector<double> sums =
      parse_series_features("bins(10,sum)").extract(ramps(1, 23, 10), "x");
  EXPECT_EQ(sums, (std::vector<double>{3, 12, 21, 19, 23, 27, 31, 35, 39, 43}));
  const std::vector<double> means =
      parse_series_features("bins(10,mean)").extract(ramps(1, 23, 10), "x");
  EXPECT_DOUBLE_EQ(means[0], 1.0);
  EXPECT_DOUBLE_EQ(means[3], 9.5);
  EXPECT_DOUBLE_EQ(means[9], 21.5);
}

// Means do not change with the sensor's rate; sums do.
TEST(SeriesFeatures, MeansDoNotFollowTheRateSumsDo) {
  Series slow, fast;
  slow.channels = fast.channels = {"f"};
  for (int i = 0; i < 100; ++i)
    slow.t.push_back(i / 100.0), slow.values.resize(1), slow.values[0].push_back(2.0);
  for (int i = 0; i < 400; ++i)
    fast.t.push_back(i / 400.0), fast.values.resize(1), fast.values[0].push_back(2.0);
  const SeriesFeatures mean = parse_series_features("bins(5,mean)");
  const SeriesFeatures sum = parse_series_features("bins(5,sum)");
  EXPECT_EQ(mean.extract(slow, "x"), mean.extract(fast, "x"));
  EXPECT_DOUBLE_EQ(sum.extract(slow, "x")[0], 40.0);
  EXPECT_DOUBLE_EQ(sum.extract(fast, "x")[0], 160.0);
}

// The UR5 containers' wrist forces: the three force axes of a wrench, 10 bins each.
TEST(SeriesFeatures, Ur5ForcePresetReadsTheForceAxesOnly) {
  Series wrench = ramps(6, 50, 100);
  wrench.channels = {"force_x", "force_y", "force_z", "torque_x", "torque_y", "torque_z"};
  const SeriesFeatures f = parse_series_features("ur5-force");
  const std::vector<double> row = f.extract(wrench, "x");
  ASSERT_EQ(row.size(), 30u);
  // force_z is channel 3 (values 3i); its first bin averages i = 0..4: 3 * 2. Bin by bin, the
  // first bin's three axes come first.
  EXPECT_DOUBLE_EQ(row[2], 6.0);
  EXPECT_EQ(f.feature_names(wrench.channels)[2], "force_z_b1");
  EXPECT_EQ(f.feature_names(wrench.channels)[3], "force_x_b2");
  EXPECT_EQ(parse_series_features("ur5-effort").extract(ramps(6, 50, 100), "x").size(), 60u);
}

TEST(SeriesFeatures, StatsOfAKnownChannel) {
  Series s;
  s.channels = {"a"};
  s.t = {0, 1, 2, 3};
  s.values = {{1, 2, 3, 4}};
  const std::vector<double> row = parse_series_features("stats").extract(s, "x");
  ASSERT_EQ(row.size(), 5u);
  EXPECT_DOUBLE_EQ(row[0], 2.5);              // mean
  EXPECT_DOUBLE_EQ(row[1], std::sqrt(1.25));  // population standard deviation
  EXPECT_DOUBLE_EQ(row[2], 1.0);
  EXPECT_DOUBLE_EQ(row[3], 4.0);
  EXPECT_DOUBLE_EQ(row[4], std::sqrt(7.5));  // RMS: (1 + 4 + 9 + 16) / 4
}

// A unit sine at 10 Hz sampled `samples` times at 100 Hz, channel "accel".
Series sine_at_100_hz(int samples) {
  Series s;
  s.channels = {"accel"};
  s.values.resize(1);
  for (int i = 0; i < samples; ++i) {
    s.t.push_back(i / 100.0);
    s.values[0].push_back(std::sin(2 * std::numbers::pi * 10 * i / 100.0));
  }
  return s;
}

// A unit sine at 10 Hz, 200 samples at 100 Hz (20 whole cycles): its power 1/2 splits between
// +-10 Hz, so the one-sided bin at 10 Hz holds 1/4; [8, 12) Hz spans 8 bins of 0.5 Hz, mean 1/32.
TEST(SeriesFeatures, BandPowerOfASine) {
  const Series s = sine_at_100_hz(200);
  const std::vector<double> row = parse_series_features("bands(0,8,12,30)").extract(s, "x");
  ASSERT_EQ(row.size(), 3u);
  EXPECT_NEAR(row[1], 1.0 / 32, 1e-6);
  EXPECT_NEAR(row[0], 0.0, 1e-9);
  EXPECT_NEAR(row[2], 0.0, 1e-9);
  EXPECT_EQ(parse_series_features("bands(0,8,12,30)").feature_names(s.channels)[1], "accel_8_12hz");
  EXPECT_THAT([&] { parse_series_features("bands(0,60)").extract(s, "x"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("above half the series' rate")));
}

// 202 samples (twice a prime) are computed on a 216-point grid over the same 2.01 s (bins 0.495 Hz
// apart, 8 of them in [8, 12) Hz). Linear interpolation between samples 36 degrees of phase apart
// keeps 1 - (1 - cos 36)/3 of the sine's power on average over the grid's offsets, so the band's
// mean is that share of 1/32, less what leaks out of the band (20.1 cycles under a rectangular
// window: a few percent, none of it gained).
TEST(SeriesFeatures, BandPowerOnALengthWithALargePrimeFactor) {
  const Series s = sine_at_100_hz(202);
  const std::vector<double> row = parse_series_features("bands(0,8,12,30)").extract(s, "x");
  const double kept = 1.0 - (1.0 - std::cos(2 * std::numbers::pi / 10)) / 3.0;
  EXPECT_GT(row[1], 0.92 * kept / 32);
  EXPECT_LT(row[1], 1.01 * kept / 32);
  EXPECT_LT(row[0], 0.01 * row[1]);
}

// Found by series_file_fuzz: samples 0.01 s apart and one 12000 s later would resample to 1.2
// million points; such gaps are refused, naming them.
TEST(SeriesFeatures, BandsRefuseSamplesWithGaps) {
  const Series s = parse_series_csv("t,a\n0,1\n0.01,2\n0.02,3\n0.03,1\n12001,2\n", "gaps.csv");
  EXPECT_THAT([&] { parse_series_features("bands(0,1,5,20)").extract(s, "gaps.csv"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("the samples have gaps")));
}

TEST(SeriesFeatures, SpecsReadBackCanonically) {
  for (const char* spec : {"bins(10,sum)", "bins(3,mean)[a,b]", "bins(10,mean,time-major)[a]",
                           "stats", "bands(0,2.5,10)", "stats[force_z]"})
    EXPECT_EQ(parse_series_features(spec).spec(), spec);
  EXPECT_EQ(parse_series_features(" bins( 4 , mean ) ").spec(), "bins(4,mean)");
  EXPECT_EQ(parse_series_features("ur5-force").spec(),
            "bins(10,mean,time-major)[force_x,force_y,force_z]");
}

TEST(SeriesFeatures, BadSpecsSayWhatIsWrong) {
  const auto error = [](const char* spec, const char* what) {
    EXPECT_THAT([&] { parse_series_features(spec); },
                ::testing::ThrowsMessage<InputError>(HasSubstr(what)))
        << spec;
  };
  error("bins(10)", "how many, sum or mean, and optionally time-major");
  error("bins(10,sum,time)", "the third argument of bins is time-major, not 'time'");
  error("bins(0,sum)", "whole number from 1");
  error("bins(2.5,sum)", "whole number");
  error("bins(10,max)", "sum or the mean");
  error("stats(3)", "no arguments");
  error("bands(5)", "at least two edges");
  error("bands(5,2)", "must increase");
  error("bands(-1,2)", "negative");
  error("wavelets", "unknown kind 'wavelets'");
  error("wavelets", "cy101-haptic");
  error("bins(10,sum)[a,a]", "listed twice");
  error("bins(10,sum)[a,]", "empty");
  error("bins(10,sum)[a", "']'");
  error("bins(10,sum", "')'");
}

TEST(SeriesFeatures, BadSeriesForAnExtractorAreNamed) {
  EXPECT_THAT([] { parse_series_features("bins(10,mean)").extract(ramps(1, 5, 10), "p.csv"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("5 samples, fewer than the 10 bins")));
  EXPECT_THAT([] { parse_series_features("stats[zz]").extract(ramps(2, 5, 10), "p.csv"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("no channel 'zz'")));
}

}  // namespace
}  // namespace echoplan::signal
