// Table-driven argument parsing in the manner of GenerateCLP/TCLAP: "--longflag value",
// "--longflag=value", "-f value", bare booleans, positional arguments by index, "--" ends options.
#include "CommandLine.h"

#include "Core/Lowercase.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace slicemesh::cli
{

namespace
{

/** Beyond a long, the value is LONG_MIN or LONG_MAX: an integer still, outside any range checked. */
bool parseInteger(const std::string& text, long& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtol(text.c_str(), &end, 10);
  return (errno == 0 || errno == ERANGE) && *end == '\0';
}

bool parseDouble(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && *end == '\0' && std::isfinite(value);
}

std::vector<std::string> splitComma(const std::string& text)
{
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, ',');)
  {
    parts.push_back(part);
  }
  return parts;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator)
{
  std::string text;
  for (const std::string& item : items)
  {
    text += (text.empty() ? "" : separator) + item;
  }
  return text;
}

/** Checks one value against the parameter's type, elements and constraints. */
void checkValue(const ModuleParameter& p, const std::string& value)
{
  const std::string who = p.spelling() + " (" + p.label + ")";
  if (p.isEnumeration())
  {
    if (std::find(p.elements.begin(), p.elements.end(), value) == p.elements.end())
    {
      throw ArgumentError(who + ": '" + value + "' is not one of " + joined(p.elements, ", "));
    }
    return;
  }
  const bool numeric = p.isInteger() || p.isFloating() || p.tag == "integer-vector" || p.tag == "float-vector" ||
                       p.tag == "double-vector" || p.tag == "point" || p.tag == "region";
  if (!numeric)
  {
    if (p.tag == "file" && value.empty() && p.defaultValue.empty())
    {
      return; // an optional file (--report, --snapshot, --inputContours) given empty: none, as Slicer leaves it out
    }
    if ((p.tag == "image" || p.tag == "geometry" || p.tag == "file") && value.empty())
    {
      throw ArgumentError(who + ": an empty path");
    }
    if (!p.fileExtensions.empty() && p.channel == "output")
    {
      // Outputs are written by extension, so an unknown one is a usage error caught before any work.
      const std::string extension = lowercase(std::filesystem::path(value).extension().string());
      if (std::find(p.fileExtensions.begin(), p.fileExtensions.end(), extension) == p.fileExtensions.end())
      {
        throw ArgumentError(who + ": '" + value + "' must end in one of " + joined(p.fileExtensions, ", "));
      }
    }
    return;
  }
  const std::vector<std::string> parts = p.isVector() || p.tag == "point" || p.tag == "region"
                                           ? splitComma(value)
                                           : std::vector<std::string>{ value };
  if ((p.tag == "point" && parts.size() != 3) || (p.tag == "region" && parts.size() != 6))
  {
    throw ArgumentError(who + ": '" + value + "' needs " + (p.tag == "point" ? "3" : "6") + " comma-separated numbers");
  }
  const bool integral = p.isInteger() || p.tag == "integer-vector";
  std::optional<double> minimum = p.minimum;
  std::optional<double> maximum = p.maximum;
  if (integral)
  {
    // An integer parameter is an int (as GenerateCLP declares it): a value beyond one would wrap
    // (--label 4294967297 meshed label 1).
    minimum = std::max(minimum.value_or(std::numeric_limits<int>::min()), double(std::numeric_limits<int>::min()));
    maximum = std::min(maximum.value_or(std::numeric_limits<int>::max()), double(std::numeric_limits<int>::max()));
  }
  for (const std::string& part : parts)
  {
    double number = 0.0;
    long whole = 0;
    if (integral ? !parseInteger(part, whole) : !parseDouble(part, number))
    {
      throw ArgumentError(who + ": '" + value + "' is not " + (integral ? "an integer" : "a number"));
    }
    if (integral)
    {
      number = static_cast<double>(whole);
    }
    if ((minimum && number < *minimum) || (maximum && number > *maximum))
    {
      std::ostringstream range;
      // Ten digits: an int's ends in full (2147483647, not 2.14748e+09).
      range << std::setprecision(10) << who << ": " << value << " is outside the range ";
      minimum ? range << *minimum : range << "-inf";
      range << " .. ";
      maximum ? range << *maximum : range << "inf";
      throw ArgumentError(range.str());
    }
  }
}

const ModuleParameter* findOption(const ModuleDescription& module, const std::string& token)
{
  for (const ModuleParameter* p : module.parameters())
  {
    if (p->isReturnParameter())
    {
      continue;
    }
    if ((!p->longflag.empty() && token == "--" + p->longflag) || (!p->flag.empty() && token == "-" + p->flag))
    {
      return p;
    }
  }
  return nullptr;
}

} // namespace

