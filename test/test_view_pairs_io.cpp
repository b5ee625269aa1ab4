/*
 * pcl_tensor: the pairs file of pcl_tensor_model.
 */
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/view_pairs_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace
{
  std::string
  writePairs (const std::string& name, const std::string& text)
  {
    const std::string path = ::testing::TempDir () + name;
    std::ofstream (path) << text;
    return path;
  }

  const std::vector<std::string> kViews = {"scans/a.ply", "scans/b.ply", "other/c.pcd"};
}

TEST (ViewPairsIO, ReadsIndicesAndNames)
{
  const auto pairs = pcl::io::loadViewPairs (
      writePairs ("pairs.txt", "# overlapping views\n0 1\n\nb.ply other/c.pcd\n  2   scans/a.ply  \n"), kViews);
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 2}, {2, 0}};
  EXPECT_EQ (pairs, expected);
}

TEST (ViewPairsIO, RefusesBadLinesWithTheLineNumber)
{
  struct Case
  {
    const char* name;
    const char* text;
    const char* line;  // where the message must point
  };
  const Case cases[] = {
    {"one.txt", "0 1\n2\n", "one.txt:2:"},              // one entry
    {"three.txt", "0 1 2\n", "three.txt:1:"},            // three entries
    {"unknown.txt", "# c\n0 d.ply\n", "unknown.txt:2:"},  // no such view
    {"range.txt", "0 3\n", "range.txt:1:"},              // index out of range
    {"self.txt", "a.ply 0\n", "self.txt:1:"},            // a view with itself
    {"negative.txt", "-1 0\n", "negative.txt:1:"},
  };
  for (const auto& c : cases)
  {
    try
    {
      pcl::io::loadViewPairs (writePairs (c.name, c.text), kViews);
      ADD_FAILURE () << c.name << " was accepted";
    }
    catch (const pcl::IOException& e)
    {
      EXPECT_NE (pcl::errorDescription (e).find (c.line), std::string::npos) << pcl::errorDescription (e);
    }
  }
  EXPECT_THROW (pcl::io::loadViewPairs ("/nonexistent/pairs.txt", kViews), pcl::IOException);
  // A directory opens like a file on Linux and reads as no pairs at all: it must not pass as an empty list.
  EXPECT_THROW (pcl::io::loadViewPairs (std::filesystem::temp_directory_path ().string (), kViews), pcl::IOException);
}

TEST (ViewPairsIO, AmbiguousFileNamesMustBeGivenInFull)
{
  const std::vector<std::string> views = {"left/a.ply", "right/a.ply"};
  EXPECT_THROW (pcl::io::loadViewPairs (writePairs ("ambiguous.txt", "a.ply 1\n"), views), pcl::IOException);
  const auto pairs = pcl::io::loadViewPairs (writePairs ("full.txt", "left/a.ply right/a.ply\n"), views);
  ASSERT_EQ (pairs.size (), 1u);
  EXPECT_EQ (pairs[0], std::make_pair (0, 1));
}
