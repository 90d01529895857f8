// Colour tables as ITK-SNAP writes them: names in double quotes, spaces and all, and an opacity from
// 0 to 1; read beside the whitespace-separated tables of Slicer and FreeSurfer.
#include "ColorTable.h"
#include "Core/SliceMeshTypes.h"
#include "TemporaryFolderTest.h"

#include <fstream>

namespace slicemesh::testing
{
namespace
{

class ColorTableFile : public TemporaryFolderTest
{
protected:
  ColorTableFile() : TemporaryFolderTest("slicemesh-colortable-") {}

  std::string write(const std::string& name, const std::string& text) const
  {
    std::ofstream(path(name)) << text;
    return path(name);
  }
};

TEST_F(ColorTableFile, ItkSnapLabelDescriptionsKeepTheirQuotedNames)
{
  const ColorTable table = ColorTable::read(write("labels.txt", R"(################################################
# ITK-SnAP Label Description File
# IDX   -R-  -G-  -B-  -A--  VIS MSH  LABEL
################################################
    0     0    0    0        0  0  0    "Clear Label"
    1   255    0    0        1  1  1    "Left hippocampus"
    2     0  255    0      0.5  1  0    "Lesion #2, enhancing"
   12    10   20   30        1  1  1    ""
)"));
  EXPECT_EQ(table.size(), 4u);
  EXPECT_EQ(table.entry(1).name, "Left hippocampus");
  EXPECT_EQ(table.entry(1).rgba, (std::array<unsigned char, 4>{ 255, 0, 0, 255 }));
  EXPECT_EQ(table.entry(2).name, "Lesion #2, enhancing"); // a '#' inside the quotes is no comment
  EXPECT_EQ(table.entry(2).rgba, (std::array<unsigned char, 4>{ 0, 255, 0, 128 }));
  EXPECT_EQ(table.entry(12).name, "Label_12"); // an empty name
  EXPECT_EQ(table.entry(12).rgba[2], 30);
  EXPECT_EQ(safeFileName(table.entry(1).name), "Left_hippocampus");
}

TEST_F(ColorTableFile, AQuotedLineWithoutItsNumbersOrItsClosingQuoteIsRefused)
{
  for (const std::string line : { "\"Liver\"\n", "1 255 0 0 1 1 1 \"Liver\n", "1 255 0 0 2 1 1 \"Liver\"\n",
                                  "1 300 0 0 1 1 1 \"Liver\"\n", "1.5 255 0 0 1 1 1 \"Liver\"\n" })
  {
    try
    {
      ColorTable::read(write("bad.txt", line));
      ADD_FAILURE() << "accepted: " << line;
    }
    catch (const Error& e)
    {
      EXPECT_NE(std::string(e.what()).find("bad.txt:1:"), std::string::npos) << e.what();
    }
  }
  // A quote inside a comment of a Slicer line leaves the line Slicer's.
  const ColorTable slicer = ColorTable::read(write("slicer.ctbl", "3 Kidney 10 20 30 255 # \"left\"\n"));
  EXPECT_EQ(slicer.entry(3).name, "Kidney");
  EXPECT_EQ(slicer.entry(3).rgba, (std::array<unsigned char, 4>{ 10, 20, 30, 255 }));
}

} // namespace
} // namespace slicemesh::testing