const std::string& ParsedArguments::text(const std::string& name) const
{
  const auto found = values.find(name);
  if (found == values.end())
  {
    throw std::logic_error("no parameter called '" + name + "' in the module XML");
  }
  return found->second;
}

bool ParsedArguments::flag(const std::string& name) const
{
  return text(name) == "true";
}

long ParsedArguments::integer(const std::string& name) const
{
  long value = 0;
  if (!parseInteger(text(name), value))
  {
    throw std::logic_error("parameter '" + name + "' is not an integer");
  }
  return value;
}

double ParsedArguments::number(const std::string& name) const
{
  double value = 0.0;
  if (!parseDouble(text(name), value))
  {
    throw std::logic_error("parameter '" + name + "' is not a number");
  }
  return value;
}

bool ParsedArguments::given(const std::string& name) const
{
  const auto found = wasGiven.find(name);
  return found != wasGiven.end() && found->second;
}

ParsedArguments parseCommandLine(const ModuleDescription& module, const std::vector<std::string>& arguments)
{
  ParsedArguments parsed;
  for (const ModuleParameter* p : module.parameters())
  {
    if (!p->isReturnParameter())
    {
      parsed.values[p->name] = p->isBoolean() ? "false" : p->defaultValue;
      parsed.wasGiven[p->name] = false;
    }
  }

  std::vector<std::string> positional;
  bool optionsEnded = false;
  for (std::size_t i = 0; i < arguments.size(); ++i)
  {
    std::string token = arguments[i];
    const bool looksLikeOption = !optionsEnded && token.size() > 1 && token[0] == '-';
    if (!looksLikeOption)
    {
      positional.push_back(token);
      continue;
    }
    if (token == "--")
    {
      optionsEnded = true;
      continue;
    }
    // "--name=value" is the same as "--name value".
    std::optional<std::string> attachedValue;
    const std::size_t equals = token.find('=');
    if (token.rfind("--", 0) == 0 && equals != std::string::npos)
    {
      attachedValue = token.substr(equals + 1);
      token = token.substr(0, equals);
    }
    const auto takeValue = [&]() -> std::string
    {
      if (attachedValue)
      {
        return *attachedValue;
      }
      if (i + 1 >= arguments.size())
      {
        throw ArgumentError(token + " needs a value");
      }
      return arguments[++i];
    };

    if (token == "--help" || token == "-h")
    {
      parsed.help = true;
    }
    else if (token == "--xml")
    {
      parsed.xml = true;
    }
    else if (token == "--version")
    {
      parsed.version = true;
    }
    else if (token == "--echo")
    {
      parsed.echo = true;
    }
    else if (token == "--returnparameterfile")
    {
      parsed.returnParameterFile = takeValue();
    }
    else if (token == "--processinformationaddress")
    {
      parsed.processInformationAddress = takeValue();
    }
    else if (const ModuleParameter* p = findOption(module, token))
    {
      if (p->isBoolean())
      {
        if (attachedValue)
        {
          throw ArgumentError(token + " is a switch and takes no value");
        }
        parsed.values[p->name] = "true";
      }
      else
      {
        const std::string value = takeValue();
        checkValue(*p, value);
        if (parsed.wasGiven[p->name] && !p->multiple)
        {
          throw ArgumentError(token + " is given more than once");
        }
        parsed.values[p->name] =
          parsed.wasGiven[p->name] ? parsed.values[p->name] + ";" + value : value; // multiple: ';'-joined
      }
      parsed.wasGiven[p->name] = true;
    }
    else
    {
      throw ArgumentError("unknown option '" + token + "' (see --help)");
    }
  }

  const std::vector<const ModuleParameter*> indexed = module.indexedParameters();
  // A contour file given by --inputContours stands in for the input volume, which may then be left
  // out (as 3D Slicer leaves out a volume nobody selected): the one positional argument is the output.
  const bool volumeLeftOut = module.findByName("inputContours") && !parsed.values["inputContours"].empty() &&
                             indexed.size() == 2 && positional.size() == 1;
  if (volumeLeftOut)
  {
    parsed.values[indexed[0]->name] = "";
    positional.insert(positional.begin(), std::string());
  }
  if (positional.size() > indexed.size())
  {
    throw ArgumentError("unexpected argument '" + positional[indexed.size()] + "' (see --help)");
  }
  for (std::size_t k = 0; k < indexed.size(); ++k)
  {
    const ModuleParameter& p = *indexed[k];
    if (volumeLeftOut && k == 0)
      continue;
    if (k < positional.size())
    {
      checkValue(p, positional[k]);
      parsed.values[p.name] = positional[k];
      parsed.wasGiven[p.name] = true;
    }
    else if (!(parsed.help || parsed.xml || parsed.version) && p.defaultValue.empty())
    {
      throw ArgumentError("missing argument <" + p.name + "> (" + p.label + "); usage: see --help");
    }
  }
  return parsed;
}

} // namespace slicemesh::cli
