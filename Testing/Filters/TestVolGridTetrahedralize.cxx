// The VTK face of the Delaunay kernel: what a VTK C++ pipeline relies on.
#include "vtkVolGridTetrahedralize.h"

#include "vtkCallbackCommand.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace
{
vtkNew<vtkPolyData> cloud(const std::vector<std::array<double, 3>>& xyz)
{
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> label;
  label->SetName("Label");
  for (size_t i = 0; i < xyz.size(); ++i)
  {
    points->InsertNextPoint(xyz[i].data());
    label->InsertNextValue(static_cast<double>(i));
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(label);
  return data;
}

double tetVolume(vtkUnstructuredGrid* grid, vtkIdType cell)
{
  vtkIdType n;
  const vtkIdType* ids;
  grid->GetCellPoints(cell, n, ids);
  double p[4][3];
  for (int i = 0; i < 4; ++i)
    grid->GetPoint(ids[i], p[i]);
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = p[1][k] - p[0][k];
    v[k] = p[2][k] - p[0][k];
    w[k] = p[3][k] - p[0][k];
  }
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
    6.0;
}

// Collects the error messages an algorithm emits.
struct ErrorCatcher
{
  std::string messages;
  vtkNew<vtkCallbackCommand> callback;
  explicit ErrorCatcher(vtkObject* watched)
  {
    callback->SetClientData(this);
    callback->SetCallback([](vtkObject*, unsigned long, void* self, void* text)
                          { static_cast<ErrorCatcher*>(self)->messages += static_cast<const char*>(text); });
    watched->AddObserver(vtkCommand::ErrorEvent, callback);
    watched->AddObserver(vtkCommand::WarningEvent, callback);
  }
};
} // namespace

TEST(VolGridTetrahedralize, FillsTheConvexHullOfAGridWithPositiveTets)
{
  // A 5x5x5 grid (every cell cospherical) and random interior points: the hull is the unit cube.
  std::vector<std::array<double, 3>> xyz;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        xyz.push_back({ i / 4.0, j / 4.0, k / 4.0 });
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i)
    xyz.push_back({ unit(random), unit(random), unit(random) });
  auto input = cloud(xyz);

  vtkNew<vtkVolGridTetrahedralize> filter;
  filter->SetInputData(input);
  filter->CheckOutputOn();
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(xyz.size()));
  ASSERT_GT(out->GetNumberOfCells(), 0);
  double volume = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    ASSERT_EQ(out->GetCellType(c), VTK_TETRA);
    const double v = tetVolume(out, c);
    ASSERT_GT(v, 0.0) << "cell " << c;
    volume += v;
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  EXPECT_NE(out->GetPointData()->GetArray("Label"), nullptr);
}

TEST(VolGridTetrahedralize, TheMeshDoesNotDependOnTheInsertionOrder)
{
  std::vector<std::array<double, 3>> xyz;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        xyz.push_back({ double(i), double(j), double(k) });
  auto input = cloud(xyz);
  vtkNew<vtkVolGridTetrahedralize> sorted, unsorted;
  sorted->SetInputData(input);
  unsorted->SetInputData(input);
  unsorted->SpatialSortOff();
  sorted->Update();
  unsorted->Update();
  auto canonical = [](vtkUnstructuredGrid* g)
  {
    std::vector<std::array<vtkIdType, 4>> tets;
    for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      g->GetCellPoints(c, n, ids);
      std::array<vtkIdType, 4> t = { ids[0], ids[1], ids[2], ids[3] };
      std::sort(t.begin(), t.end());
      tets.push_back(t);
    }
    std::sort(tets.begin(), tets.end());
    return tets;
  };
  EXPECT_EQ(canonical(sorted->GetOutput()), canonical(unsorted->GetOutput()));
}

TEST(VolGridTetrahedralize, MergesDuplicatesAndMapsThemBack)
{
  std::vector<std::array<double, 3>> xyz = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
                                             { 1, 0, 0 }, { 1, 1, 1 }, { 0, 0, 0 } };
  auto input = cloud(xyz);
  vtkNew<vtkVolGridTetrahedralize> filter;
  ErrorCatcher catcher(filter);
  filter->SetInputData(input);
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 5);
  auto* ids = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("InputPointId"));
  ASSERT_NE(ids, nullptr);
  const vtkIdType expected[5] = { 0, 1, 2, 3, 5 };
  for (int o = 0; o < 5; ++o)
    EXPECT_EQ(ids->GetValue(o), expected[o]);
  EXPECT_NE(catcher.messages.find("2 duplicate point(s)"), std::string::npos) << catcher.messages;
}

TEST(VolGridTetrahedralize, BadInputGivesAnErrorAndNoOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<std::array<double, 3>>> cases = {
    {},                                                                   // empty
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 2, 3, 0 } },  // coplanar
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { nan, 0, 0 } } // NaN
  };
  const char* expectedWords[] = { "empty", "coplanar", "NaN" };
  for (size_t i = 0; i < cases.size(); ++i)
  {
    auto input = cloud(cases[i]);
    vtkNew<vtkVolGridTetrahedralize> filter;
    ErrorCatcher catcher(filter);
    filter->SetInputData(input);
    filter->Update();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0) << "case " << i;
    EXPECT_NE(catcher.messages.find(expectedWords[i]), std::string::npos) << "case " << i << ": " << catcher.messages;
  }
}
