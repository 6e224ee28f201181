// One default per option for meshing and refinement (refine used to run with beta 0.55 from
// FieldPointOptions while meshing used 0.4), and the CLI/filter setter reaching the right member.
#include "OptionValues.h"

#include <gtest/gtest.h>

using namespace volgrid;

TEST(OptionValues, MeshingAndRefinementShareTheTableDefaults)
{
  const ImprovementOptions meshing;
  const RefineOptions refining;
  EXPECT_EQ(meshing.fieldPointOptions.alpha, option::alpha.defaultValue);
  EXPECT_EQ(meshing.fieldPointOptions.beta, option::beta.defaultValue);
  EXPECT_EQ(refining.fieldPointOptions.alpha, option::alpha.defaultValue);
  EXPECT_EQ(refining.fieldPointOptions.beta, option::beta.defaultValue);
  EXPECT_EQ(meshing.sizing.gradation, option::gradation.defaultValue);
  EXPECT_EQ(meshing.sizing.scale, option::sizeScale.defaultValue);
  EXPECT_EQ(meshing.optimization.targetDegrees, option::targetAngle.defaultValue);
  EXPECT_EQ(refining.optimization.targetDegrees, option::targetAngle.defaultValue);
  EXPECT_EQ(meshing.optimization.maxPasses, static_cast<int>(option::passes.defaultValue));
}

TEST(OptionValues, EveryTableOptionHasAMeshingMember)
{
  for (const OptionSpec* spec : option::table)
  {
    ImprovementOptions o;
    EXPECT_TRUE(setOption(o, *spec, 7)) << spec->name;
  }
  ImprovementOptions o;
  setOption(o, option::beta, 0.3);
  setOption(o, option::maxEdge, 2.5);
  EXPECT_EQ(o.fieldPointOptions.beta, 0.3);
  EXPECT_EQ(o.sizing.maxEdgeLength, 2.5);
  RefineOptions r;
  EXPECT_FALSE(setOption(r, option::gradation, 2));
  EXPECT_FALSE(refinementOption(option::gradation));
  EXPECT_TRUE(setOption(r, option::beta, 0.3));
  EXPECT_EQ(r.fieldPointOptions.beta, 0.3);
}
