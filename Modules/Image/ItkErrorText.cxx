#include "ItkErrorText.h"

#include <cctype>

namespace slicemesh
{

std::string collapsedWhitespace(const std::string& text)
{
  std::string line;
  bool pendingSpace = false;
  for (char c : text)
  {
    if (std::isspace(static_cast<unsigned char>(c)))
    {
      pendingSpace = !line.empty();
      continue;
    }
    if (pendingSpace)
      line += ' ';
    pendingSpace = false;
    line += c;
  }
  return line;
}

namespace
{

/** The text after a leading "itk::ERROR: Class(0x...): " (ITK 5) or "ITK ERROR: Class(0x...): ". */
std::string withoutItkPrefix(std::string text)
{
  for (const std::string prefix : { "itk::ERROR: ", "ITK ERROR: " })
    if (text.compare(0, prefix.size(), prefix) == 0)
    {
      text.erase(0, prefix.size());
      const std::size_t open = text.find('('), close = text.find("): ");
      if (open != std::string::npos && close != std::string::npos && open < close &&
          text.compare(open + 1, 2, "0x") == 0 && text.find(' ') > open)
        text.erase(0, close + 3);
      break;
    }
  return text;
}

} // namespace

std::string itkErrorText(const itk::ExceptionObject& error)
{
  const char* description = error.GetDescription();
  std::string text = withoutItkPrefix(collapsedWhitespace(description && *description ? description : error.what()));
  const std::string link = "[nrrd] ";
  if (const std::size_t last = text.rfind(link); last != std::string::npos)
  {
    text = text.substr(last + link.size());
    // The link starts with the function's name ("_nrrdReadNrrdParse_sizes: ").
    if (const std::size_t colon = text.find(": "); colon != std::string::npos && text.find(' ') > colon)
      text = text.substr(colon + 2);
  }
  constexpr std::size_t maxLength = 200;
  if (text.size() > maxLength)
    text = text.substr(0, maxLength - 3) + "...";
  return text.empty() ? std::string("unknown ITK error") : text;
}

} // namespace slicemesh
