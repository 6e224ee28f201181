// Named patches through the VTK filters: a body inside a generated far field keeps its patch names
// (PatchNames field data on both outputs of VolGrid Tetrahedralize, RegionNames on the tets), and VolGrid
// Quality adds checkMesh's CFD metrics (NonOrthogonality, Skewness, VolumeRatio and their figures).
#include "VolGridSurfaceConversion.h"
#include "vtkVolGridQuality.h"
#include "vtkVolGridTetrahedralize.h"

#include "Enclosures.h"
#include "PatchNames.h"
#include "SurfaceMesh.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

namespace
{
std::vector<std::string> names(vtkDataObject* data, const char* array)
{
  std::vector<std::string> out;
  auto* a = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(array));
  for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
    out.push_back(a->GetValue(i));
  return out;
}
} // namespace

namespace
{
// A unit sphere (patch 0, "wing") inside a sphere of radius 6 (patch 1, "farfield"), as poly data.
vtkSmartPointer<vtkPolyData> bodyInFarField()
{
  volgrid::SurfaceMesh far, body;
  volgrid::EnclosureOptions o;
  o.shape = volgrid::EnclosureShape::Sphere;
  o.dimensions[0] = 6;
  o.targetEdgeLength = 1.0;
  o.patchId = 1; // named "farfield" by the enclosure generator
  EXPECT_TRUE(volgrid::makeEnclosure(o, far).ok());
  o.dimensions[0] = 1;
  o.targetEdgeLength = 0.3;
  o.patchId = 0;
  EXPECT_TRUE(volgrid::makeEnclosure(o, body).ok());
  body.patchNames[0] = "wing";
  far.append(body);
  EXPECT_EQ(far.patchNames, (volgrid::NameTable{ { 0, "wing" }, { 1, "farfield" } }));
  auto input = vtkSmartPointer<vtkPolyData>::New();
  VolGridSurfaceMeshToPolyData(far, input, "PatchId");
  return input;
}
} // namespace

TEST(VolGridPatchNames, NamesReachBothOutputsAndQualityHasCfdMetrics)
{
  vtkSmartPointer<vtkPolyData> input = bodyInFarField();
  EXPECT_EQ(names(input, "PatchNames"), (std::vector<std::string>{ "wing", "farfield" }));

  vtkNew<vtkVolGridTetrahedralize> mesher;
  mesher->SetInputData(input);
  mesher->Update();
  vtkUnstructuredGrid* volume = mesher->GetOutput(0);
  vtkPolyData* boundary = vtkPolyData::SafeDownCast(mesher->GetOutputDataObject(1));
  ASSERT_GT(volume->GetNumberOfCells(), 0);
  ASSERT_NE(boundary, nullptr);
  EXPECT_EQ(names(boundary, "PatchNames"), (std::vector<std::string>{ "wing", "farfield" }));
  EXPECT_EQ(names(volume, "PatchNames"), (std::vector<std::string>{ "wing", "farfield" }));
  EXPECT_EQ(names(volume, "RegionNames"), (std::vector<std::string>{ "region0" }));

  vtkNew<vtkVolGridQuality> quality;
  quality->SetInputData(volume);
  quality->SetMetric(vtkVolGridQuality::NON_ORTHOGONALITY);
  quality->Update();
  vtkDataSet* out = vtkDataSet::SafeDownCast(quality->GetOutputDataObject(0));
  for (const char* a : { "NonOrthogonality", "Skewness", "VolumeRatio" })
    ASSERT_NE(out->GetCellData()->GetArray(a), nullptr) << a;
  vtkDataArray* maxNonOrtho = out->GetFieldData()->GetArray("MaxNonOrthogonality");
  ASSERT_NE(maxNonOrtho, nullptr);
  double range[2];
  out->GetCellData()->GetArray("NonOrthogonality")->GetRange(range);
  EXPECT_DOUBLE_EQ(range[1], maxNonOrtho->GetTuple1(0)); // the cells' maxima reach the face maximum
  EXPECT_GT(range[1], 0.0);
  EXPECT_LT(range[1], 90.0);
  ASSERT_NE(out->GetCellData()->GetArray("Quality"), nullptr); // the selected metric is coloured
  EXPECT_NE(out->GetFieldData()->GetArray("SevereNonOrthogonalFaces"), nullptr);
  EXPECT_NE(out->GetFieldData()->GetArray("HighlySkewFaces"), nullptr);
}

TEST(VolGridPatchNames, PatchAssignmentRenamesAndRegroups)
{
  vtkSmartPointer<vtkPolyData> input = bodyInFarField();
  vtkNew<vtkVolGridTetrahedralize> mesher;
  mesher->SetInputData(input);
  mesher->SetPatchAssignment("outer=1,body=0");
  mesher->Update();
  vtkPolyData* boundary = vtkPolyData::SafeDownCast(mesher->GetOutputDataObject(1));
  ASSERT_NE(boundary, nullptr);
  EXPECT_EQ(names(boundary, "PatchNames"), (std::vector<std::string>{ "patch0", "outer", "body" }));
  double range[2];
  boundary->GetCellData()->GetArray("PatchId")->GetRange(range);
  EXPECT_EQ(range[0], 1.0);
  EXPECT_EQ(range[1], 2.0);
  // An id no triangle carries is an error: no output.
  mesher->SetPatchAssignment("outer=7");
  mesher->Update();
  EXPECT_EQ(mesher->GetOutput(0)->GetNumberOfCells(), 0);
}
