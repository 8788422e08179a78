// The campaign's figures: the data gnuplot plots, from the hand-written campaign of
// campaign_results_fixture.h; the figures drawn (one PNG and one SVG each, in page order); and the
// template spectrograms, whose mean over two recordings is the mean of each one's.
#include "experiment/campaign_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "audio/io.h"
#include "campaign_results_fixture.h"
#include "common/error.h"
#include "experiment/gnuplot.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;
using testing::small_campaign;

std::string head_of(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  return bytes.substr(0, static_cast<std::size_t>(in.gcount()));
}

TEST(CampaignFigures, BeliefData) {
  // Trial 3: listens twice hearing a (0.5 -> 0.75 -> 1), then picks.
  const std::vector<StepRecord> steps = small_campaign().entries[3].result.steps;
  EXPECT_EQ(belief_data(steps, 0), "0 0.5 0.5\n1 0.75 0.25\n2 1 0\n");
  EXPECT_EQ(belief_data(steps, 1000), "0 500 500\n1 750 250\n2 1000 0\n");
}

TEST(CampaignFigures, ConfusionData) {
  ConfusionCounts c;
  c.rows = {"a", "b_heavy"};
  c.columns = {"heard_a", "heard_b"};
  c.counts = {{2, 1}, {0, 1}};
  // column, row, count; rows outer.
  EXPECT_EQ(confusion_data(c), "0 0 2\n1 0 1\n0 1 0\n1 1 1\n");
}

TEST(CampaignFigures, DrawsEachFigureAsPngAndSvgInPageOrder) {
  try {
    find_gnuplot();
  } catch (const InputError&) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_figures_test";
  fs::remove_all(dir);
  const std::vector<Figure> figures = draw_figures(dir, small_campaign(), {});
  std::vector<std::string> stems;
  for (const Figure& f : figures) stems.push_back(f.stem);
  EXPECT_EQ(stems, (std::vector<std::string>{"belief_one_a", "belief_one_b_heavy", "confusion_one",
                                             "belief_two_a", "belief_two_b_heavy", "confusion_two",
                                             "reliability"}));
  EXPECT_EQ(figures[0].title, "Belief at each decision: a in the world, arm one");
  EXPECT_NE(figures[0].caption.find("1 = listen, 2 = pick_a, 3 = pick_b"), std::string::npos)
      << figures[0].caption;
  for (const std::string& stem : stems) {
    EXPECT_EQ(head_of(dir / "figures" / (stem + ".png"), 4), "\x89PNG") << stem;
    const std::string svg = head_of(dir / "figures" / (stem + ".svg"), 400);
    EXPECT_NE(svg.find("<svg"), std::string::npos) << stem;
  }
  fs::remove_all(dir);
}

// A campaign heard through noise whose steps measured their recordings draws each arm by noise
// level last; without world.noise the figure is not drawn (above).
TEST(CampaignFigures, ACampaignHeardThroughNoiseDrawsItsArmsByNoiseLevel) {
  try {
    find_gnuplot();
  } catch (const InputError&) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  CampaignResults results = small_campaign();
  results.config.world.noise = {{"white"}, "0"};
  for (JournalEntry& e : results.entries)
    for (StepRecord& s : e.result.steps) s.heard_ebr_db = 3.0 + e.id;
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_noise_figure_test";
  fs::remove_all(dir);
  const std::vector<Figure> figures = draw_figures(dir, results, {});
  ASSERT_FALSE(figures.empty());
  EXPECT_EQ(figures.back().stem, "noise_levels");
  EXPECT_EQ(head_of(dir / "figures" / "noise_levels.png", 4), "\x89PNG");
  fs::remove_all(dir);
}

// A 0.5 s mono clip at 16 kHz: silence, then a decaying tone from 0.1 s.
audio::AudioClip tone(double hz, double amplitude) {
  audio::AudioClip clip;
  clip.sample_rate = 16000;
  clip.samples.assign(8000, 0.0f);
  for (std::size_t i = 1600; i < clip.samples.size(); ++i) {
    const double t = (i - 1600) / 16000.0;
    clip.samples[i] =
        static_cast<float>(amplitude * std::exp(-8 * t) * std::sin(2 * M_PI * hz * t));
  }
  return clip;
}

TEST(CampaignFigures, TemplateIsTheMeanOfItsRecordings) {
  const fs::path dir = fs::temp_directory_path() / "echoplan_campaign_figures_templates";
  fs::remove_all(dir);
  auto write = [&](const std::string& object, const std::string& name,
                   const audio::AudioClip& clip) {
    fs::create_directories(dir / object / "strike");
    audio::write_audio((dir / object / "strike" / name).string(), clip);
  };
  write("both", "x.wav", tone(440, 0.5));
  write("both", "y.wav", tone(1500, 0.2));
  write("only_x", "x.wav", tone(440, 0.5));
  write("only_y", "y.wav", tone(1500, 0.2));
  const std::vector<TemplateMatrix> t =
      template_matrices(dir, {"both", "only_x", "missing", "only_y"}, {"strike", "slide"});
  ASSERT_EQ(t.size(), 3u);  // no recordings of "missing" or of any slide: no template
  EXPECT_EQ(t[0].object, "both");
  EXPECT_EQ(t[0].action, "strike");
  EXPECT_EQ(t[0].recordings, 2);
  EXPECT_EQ(t[1].object, "only_x");
  EXPECT_EQ(t[2].object, "only_y");
  EXPECT_DOUBLE_EQ(t[0].hop_seconds, 0.01);  // the psf preset's 10 ms hop
  EXPECT_EQ(t[0].mean.cols, 26u);            // its 26 mel bands
  ASSERT_EQ(t[1].mean.values.size(), t[0].mean.values.size());
  ASSERT_EQ(t[2].mean.values.size(), t[0].mean.values.size());
  for (std::size_t v = 0; v < t[0].mean.values.size(); ++v)
    ASSERT_NEAR(t[0].mean.values[v], (t[1].mean.values[v] + t[2].mean.values[v]) / 2, 1e-4) << v;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace echoplan::experiment
