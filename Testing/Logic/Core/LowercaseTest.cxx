// Text compared without regard to case: the one suffix test the readers choose formats by.
#include "Core/Lowercase.h"

#include <gtest/gtest.h>

namespace slicemesh
{
namespace
{

TEST(Lowercase, EndsInAnyCaseComparesTheSuffixWithoutRegardToCase)
{
  EXPECT_TRUE(endsInAnyCase("brain.nii.gz", ".nii.gz"));
  EXPECT_TRUE(endsInAnyCase("BRAIN.NII.GZ", ".nii.gz"));
  EXPECT_TRUE(endsInAnyCase("Brain.Nrrd", ".NRRD"));
  EXPECT_TRUE(endsInAnyCase(".mha", ".mha"));
  EXPECT_TRUE(endsInAnyCase("anything", ""));
  EXPECT_FALSE(endsInAnyCase("brain.nii.gz", ".nii"));
  EXPECT_FALSE(endsInAnyCase("mha", ".mha")) << "shorter than the suffix";
  EXPECT_FALSE(endsInAnyCase("", ".nrrd"));
  EXPECT_TRUE(endsInAnyCase("L\xc3\xa9SION", "l\xc3\xa9sion"));
  EXPECT_FALSE(endsInAnyCase("L\xc3\xa9sion", "l\xc3\x89sion")) << "only ASCII letters change case";
}

} // namespace
} // namespace slicemesh
