// Text compared without regard to case, as
// file extensions, DICOM keywords and legacy VTK section names are.
#ifndef Lowercase_h
#define Lowercase_h

#include <algorithm>
#include <cctype>
#include <string>

namespace slicemesh
{

/** The text with ASCII letters in lower case (other bytes as they are). */
inline std::string lowercase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** Whether `text` ends in `suffix`, ASCII letters of either in any case: a file name's extension
 *  (".nii.gz", ".NRRD", ".Mha"). */
inline bool endsInAnyCase(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && lowercase(text.substr(text.size() - suffix.size())) == lowercase(suffix);
}

} // namespace slicemesh

#endif
