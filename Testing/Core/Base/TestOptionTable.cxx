// The option table (OptionTable.h) against the ParaView panel (Plugin/VolGridTetrahedralize.xml): every
// option's default and slider range must be the table's, so that a default or a range changes in one
// place. The second test shows the check catches an XML that disagrees.
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

std::string readPluginXml()
{
  std::ifstream in(std::string(VOLGRID_TEST_DATA_DIR) + "/../../Plugin/VolGridTetrahedralize.xml");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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
  for (const OptionSpec* spec : option::table)
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

} // namespace

TEST(OptionTable, PluginXmlAgreesWithTheTable)
{
  const std::string xml = readPluginXml();
  ASSERT_FALSE(xml.empty());
  EXPECT_EQ(allDisagreements(xml), std::vector<std::string>());
}

TEST(OptionTable, ADisagreeingPluginXmlIsCaught)
{
  const std::string xml = readPluginXml();
  const std::string defaultChanged =
    replaced(xml, "name=\"Beta\" command=\"SetBeta\" number_of_elements=\"1\" default_values=\"0.4\"",
             "name=\"Beta\" command=\"SetBeta\" number_of_elements=\"1\" default_values=\"0.55\"");
  ASSERT_EQ(allDisagreements(defaultChanged).size(), 1u);
  EXPECT_EQ(allDisagreements(defaultChanged)[0], "Beta: default 0.55 in the XML, 0.4 in the table");
  const std::string rangeChanged = replaced(xml, "<DoubleRangeDomain name=\"range\" min=\"1\" max=\"60\"/>",
                                            "<DoubleRangeDomain name=\"range\" min=\"1\" max=\"90\"/>");
  ASSERT_EQ(allDisagreements(rangeChanged).size(), 1u);
  EXPECT_EQ(allDisagreements(rangeChanged)[0], "TargetMinDihedral: max '90' in the XML, 60 in the table");
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
