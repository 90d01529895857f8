// Reads the Slicer Execution Model XML with VTK's expat-based XML utilities.
#include "ModuleDescription.h"

#include "Core/Lowercase.h"
#include "Core/SliceMeshTypes.h"

#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <sstream>

namespace slicemesh::cli
{

namespace
{

/** Element tags that describe a parameter (all others inside <parameters> are ignored). */
bool isParameterTag(const std::string& tag)
{
  static const std::set<std::string> tags = {
    "integer", "float", "double", "boolean", "string",
    "integer-vector", "float-vector", "double-vector", "string-vector",
    "integer-enumeration", "float-enumeration", "double-enumeration", "string-enumeration",
    "point", "pointfile", "region", "file", "directory",
    "image", "geometry", "transform", "table", "measurement"
  };
  return tags.count(tag) > 0;
}

std::string trimmed(const std::string& text)
{
  const auto isSpace = [](unsigned char c) { return std::isspace(c) != 0; };
  auto begin = std::find_if_not(text.begin(), text.end(), isSpace);
  auto end = std::find_if_not(text.rbegin(), text.rend(), isSpace).base();
  return begin < end ? std::string(begin, end) : std::string();
}

/** Character data of the first child called name, trimmed; empty when there is none. */
std::string childText(vtkXMLDataElement* element, const char* name)
{
  vtkXMLDataElement* child = element->FindNestedElementWithName(name);
  return child && child->GetCharacterData() ? trimmed(child->GetCharacterData()) : std::string();
}

std::string withoutLeadingDashes(std::string text)
{
  text.erase(0, text.find_first_not_of('-'));
  return text;
}

bool isIdentifier(const std::string& text)
{
  static const std::regex identifier("[_a-zA-Z][_a-zA-Z0-9]*");
  return std::regex_match(text, identifier);
}

double parseNumber(const std::string& text, const std::string& context)
{
  std::istringstream in(text);
  double value = 0.0;
  if (!(in >> value) || !(in >> std::ws).eof())
  {
    throw Error("module XML: " + context + " '" + text + "' is not a number");
  }
  return value;
}

ModuleParameter readParameter(vtkXMLDataElement* element)
{
  ModuleParameter p;
  p.tag = element->GetName();
  p.name = childText(element, "name");
  p.flag = withoutLeadingDashes(childText(element, "flag"));
  p.longflag = withoutLeadingDashes(childText(element, "longflag"));
  if (p.name.empty())
  {
    p.name = p.longflag;
  }
  const std::string index = childText(element, "index");
  if (!index.empty())
  {
    p.index = static_cast<int>(parseNumber(index, p.name + " index"));
  }
  p.label = childText(element, "label");
  p.description = childText(element, "description");
  p.defaultValue = childText(element, "default");
  p.channel = childText(element, "channel");
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* child = element->GetNestedElement(i);
    if (std::string(child->GetName()) == "element" && child->GetCharacterData())
    {
      p.elements.push_back(trimmed(child->GetCharacterData()));
    }
  }
  if (vtkXMLDataElement* constraints = element->FindNestedElementWithName("constraints"))
  {
    const std::string minimum = childText(constraints, "minimum");
    const std::string maximum = childText(constraints, "maximum");
    if (!minimum.empty())
    {
      p.minimum = parseNumber(minimum, p.name + " minimum");
    }
    if (!maximum.empty())
    {
      p.maximum = parseNumber(maximum, p.name + " maximum");
    }
  }
  if (const char* extensions = element->GetAttribute("fileExtensions"))
  {
    std::istringstream list(extensions);
    for (std::string extension; std::getline(list, extension, ',');)
    {
      p.fileExtensions.push_back(lowercase(trimmed(extension)));
    }
  }
  const auto attributeIsTrue = [element](const char* name)
  {
    const char* value = element->GetAttribute(name);
    return value && std::string(value) == "true";
  };
  p.multiple = attributeIsTrue("multiple");
  p.hidden = attributeIsTrue("hidden");
  return p;
}

/** The rules of SLICER_CLI.md section 1 that the command line depends on. */
void checkParameter(const ModuleParameter& p)
{
  const std::string where = "module XML: parameter '" + p.name + "'";
  if (!isIdentifier(p.name))
  {
    throw Error(where + ": the name is not an identifier");
  }
  if (!p.flag.empty() && (p.flag.size() != 1 || !std::isalpha(static_cast<unsigned char>(p.flag[0]))))
  {
    throw Error(where + ": the flag must be one letter");
  }
  if (!p.longflag.empty() && !isIdentifier(p.longflag))
  {
    throw Error(where + ": the longflag is not an identifier");
  }
  if (p.index && (!p.flag.empty() || !p.longflag.empty()))
  {
    throw Error(where + ": a flag cannot be combined with an index");
  }
  if (!p.index && p.flag.empty() && p.longflag.empty() && !p.isReturnParameter())
  {
    throw Error(where + ": needs a flag, a longflag or an index");
  }
  if (p.isBoolean() && p.defaultValue != "false")
  {
    throw Error(where + ": a boolean must default to false (present on the command line means true)");
  }
  if (p.isEnumeration() &&
      std::find(p.elements.begin(), p.elements.end(), p.defaultValue) == p.elements.end())
  {
    throw Error(where + ": the default '" + p.defaultValue + "' is not one of its elements");
  }
}

} // namespace

