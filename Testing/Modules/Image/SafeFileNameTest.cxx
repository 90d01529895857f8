// A label or segment name becomes part of a mesh's file name: readable in any script, with nothing
// that hides in a listing, and never more bytes than a file name may hold.
#include "ColorTable.h"
#include "Core/Utf8.h"

#include <gtest/gtest.h>

#include <string>

namespace slicemesh
{
namespace
{

TEST(SafeFileName, KeepsTheLettersOfEveryScript)
{
  EXPECT_EQ(safeFileName("R\xC3\xBC" "ckenmark"), "R\xC3\xBC" "ckenmark");       // Rückenmark
  EXPECT_EQ(safeFileName("\xE8\x82\x9D\xE8\x87\x93"), "\xE8\x82\x9D\xE8\x87\x93"); // 肝臓
  EXPECT_EQ(safeFileName("L\xC3\xA9sion 2"), "L\xC3\xA9sion_2");                   // Lésion 2
}

TEST(SafeFileName, ReplacesEachHiddenOrSeparatingCharacterByOneUnderscore)
{
  EXPECT_EQ(safeFileName("Left Hippocampus/2"), "Left_Hippocampus_2");
  // A no-break space, a zero-width space, a right-to-left override, an ideographic space.
  EXPECT_EQ(safeFileName("a\xC2\xA0" "b\xE2\x80\x8B" "c\xE2\x80\xAE" "d\xE3\x80\x80" "e"), "a_b_c_d_e");
  // A C1 control and a byte order mark.
  EXPECT_EQ(safeFileName("\xC2\x85x\xEF\xBB\xBF"), "_x_");
  // Arabic's letter mark (a direction mark in real Arabic text), the Ogham space, the Mongolian vowel
  // separator and a tag character.
  EXPECT_EQ(safeFileName("\xD8\xA7\xD9\x84\xD8\x9C" "a\xE1\x9A\x80" "b\xE1\xA0\x8E" "c\xF3\xA0\x80\xA1"),
            "\xD8\xA7\xD9\x84_a_b_c_");
}

TEST(SafeFileName, ReplacesBytesThatAreNotUtf8OneByOne)
{
  // Latin-1 "ü" (one byte) and a sequence cut short: no byte of either passes into the name.
  EXPECT_EQ(safeFileName("R\xFC" "ckenmark"), "R_ckenmark");
  EXPECT_EQ(safeFileName("a\xE8\x82"), "a__");
  EXPECT_EQ(safeFileName(""), "unnamed");
}

TEST(SafeFileName, CutsALongNameBetweenCharacters)
{
  std::string longName;
  for (int i = 0; i < 150; ++i)
    longName += "\xC3\xBC"; // 300 bytes of "ü"
  const std::string cut = safeFileName("x" + longName);
  EXPECT_LE(cut.size(), maxSafeFileNameLength);
  EXPECT_GE(cut.size(), maxSafeFileNameLength - 1);
  EXPECT_TRUE(isUtf8(cut));
  EXPECT_EQ(safeFileName(std::string(300, 'A')), std::string(maxSafeFileNameLength, 'A'));
}

} // namespace
} // namespace slicemesh
