// The option table (OptionTable.h) against the ParaView panel: the build writes VolGridTetrahedralize.xml
// from Plugin/VolGridTetrahedralize.xml.in (fillOptionPlaceholders); every option's default and slider
// range in the generated file must be the table's, so that a default or a range changes in one place.
// Further tests show the check catches an XML that disagrees and the generator refuses a template that
// keeps a number of its own.
#include "OptionTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace volgrid;

namespace
{

std::string readFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The XML the build generated for the plugin.
std::string readPluginXml()
{
  return readFile(VOLGRID_GENERATED_PLUGIN_XML);
}

// The value of attribute `name` in `tag` (the text of one XML start tag), or "" when absent.
std::string attribute(const std::string& tag, const std::string& name)
{
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos)
    return "";
  const size_t begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

std::string show(double x)
{
  std::ostringstream os;
  os << x;
  return os.str();
}

// What the XML says of `spec`'s property that the table does not; empty when they agree.
std::vector<std::string> disagreements(const std::string& xml, const OptionSpec& spec)
{
  const std::string element = spec.type == OptionType::Integer ? "IntVectorProperty" : "DoubleVectorProperty";
  const std::string domain = spec.type == OptionType::Integer ? "IntRangeDomain" : "DoubleRangeDomain";
  const std::string name = spec.property;
  const size_t start = xml.find("<" + element + " name=\"" + name + "\"");
  if (start == std::string::npos)
    return { name + ": no " + element + " in the XML" };
  const size_t end = xml.find("</" + element + ">", start);
  const std::string property = xml.substr(start, end - start);
  const std::string head = property.substr(0, property.find('>'));
  const size_t domainAt = property.find("<" + domain);
  if (domainAt == std::string::npos)
    return { name + ": no " + domain };
  const std::string range = property.substr(domainAt, property.find('>', domainAt) - domainAt);

  std::vector<std::string> found;
  const std::string xmlDefault = attribute(head, "default_values");
  if (xmlDefault.empty() || std::stod(xmlDefault) != spec.defaultValue)
    found.push_back(name + ": default " + xmlDefault + " in the XML, " + show(spec.defaultValue) + " in the table");
  const std::string xmlMin = attribute(range, "min"), xmlMax = attribute(range, "max");
  if (xmlMin.empty() || std::stod(xmlMin) != spec.sliderMin)
    found.push_back(name + ": min " + xmlMin + " in the XML, " + show(spec.sliderMin) + " in the table");
  const bool maxAgrees = xmlMax.empty() ? std::isinf(spec.sliderMax) : std::stod(xmlMax) == spec.sliderMax;
  if (!maxAgrees)
    found.push_back(name + ": max '" + xmlMax + "' in the XML, " + show(spec.sliderMax) + " in the table");
  return found;
}

std::vector<std::string> allDisagreements(const std::string& xml)
{
  std::vector<std::string> found;
  for (const auto& rows :
       { std::vector<const OptionSpec*>(std::begin(option::table), std::end(option::table)),
         std::vector<const OptionSpec*>(std::begin(option::layerTable), std::end(option::layerTable)) })
    for (const OptionSpec* spec : rows)
      for (const std::string& line : disagreements(xml, *spec))
        found.push_back(line);
  return found;
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// `xml` with the value of the first attribute `name` after `anchor` set to `value`.
std::string withAttribute(std::string xml, const std::string& anchor, const std::string& name, const std::string& value)
{
  const size_t at = xml.find(anchor);
  EXPECT_NE(at, std::string::npos) << anchor;
  const size_t begin = xml.find(" " + name + "=\"", at);
  EXPECT_NE(begin, std::string::npos) << name;
  if (at == std::string::npos || begin == std::string::npos)
    return xml;
  const size_t valueAt = begin + name.size() + 3;
  return xml.replace(valueAt, xml.find('"', valueAt) - valueAt, value);
}
} // namespace

TEST(OptionTable, PluginXmlAgreesWithTheTable)
{
  const std::string xml = readPluginXml();
  ASSERT_FALSE(xml.empty());
  EXPECT_EQ(allDisagreements(xml), std::vector<std::string>());
}

TEST(OptionTable, ADisagreeingPluginXmlIsCaught)
{
  // A copy of the generated XML with Beta's default and TargetMinDihedral's slider maximum edited by hand.
  const std::string xml = readPluginXml();
  const std::string defaultChanged = withAttribute(xml, "name=\"Beta\"", "default_values", "12345");
  ASSERT_EQ(allDisagreements(defaultChanged).size(), 1u);
  EXPECT_EQ(allDisagreements(defaultChanged)[0],
            "Beta: default 12345 in the XML, " + show(option::beta.defaultValue) + " in the table");
  const std::string rangeChanged = withAttribute(xml, "name=\"TargetMinDihedral\"", "max", "12345");
  ASSERT_EQ(allDisagreements(rangeChanged).size(), 1u);
  EXPECT_EQ(allDisagreements(rangeChanged)[0],
            "TargetMinDihedral: max '12345' in the XML, " + show(option::targetAngle.sliderMax) + " in the table");
}

TEST(OptionTable, TheGeneratedXmlIsTheFilledTemplate)
{
  const std::string templ = readFile(VOLGRID_PLUGIN_XML_TEMPLATE);
  ASSERT_FALSE(templ.empty());
  std::string filled;
  ASSERT_TRUE(fillOptionPlaceholders(templ, filled).ok());
  EXPECT_EQ(filled, readPluginXml());
  EXPECT_EQ(filled.find("@VOLGRID_OPTION_"), std::string::npos);
  // Numbers as people write them: 0.4, not 0.40000000000000002; 60, not 6e+01.
  EXPECT_EQ(filled.find("e+"), std::string::npos);
  EXPECT_EQ(filled.find("0000000"), std::string::npos);
}

TEST(OptionTable, ATemplateKeepingItsOwnNumberIsRefused)
{
  const std::string templ = readFile(VOLGRID_PLUGIN_XML_TEMPLATE);
  std::string filled;
  const Status ownDefault = fillOptionPlaceholders(
    replaced(templ, "default_values=\"@VOLGRID_OPTION_Beta_DEFAULT@\"", "default_values=\"0.55\""), filled);
  EXPECT_FALSE(ownDefault.ok());
  EXPECT_NE(ownDefault.message.find("@VOLGRID_OPTION_Beta_DEFAULT@"), std::string::npos) << ownDefault.message;
  const Status unknown = fillOptionPlaceholders(templ + "@VOLGRID_OPTION_Gamma_DEFAULT@", filled);
  EXPECT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message.find("VOLGRID_OPTION_Gamma_DEFAULT"), std::string::npos) << unknown.message;
  EXPECT_FALSE(fillOptionPlaceholders(templ + "@VOLGRID_OPTION_Alpha", filled).ok());
}

