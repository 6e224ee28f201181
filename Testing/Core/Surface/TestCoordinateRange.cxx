// Coordinates outside the range the mesher handles are refused up front, naming the point.
#include "CoordinateRange.h"

#include <gtest/gtest.h>

namespace
{
volgrid::SurfaceMesh scaledTetrahedron(double s)
{
  volgrid::SurfaceMesh m;
  m.points = { 0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s };
  m.addTriangle(0, 2, 1);
  m.addTriangle(0, 1, 3);
  m.addTriangle(0, 3, 2);
  m.addTriangle(1, 2, 3);
  return m;
}
} // namespace

TEST(CoordinateRange, OrdinaryAndLargeButSafeModelsPass)
{
  for (const double s : { 1.0, 1e-20, 1e20, 1e30 })
    EXPECT_TRUE(volgrid::checkCoordinateRange(scaledTetrahedron(s), "t.off").ok()) << s;
}

TEST(CoordinateRange, HugeCoordinatesNameThePoint)
{
  const volgrid::Status s = volgrid::checkCoordinateRange(scaledTetrahedron(1e300), "t.off");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("t.off: point 1"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("1e+300"), std::string::npos) << s.message;
  EXPECT_FALSE(volgrid::checkCoordinateRange(scaledTetrahedron(1e100), "t.off").ok());
}

TEST(CoordinateRange, TinyModelsAreRefused)
{
  const volgrid::Status s = volgrid::checkCoordinateRange(scaledTetrahedron(1e-40), "t.off");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("across"), std::string::npos) << s.message;
}
