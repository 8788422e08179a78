// index.html from a small hand-written campaign (campaign_results_fixture.h): names are escaped,
// every figure is inlined and named, the reference's columns appear only when the campaign has a
// reference, and the trial and step tables hold the fixture's values.
#include "experiment/html_report.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../common/test_folder.h"
#include "campaign_results_fixture.h"
#include "common/error.h"

namespace echoplan::experiment {
namespace {

namespace fs = std::filesystem;
using testing::small_campaign;
using testing::small_reference;

bool has(const std::string& page, const std::string& text) {
  return page.find(text) != std::string::npos;
}

int count(const std::string& page, const std::string& text) {
  int n = 0;
  for (std::size_t at = page.find(text); at != std::string::npos; at = page.find(text, at + 1)) ++n;
  return n;
}

class HtmlReport : public TestFolder {
 protected:
  void SetUp() override {
    TestFolder::SetUp();
    fs::create_directories(dir_ / "figures");
    std::ofstream(dir_ / "figures" / "belief_one_a.png", std::ios::binary) << "foo";
    std::ofstream(dir_ / "figures" / "confusion_one.png", std::ios::binary) << "fo";
  }

  const std::vector<Figure> figures_ = {{"belief_one_a", "Belief <one>", "c & d"},
                                        {"confusion_one", "Heard", "counts"}};
};

TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\xfe", 2)), "//4=");
}

TEST_F(HtmlReport, InlinesAndNamesEveryFigure) {
  const std::string page = html_report(dir_, small_campaign(), figures_);
  EXPECT_TRUE(has(page, "<h2>Belief &lt;one&gt;</h2>")) << page;
  EXPECT_TRUE(has(page, "src=\"data:image/png;base64,Zm9v\""));
  EXPECT_TRUE(has(page, "<figcaption>c &amp; d (also <code>figures/belief_one_a.svg</code>)"));
  EXPECT_TRUE(has(page, "src=\"data:image/png;base64,Zm8=\""));
  EXPECT_TRUE(has(page, "<code>figures/confusion_one.svg</code>"));
  EXPECT_EQ(count(page, "<figure>"), 2);
  fs::remove(dir_ / "figures" / "confusion_one.png");
  EXPECT_THROW(html_report(dir_, small_campaign(), figures_), InputError);
}

TEST_F(HtmlReport, EscapesNames) {
  CampaignResults results = small_campaign();
  results.config.source = "small&<x>.yaml";
  results.spec.observation.names[0] = "\"heard\" a";
  results.spec.action_names[0] = "listen<1>";
  const std::string page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<code>small&amp;&lt;x&gt;.yaml</code>"));
  EXPECT_TRUE(has(page, "<td class=\"l\">&quot;heard&quot; a</td>"));
  EXPECT_TRUE(has(page, "<th>mean listen&lt;1&gt;</th>"));
  EXPECT_FALSE(has(page, "<x>"));
  EXPECT_FALSE(has(page, "listen<1>"));
}

TEST_F(HtmlReport, ReferenceColumnsOnlyWithAReference) {
  CampaignResults results = small_campaign();
  std::string page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<h2>Results</h2>"));
  EXPECT_FALSE(has(page, "correct</th>"));
  EXPECT_FALSE(has(page, "notebook"));
  // Totals: original objects, variants and all, per arm.
  EXPECT_EQ(count(page, "<tr class=\"total\">"), 6);

  results.config.reference = small_reference("R&D");
  page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<h2>Results and the R&amp;D's</h2>"));
  EXPECT_TRUE(has(page, "<th>R&amp;D: correct</th><th>R&amp;D: reward</th></tr>"));
  EXPECT_TRUE(has(page, "<td>9/10</td><td>7.50</td></tr>"));   // a, and the original objects
  EXPECT_TRUE(has(page, "<td>25/30</td><td>4.25</td></tr>"));  // all
  EXPECT_EQ(count(page, "<td>9/10</td>"), 4);                  // 2 rows x 2 arms
  EXPECT_EQ(count(page, "<td></td><td></td></tr>"), 4);        // b_heavy and variants, per arm
  EXPECT_TRUE(has(page, "<p>Numbers from the lab's notebook &lt;p. 3&gt; &amp; friends.</p>"));
}

// With more actions than fit as columns (recorded data with many behaviours), the results table
// leaves them out and a table of their own gives each a row and each arm a column, so the page
// keeps a laptop screen's width.
TEST_F(HtmlReport, ManyBehavioursGetARowEachInsteadOfAColumn) {
  CampaignResults results = small_campaign();
  EXPECT_TRUE(has(html_report(dir_, results, {}), "<th>mean listen</th>"));
  EXPECT_FALSE(has(html_report(dir_, results, {}), "Behaviours performed per trial"));
  // As a dataset world presents itself: the sensing actions are the first five.
  results.world.per_object = false;
  results.sensing_actions = 5;
  results.spec.action_names = {"b1", "b2", "b3", "b4", "b5", "pick_a", "pick_b"};
  for (JournalEntry& e : results.entries) e.result.record.action_counts.resize(7, 0);
  const std::string page = html_report(dir_, results, {});
  EXPECT_FALSE(has(page, "<th>mean b1</th>"));
  EXPECT_TRUE(has(page, "<h2>Behaviours performed per trial</h2>"));
  EXPECT_TRUE(has(page, "<tr><th class=\"l\">behaviour</th><th>one</th><th>two</th></tr>"));
  // The fixture's first action is its listens (one: 1 + 1 + 0 in 3 trials; two: 2 + 1 + 1), its
  // second counts the trials that believed a (one: 1 of 3; two: 3 of 3).
  EXPECT_TRUE(has(page, "<tr><td class=\"l\">b1</td><td>0.67</td><td>1.33</td></tr>")) << page;
  EXPECT_TRUE(has(page, "<tr><td class=\"l\">b2</td><td>0.33</td><td>1.00</td></tr>"));
  EXPECT_TRUE(has(page, "<tr><td class=\"l\">b5</td><td>0.00</td><td>0.00</td></tr>"));
  EXPECT_FALSE(has(page, "<td class=\"l\">pick_a</td><td>"));
}

TEST_F(HtmlReport, HeardConfusionBesideTheReferencesOnlyWhenBothAreThere) {
  CampaignResults results = small_campaign();
  results.config.reference = small_reference("lab");
  // The simulated training set: 3 of 4 "a" heard as "a"; the lab: 5 of 8, and a variant.
  results.heard = {{"listen", {"a", "b"}, {"a", "b"}, {{3, 1}, {0, 4}}}};
  std::string page = html_report(dir_, results, {});
  EXPECT_FALSE(has(page, "What the classifier hears")) << "no heard counts in the reference";

  results.config.reference->heard =
      HeardReference{"report-template",
                     "From the logs.",
                     {{"listen", {"a", "b_heavy"}, {"a", "b"}, {{5, 3}, {2, 6}}}}};
  page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<code>report-template</code>"));
  EXPECT_TRUE(has(page, "<p>From the logs.</p>"));
  EXPECT_TRUE(has(page,
                  "<tr><td>a</td><td>3 1</td><td>3/4 = 0.75</td><td>5 3</td><td>5/8 = "
                  "0.62</td></tr>"));
  // "b" was not heard in the lab; "b_heavy", a variant playing "b", is right when heard as "b".
  EXPECT_TRUE(has(page, "<tr><td>b</td><td>0 4</td><td>4/4 = 1.00</td><td>-</td><td>-</td></tr>"));
  EXPECT_TRUE(
      has(page, "<tr><td>b_heavy</td><td>-</td><td>-</td><td>2 6</td><td>6/8 = 0.75</td></tr>"));
  // A row that is no class and plays none (not among the trials): counts only.
  results.config.reference->heard->actions[0].rows[1] = "c_odd";
  page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<tr><td>c_odd</td><td>-</td><td>-</td><td>2 6</td><td>-</td></tr>"));

  results.heard.clear();  // not a simulated world
  EXPECT_FALSE(has(html_report(dir_, results, {}), "What the classifier hears"));
}

TEST_F(HtmlReport, TrialAndStepTables) {
  CampaignResults results = small_campaign();
  std::string page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "6 of 6 trials finished"));
  // Trial 1 ended believing b while a was in the world: marked bad.
  EXPECT_TRUE(has(page,
                  "<tr><td>1</td><td class=\"l\">one</td><td class=\"l\">a</td><td "
                  "class=\"l\">a</td><td class=\"l bad\">b</td><td>2</td><td>1</td><td>0</td>"
                  "<td>1</td><td>-2.0000</td></tr>"));
  // Trial 3's second listen: belief 0.75 / 0.25 before it, heard_a with probability 0.75.
  EXPECT_TRUE(has(page,
                  "<tr><td>3</td><td>1</td><td>0.750</td><td>0.250</td><td class=\"l\">listen</td>"
                  "<td class=\"l\">heard_a</td><td>0.750</td></tr>"));
  // Its pick: no probability for "none".
  EXPECT_TRUE(has(page,
                  "<tr><td>3</td><td>2</td><td>1.000</td><td>0.000</td><td class=\"l\">pick_a</td>"
                  "<td class=\"l\">none</td><td></td></tr>"));
  results.belief_particles = 100;
  page = html_report(dir_, results, {});
  EXPECT_TRUE(has(page, "<th>a particles</th>"));
  EXPECT_TRUE(has(page, "<tr><td>3</td><td>1</td><td>75</td><td>25</td>"));
}

}  // namespace
}  // namespace echoplan::experiment