TEST(OptionTable, DefaultsAndSlidersLieInTheValidRange)
{
  for (const OptionSpec* spec : option::table)
  {
    EXPECT_TRUE(spec->valid(spec->defaultValue)) << spec->name;
    EXPECT_GE(spec->sliderMin, spec->minimum) << spec->name;
    EXPECT_LE(spec->sliderMax, spec->maximum) << spec->name;
    EXPECT_EQ(findOption(spec->name), spec);
    EXPECT_EQ(findOptionByProperty(spec->property), spec);
  }
  EXPECT_FALSE(option::targetAngle.valid(0));
  EXPECT_TRUE(option::targetAngle.valid(60));
  EXPECT_FALSE(option::targetAngle.valid(60.5));
  EXPECT_FALSE(option::passes.valid(2.5));
  EXPECT_EQ(option::targetAngle.rangeText(), "(0, 60]");
  EXPECT_EQ(option::alpha.rangeText(), "(0, inf)");
}

// The boundary-layer rows: valid defaults (first-height's 0 means "not given": y+ instead), integer layers,
// and not found by findOption, whose rows the mesh command sets on the improvement options.
TEST(OptionTable, LayerRows)
{
  EXPECT_TRUE(option::layers.valid(option::layers.defaultValue));
  EXPECT_TRUE(option::growth.valid(option::growth.defaultValue));
  EXPECT_FALSE(option::firstHeight.valid(0));
  EXPECT_FALSE(option::layers.valid(2.5));
  EXPECT_FALSE(option::layers.valid(option::layers.maximum + 1));
  EXPECT_FALSE(option::growth.valid(0.99));
  EXPECT_EQ(option::growth.rangeText(), "[1, inf)");
  for (const OptionSpec* spec : option::layerTable)
  {
    EXPECT_EQ(findOption(spec->name), nullptr) << spec->name;
    EXPECT_EQ(findOptionByProperty(spec->property), nullptr) << spec->property;
  }
}
