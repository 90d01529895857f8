// Label names and colours from a colour table file: 3D Slicer's .ctbl/.txt, FreeSurfer's LUT, an
// ITK-SNAP label description file, or a plain "value name" list (MRIcron's atlas .txt such as
// aal.nii.txt).
#ifndef ColorTable_h
#define ColorTable_h

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace slicemesh
{

struct LabelColor
{
  int label = 0;
  std::string name;
  std::array<unsigned char, 4> rgba{ 128, 128, 128, 255 };
};

/** label -> name and colour. */
class ColorTable
{
public:
  /** Reads the file. Each non-comment line is `value name [r g b [a]]` (whitespace separated;
   *  `#` starts a comment). Slicer's .ctbl/.txt give alpha as opacity (255 opaque); FreeSurfer's
   *  FreeSurferColorLUT.txt gives 0 for every entry (its fourth number is a transparency): when
   *  every entry's alpha is 0 the table is read as FreeSurfer's and all colours are opaque. Lines
   *  without a colour get the generated colour of their label. A line whose name is in double quotes
   *  is ITK-SNAP's, `value r g b opacity visible mesh "name"`: the name may hold spaces, the opacity
   *  runs from 0 to 1. Throws slicemesh::Error naming the file and line on a malformed line. */
  static ColorTable read(const std::string& path);

  /** The entry of a label; a label the table does not list gets the name "Label_<value>" and its
   *  generated colour. */
  LabelColor entry(int label) const;
  bool contains(int label) const { return this->Entries.count(label) != 0; }
  std::size_t size() const { return this->Entries.size(); }

  /** A deterministic, well-spread colour for a label (golden-ratio hue steps). */
  static std::array<unsigned char, 4> generatedColor(int label);

  /** The labels the file lists more than once, in the order their repeats come: the last line of
   *  each is the entry. */
  const std::vector<int>& repeatedLabels() const { return this->Repeated; }

private:
  std::map<int, LabelColor> Entries;
  std::vector<int> Repeated;
};

/** The longest safeFileName: room for the number before it and the extension after it. */
constexpr std::size_t maxSafeFileNameLength = 200;

/** A file-name-safe form of a label name: ASCII letters, digits, '-', '_' and '.', and the letters
 *  and signs of other scripts as their UTF-8 bytes; each other character (ASCII punctuation and
 *  spaces, controls, spaces and formatting characters beyond ASCII, a byte that is not well-formed
 *  UTF-8) becomes one '_'. Cut between characters at maxSafeFileNameLength bytes at most. */
std::string safeFileName(const std::string& name);

} // namespace slicemesh

#endif
