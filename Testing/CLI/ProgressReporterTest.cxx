// ProgressReporter in process: Slicer's tags, monotonic overall progress, start/end per stage.
#include "ProgressReporter.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

namespace slicemesh::cli
{
namespace
{

std::vector<double> overallValues(const std::string& tags)
{
  std::vector<double> values;
  const std::regex progress("<filter-progress>([^<]*)</filter-progress>");
  for (auto it = std::sregex_iterator(tags.begin(), tags.end(), progress); it != std::sregex_iterator(); ++it)
  {
    values.push_back(std::stod((*it)[1]));
  }
  return values;
}

TEST(ProgressReporter, OverallProgressIsMonotonicAndReachesOne)
{
  std::ostringstream tags;
  ProgressReporter progress({ { "A", "first", 1.0 }, { "B", "second", 3.0 } }, &tags, nullptr);
  progress.start(0);
  progress.update(0.5);
  progress.update(0.2); // a stage may report a smaller fraction; the bar must not go back
  progress.start(1);    // ends A
  for (int i = 0; i <= 100; ++i)
  {
    progress.update(i / 100.0);
  }
  progress.finish(true);

  const std::vector<double> values = overallValues(tags.str());
  ASSERT_GE(values.size(), 4u);
  EXPECT_DOUBLE_EQ(values.front(), 0.0);
  EXPECT_DOUBLE_EQ(values.back(), 1.0);
  for (std::size_t i = 1; i < values.size(); ++i)
  {
    EXPECT_GE(values[i], values[i - 1]);
    EXPECT_LE(values[i], 1.0);
  }
  // Stage A is a quarter of the work.
  EXPECT_NE(tags.str().find("<filter-progress>0.25</filter-progress>"), std::string::npos) << tags.str();
  EXPECT_LE(values.size(), 2u + 2u + 2u + 201u / 1u) << "updates are thinned out";
}

TEST(ProgressReporter, EveryStageHasStartAndEndInOrder)
{
  std::ostringstream tags;
  ProgressReporter progress({ { "A", "first", 1.0 }, { "B", "second", 1.0 } }, &tags, nullptr);
  progress.start(0);
  progress.start(1);
  progress.finish(true);
  const std::string text = tags.str();
  const std::size_t startA = text.find("<filter-start>\n<filter-name>A</filter-name>\n<filter-comment> \"first\"");
  const std::size_t endA = text.find("<filter-end>\n<filter-name>A</filter-name>\n<filter-time>");
  const std::size_t startB = text.find("<filter-start>\n<filter-name>B</filter-name>");
  const std::size_t endB = text.find("<filter-end>\n<filter-name>B</filter-name>");
  ASSERT_NE(startA, std::string::npos);
  ASSERT_NE(endB, std::string::npos);
  EXPECT_LT(startA, endA);
  EXPECT_LT(endA, startB);
  EXPECT_LT(startB, endB);
}

TEST(ProgressReporter, AFailedStageIsEndedButNotShownAsDone)
{
  std::ostringstream tags;
  ProgressReporter progress({ { "A", "first", 1.0 }, { "B", "second", 1.0 } }, &tags, nullptr);
  progress.start(0);
  progress.update(0.5);
  progress.finish(false);
  EXPECT_NE(tags.str().find("<filter-end>"), std::string::npos);
  EXPECT_LT(overallValues(tags.str()).back(), 0.5);
}

TEST(ProgressReporter, TextBarGoesOnlyToItsOwnStream)
{
  std::ostringstream bar;
  ProgressReporter progress({ { "Only", "the stage", 1.0 } }, nullptr, &bar);
  progress.start(0);
  progress.update(0.5);
  progress.finish(true);
  EXPECT_NE(bar.str().find("100%"), std::string::npos) << bar.str();
  EXPECT_EQ(bar.str().find("<filter"), std::string::npos);
}

} // namespace
} // namespace slicemesh::cli
