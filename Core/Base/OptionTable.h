// Every numeric option of the mesher, written once: its name on the command line (--NAME), its property
// in the VTK filter and the ParaView panel, its type, default, valid range and a one-line doc. The
// options structs take their defaults from here, Core's option checks and the CLI's parsing and usage
// take the valid ranges, the filter clamps to them, and the build writes Plugin/VolGridTetrahedralize.xml
// from Plugin/VolGridTetrahedralize.xml.in with fillOptionPlaceholders (Plugin/GenerateOptionXml.cxx), so
// the ParaView panel's defaults and slider ranges are this table's too (checked by TestOptionTable).
// Changing a default or a range is a one-line change of one row below.
#pragma once

#include "Status.h"

#include <limits>
#include <string>

namespace volgrid
{

enum class OptionType
{
  Real,
  Integer
};

struct OptionSpec
{
  const char* name;     // the CLI flag without "--"
  const char* property; // the filter's and the Plugin XML's property
  OptionType type;
  double defaultValue;
  double minimum, maximum;     // valid range; infinity = unbounded
  bool minimumIncluded;        // [minimum or (minimum
  bool maximumIncluded;        // maximum] or maximum)
  double sliderMin, sliderMax; // the GUI's slider (Plugin XML range domain); infinity = no max attribute
  const char* doc;

  constexpr bool valid(double x) const
  {
    return (minimumIncluded ? x >= minimum : x > minimum) && (maximumIncluded ? x <= maximum : x < maximum) &&
      (type == OptionType::Real || x == static_cast<double>(static_cast<long long>(x)));
  }
  // The closed range the filter clamps to (an open end is clamped to the end itself; Core then refuses it).
  constexpr double clamp(double x) const { return x < minimum ? minimum : x > maximum ? maximum : x; }
  // "(0, inf)", "[1, 60]": for messages and usage text.
  std::string rangeText() const;
};

namespace option
{
constexpr double kInf = std::numeric_limits<double>::infinity();
// clang-format off
//                                 name            property             type                defaults min  max   [min   max]   slider      doc
inline constexpr OptionSpec alpha{ "alpha",       "Alpha",             OptionType::Real,    0.75, 0,   kInf, false, false, 0.3, 2,    "field points, eq. 4: a tet gets a point when its centroid is farther than alpha*h from its vertices (smaller = more points)" };
inline constexpr OptionSpec beta{ "beta",         "Beta",              OptionType::Real,    0.4,  0,   kInf, true,  false, 0,   1,    "field points, eq. 5: no two points closer than beta*h (0: no minimum spacing)" };
inline constexpr OptionSpec sizeScale{ "size-scale", "SizeScale",      OptionType::Real,    1,    0,   kInf, false, false, 0.25, 10,  "h at the boundary = size-scale x the boundary's point spacing" };
inline constexpr OptionSpec gradation{ "gradation", "Gradation",       OptionType::Real,    1.5,  1,   kInf, true,  false, 1,   3,    "size growth between neighbours, h(v) <= h(u) + (gradation-1)|uv| (smaller = finer)" };
inline constexpr OptionSpec maxEdge{ "max-edge",  "MaxEdgeLength",     OptionType::Real,    0,    0,   kInf, true,  false, 0,   kInf, "cap on the target edge length; next to boundary triangles coarser than the cap the size grades down from theirs (0: no cap)" };
inline constexpr OptionSpec maxVolume{ "max-volume", "MaxVolume",      OptionType::Real,    0,    0,   kInf, true,  false, 0,   kInf, "cap on tet volume (0: no cap)" };
inline constexpr OptionSpec targetAngle{ "target-angle", "TargetMinDihedral", OptionType::Real, 18, 0, 60,  false, true,  1,   60,   "optimisation target for min(dihedral, 180 - max dihedral), degrees" };
inline constexpr OptionSpec passes{ "passes",     "MaxPasses",         OptionType::Integer, 8,    0,   1000, true,  true,  0,   50,   "optimisation pass limit (0: no optimisation passes)" };
inline constexpr OptionSpec layers{ "layers",     "NumberOfLayers",    OptionType::Integer, 0,    0,   100,  true,  true,  0,   20,   "number of prism layers on the wall patches (0: none)" };
inline constexpr OptionSpec firstHeight{ "first-height", "FirstLayerHeight", OptionType::Real, 0, 0,  kInf, false, false, 0,   kInf, "height of the layer on the wall (0: not given, --y-plus instead)" };
inline constexpr OptionSpec growth{ "growth",     "LayerGrowthRatio",  OptionType::Real,    1.2,  1,   kInf, true,  false, 1,   2,    "ratio between consecutive layer heights" };
inline constexpr OptionSpec layerThickness{ "layer-thickness", "TotalLayerThickness", OptionType::Real, 0, 0, kInf, true, false, 0, kInf, "total thickness of the layers (0: not given); with a first height the growth ratio is solved for, else the first height" };
// clang-format on
inline constexpr const OptionSpec* table[] = { &alpha,   &beta,      &sizeScale,   &gradation,
                                               &maxEdge, &maxVolume, &targetAngle, &passes };
// The boundary-layer rows (LayerOptions' defaults, the CLI's --layers parsing, the filter's "Boundary
// layers" properties and their Plugin XML placeholders). Apart from `table`, whose rows the mesh and
// refine commands set on the improvement options (findOption).
inline constexpr const OptionSpec* layerTable[] = { &layers, &firstHeight, &growth, &layerThickness };
} // namespace option

// The row whose CLI name (flag without "--") is `name`, or nullptr.
const OptionSpec* findOption(const std::string& name);
// The row whose filter / Plugin XML property is `property`, or nullptr.
const OptionSpec* findOptionByProperty(const std::string& property);

// `text` with every @VOLGRID_OPTION_<property>_DEFAULT@ replaced by that row's default and every
// @VOLGRID_OPTION_<property>_RANGE@ by its slider range as XML attributes (min="0.3" max="2"; no max when
// the slider has none). Fails on an unknown or unterminated placeholder and on a row left unused, so a
// template cannot silently keep a number of its own.
Status fillOptionPlaceholders(const std::string& text, std::string& filled);

} // namespace volgrid
