// Well-formed UTF-8: what the report's JSON must hold, and how a structure set's undeclared names
// are told apart from Latin-1 ones.
#ifndef Utf8_h
#define Utf8_h

#include <cstddef>
#include <string>

namespace slicemesh
{

/** The length of the valid UTF-8 sequence at `at` (1 to 4 bytes), 0 when it is not one: a stray
 *  continuation byte, a sequence cut short, an overlong form, a surrogate or beyond U+10FFFF. */
inline std::size_t utf8SequenceLength(const unsigned char* at, const unsigned char* end)
{
  const unsigned char lead = at[0];
  if (lead < 0x80)
    return 1;
  std::size_t length = 0; // 0xC0, 0xC1 and 0xF5 on lead only overlong forms or beyond U+10FFFF
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF)
    length = 3;
  else if (lead >= 0xF0 && lead <= 0xF4)
    length = 4;
  if (length == 0 || static_cast<std::size_t>(end - at) < length)
    return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((at[k] & 0xC0) != 0x80)
      return 0;
  // The second byte's range that excludes overlong forms, surrogates and code points over U+10FFFF.
  const unsigned char second = at[1];
  if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) || (lead == 0xF0 && second < 0x90) ||
      (lead == 0xF4 && second > 0x8F))
    return 0;
  return length;
}

/** One character of a text as forEachCharacter gives it: its bytes and, where they are well-formed
 *  UTF-8, its code point. A byte that starts no well-formed sequence is a character of its own. */
struct Utf8Character
{
  const char* bytes = nullptr;
  std::size_t length = 0;  ///< bytes, 1 to 4
  bool wellFormed = false; ///< utf8SequenceLength accepts it
  char32_t codePoint = 0;  ///< 0 where not wellFormed
};

/** Calls visit(character) for each character of the text in order, as long as visit returns true. */
template <typename Visit>
void forEachCharacter(const std::string& text, Visit visit)
{
  static constexpr unsigned char leadBits[5] = { 0, 0x7F, 0x1F, 0x0F, 0x07 };
  const auto* at = reinterpret_cast<const unsigned char*>(text.data());
  const auto* const end = at + text.size();
  while (at < end)
  {
    Utf8Character character;
    character.bytes = reinterpret_cast<const char*>(at);
    const std::size_t sequence = utf8SequenceLength(at, end);
    character.wellFormed = sequence > 0;
    character.length = character.wellFormed ? sequence : 1;
    if (character.wellFormed)
    {
      character.codePoint = at[0] & leadBits[sequence];
      for (std::size_t k = 1; k < sequence; ++k)
        character.codePoint = (character.codePoint << 6) | (at[k] & 0x3F);
    }
    if (!visit(character))
      return;
    at += character.length;
  }
}

/** Whether the whole text is well-formed UTF-8 (utf8SequenceLength). */
inline bool isUtf8(const std::string& text)
{
  bool wellFormed = true;
  forEachCharacter(text, [&](const Utf8Character& c) { return wellFormed = c.wellFormed; });
  return wellFormed;
}

} // namespace slicemesh

#endif
