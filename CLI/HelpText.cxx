// --help and --echo text.
#include "HelpText.h"

#include <sstream>

namespace slicemesh::cli
{

namespace
{

/** Greedy word wrap of text to width columns, each line prefixed by indent. */
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width = 100)
{
  std::istringstream words(text);
  std::string result = std::string(indent, ' ');
  std::size_t column = indent;
  bool lineEmpty = true;
  for (std::string word; words >> word;)
  {
    if (!lineEmpty && column + 1 + word.size() > width)
    {
      result += "\n" + std::string(indent, ' ');
      column = indent;
      lineEmpty = true;
    }
    if (!lineEmpty)
    {
      result += ' ';
      ++column;
    }
    result += word;
    column += word.size();
    lineEmpty = false;
  }
  return result + "\n";
}

std::string valueKind(const ModuleParameter& p)
{
  if (p.isEnumeration())
  {
    std::string kinds;
    for (const std::string& element : p.elements)
    {
      kinds += (kinds.empty() ? "" : "|") + element;
    }
    return kinds;
  }
  if (p.tag == "integer")
  {
    return "integer";
  }
  if (p.tag == "float" || p.tag == "double")
  {
    return "number";
  }
  if (p.tag == "point")
  {
    return "x,y,z";
  }
  return p.tag;
}

std::string optionLine(const ModuleParameter& p)
{
  std::string line = "  ";
  if (p.index)
  {
    return line + "<" + p.name + ">";
  }
  if (!p.flag.empty())
  {
    line += "-" + p.flag + (p.longflag.empty() ? "" : ", ");
  }
  if (!p.longflag.empty())
  {
    line += "--" + p.longflag;
  }
  if (!p.isBoolean())
  {
    line += " <" + valueKind(p) + ">";
  }
  return line;
}

} // namespace

std::string helpText(const ModuleDescription& module, const std::string& programName)
{
  std::ostringstream out;
  out << "Usage: " << programName << " [options]";
  for (const ModuleParameter* p : module.indexedParameters())
  {
    out << " <" << p->name << ">";
  }
  out << "\n\n" << module.title << " " << module.version << "\n" << wrapped(module.description, 0);
  for (const ParameterGroup& group : module.groups)
  {
    out << "\n" << group.label << (group.advanced ? " (advanced)" : "") << ":\n";
    for (const ModuleParameter& p : group.parameters)
    {
      if (p.isReturnParameter())
      {
        out << "  " << p.name << " (result, written to --returnparameterfile)\n";
        out << wrapped(p.label + ". " + p.description, 6);
        continue;
      }
      out << optionLine(p) << "\n";
      out << wrapped(p.label + ". " + p.description, 6);
      // Facts on a line of their own, so wrapping never splits "Default: value".
      std::ostringstream facts;
      if (!p.isBoolean() && !p.defaultValue.empty())
      {
        facts << "  Default: " << p.defaultValue;
      }
      if (p.minimum || p.maximum)
      {
        facts << "  Range: ";
        p.minimum ? facts << *p.minimum : facts << "-inf";
        facts << " .. ";
        p.maximum ? facts << *p.maximum : facts << "inf";
      }
      if (!p.fileExtensions.empty())
      {
        facts << "  Extensions:";
        for (const std::string& extension : p.fileExtensions)
        {
          facts << " " << extension;
        }
      }
      if (!facts.str().empty())
      {
        out << "    " << facts.str() << "\n";
      }
    }
  }
  out << "\nGeneral options:\n"
      << "  -h, --help\n" << wrapped("Print this help and exit.", 6)
      << "  --xml\n" << wrapped("Print the Slicer Execution Model XML that describes this module and exit.", 6)
      << "  --version\n" << wrapped("Print the version and exit.", 6)
      << "  --echo\n" << wrapped("Print the parsed arguments, then run.", 6)
      << "  --returnparameterfile <file>\n"
      << wrapped("After the mesh is written, write the results as 'name = value' lines to this file.", 6)
      << "  --processinformationaddress <address>\n"
      << wrapped("Accepted for 3D Slicer compatibility and ignored.", 6);
  return out.str();
}

std::string echoText(const ModuleDescription& module, const ParsedArguments& arguments)
{
  std::ostringstream out;
  out << module.title << " arguments:\n";
  for (const ModuleParameter* p : module.parameters())
  {
    if (!p->isReturnParameter())
    {
      out << "  " << p->name << " = " << arguments.text(p->name) << "\n";
    }
  }
  if (!arguments.returnParameterFile.empty())
  {
    out << "  returnparameterfile = " << arguments.returnParameterFile << "\n";
  }
  return out.str();
}

} // namespace slicemesh::cli