bool ModuleParameter::isEnumeration() const
{
  return tag.size() > 12 && tag.compare(tag.size() - 12, 12, "-enumeration") == 0;
}

bool ModuleParameter::isFloating() const
{
  return tag == "float" || tag == "double" || tag == "float-enumeration" || tag == "double-enumeration";
}

bool ModuleParameter::isVector() const
{
  return tag.size() > 7 && tag.compare(tag.size() - 7, 7, "-vector") == 0;
}

std::string ModuleParameter::spelling() const
{
  if (!longflag.empty())
  {
    return "--" + longflag;
  }
  if (!flag.empty())
  {
    return "-" + flag;
  }
  return "<" + name + ">";
}

std::vector<const ModuleParameter*> ModuleDescription::parameters() const
{
  std::vector<const ModuleParameter*> all;
  for (const ParameterGroup& group : groups)
  {
    for (const ModuleParameter& p : group.parameters)
    {
      all.push_back(&p);
    }
  }
  return all;
}

const ModuleParameter* ModuleDescription::findByName(const std::string& name) const
{
  for (const ModuleParameter* p : parameters())
  {
    if (p->name == name)
    {
      return p;
    }
  }
  return nullptr;
}

std::vector<const ModuleParameter*> ModuleDescription::indexedParameters() const
{
  std::vector<const ModuleParameter*> indexed;
  for (const ModuleParameter* p : parameters())
  {
    if (p->index)
    {
      indexed.push_back(p);
    }
  }
  std::sort(indexed.begin(), indexed.end(),
            [](const ModuleParameter* a, const ModuleParameter* b) { return *a->index < *b->index; });
  return indexed;
}

ModuleDescription parseModuleDescription(const std::string& xml)
{
  // ReadElementFromString returns a new reference (or null on malformed XML); the smart pointer owns it.
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromString(xml.c_str()));
  if (!root || std::string(root->GetName()) != "executable")
  {
    throw Error("module XML: not a well-formed <executable> document");
  }
  ModuleDescription module;
  module.title = childText(root, "title");
  module.category = childText(root, "category");
  module.description = childText(root, "description");
  module.version = childText(root, "version");
  module.documentationUrl = childText(root, "documentation-url");

  std::set<std::string> names, flags, indices;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* groupElement = root->GetNestedElement(g);
    if (std::string(groupElement->GetName()) != "parameters")
    {
      continue;
    }
    ParameterGroup group;
    group.label = childText(groupElement, "label");
    group.description = childText(groupElement, "description");
    const char* advanced = groupElement->GetAttribute("advanced");
    group.advanced = advanced && std::string(advanced) == "true";
    for (int i = 0; i < groupElement->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* element = groupElement->GetNestedElement(i);
      if (!isParameterTag(element->GetName()))
      {
        continue;
      }
      ModuleParameter p = readParameter(element);
      checkParameter(p);
      const bool unique = names.insert(p.name).second &&
                          (p.flag.empty() || flags.insert("-" + p.flag).second) &&
                          (p.longflag.empty() || flags.insert("--" + p.longflag).second) &&
                          (!p.index || indices.insert(std::to_string(*p.index)).second);
      if (!unique)
      {
        throw Error("module XML: parameter '" + p.name + "' repeats a name, flag or index");
      }
      group.parameters.push_back(std::move(p));
    }
    module.groups.push_back(std::move(group));
  }
  return module;
}

} // namespace slicemesh::cli
