// VolGrid Tetrahedralize's Density, Clustering and sizing, and Quality properties: what a VTK pipeline
// relies on (defaults give a good mesh, alpha controls the density, the Sources input clusters and sizes,
// the boundary output is the input, the numeric options are clamped).
#include "vtkVolGridTetrahedralize.h"

#include "VolGridSurfaceConversion.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include "CfdQuality.h"
#include "Enclosures.h"
#include "MeshChecker.h"
#include "MeshImprovement.h"
#include "OptionTable.h"
#include "SurfaceMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace
{
// The far field's and the body's triangles as one vtkPolyData.
vtkNew<vtkPolyData> joined(volgrid::SurfaceMesh far, const volgrid::SurfaceMesh& body)
{
  const int32_t off = far.numberOfPoints();
  far.points.insert(far.points.end(), body.points.begin(), body.points.end());
  for (int32_t v : body.triangles)
    far.triangles.push_back(v + off);
  far.patchIds.clear();
  vtkNew<vtkPolyData> poly;
  VolGridSurfaceMeshToPolyData(far, poly);
  return poly;
}

// Body sphere (r = 1) inside a far-field sphere (r = 6), as one vtkPolyData.
vtkNew<vtkPolyData> sphereInSphere(double bodyEdge)
{
  volgrid::SurfaceMesh far, body;
  volgrid::EnclosureOptions o;
  o.shape = volgrid::EnclosureShape::Sphere;
  o.dimensions[0] = 6;
  o.targetEdgeLength = 1.0;
  EXPECT_TRUE(volgrid::makeEnclosure(o, far).ok());
  o.dimensions[0] = 1;
  o.targetEdgeLength = bodyEdge;
  EXPECT_TRUE(volgrid::makeEnclosure(o, body).ok());
  return joined(far, body);
}

// A thin plate (6 x 4 x 0.04, whose edges force bad tets) inside a far-field sphere (r = 10).
vtkNew<vtkPolyData> plateInSphere()
{
  volgrid::SurfaceMesh far, plate;
  volgrid::EnclosureOptions o;
  o.dimensions[0] = 10;
  o.targetEdgeLength = 2.0;
  EXPECT_TRUE(volgrid::makeEnclosure(o, far).ok());
  o.shape = volgrid::EnclosureShape::Box;
  o.dimensions[0] = 6;
  o.dimensions[1] = 4;
  o.dimensions[2] = 0.04;
  o.targetEdgeLength = 0.5;
  EXPECT_TRUE(volgrid::makeEnclosure(o, plate).ok());
  return joined(far, plate);
}

struct Summary
{
  vtkIdType tets = 0, points = 0, boundaryTriangles = 0;
  volgrid::DihedralSummary dihedral;
  int64_t severeFaces = 0; // checkMesh's severely non-orthogonal faces (CfdQuality.h)
  bool valid = false;
};

Summary summarize(vtkVolGridTetrahedralize* f)
{
  Summary s;
  vtkUnstructuredGrid* grid = f->GetOutput(0);
  s.tets = grid->GetNumberOfCells();
  s.points = grid->GetNumberOfPoints();
  s.boundaryTriangles = vtkPolyData::SafeDownCast(f->GetOutputDataObject(1))->GetNumberOfPolys();
  std::vector<double> xyz(3 * static_cast<size_t>(s.points));
  for (vtkIdType i = 0; i < s.points; ++i)
    grid->GetPoint(i, xyz.data() + 3 * i);
  std::vector<int32_t> tets;
  for (vtkIdType c = 0; c < s.tets; ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, n, ids);
    for (int k = 0; k < 4; ++k)
      tets.push_back(static_cast<int32_t>(ids[k]));
  }
  volgrid::TetMesh m;
  if (s.tets > 0 && volgrid::tetMeshFromTets(xyz, tets, m).ok())
  {
    // Orientation and adjacency (optimised meshes are not Delaunay; the domain has a hole, so no ball's
    // Euler characteristic).
    volgrid::MeshCheckOptions co;
    co.delaunay = false;
    co.euler = false;
    const volgrid::MeshCheckReport r = volgrid::checkMesh(m, co);
    s.valid = r.badVertices + r.invertedTets + r.badNeighbors + r.asymmetricNeighbors + r.faceMismatches == 0;
    s.dihedral = volgrid::summarizeDihedrals(m);
    s.severeFaces = volgrid::quality::cfdMetrics(xyz, tets, nullptr).severelyNonOrthogonalFaces;
  }
  return s;
}

vtkNew<vtkPolyData> sourcePoints(const std::vector<double>& xyz, const std::vector<double>& sizes)
{
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> size;
  size->SetName("TargetSize");
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    points->InsertNextPoint(&xyz[3 * i]);
    size->InsertNextValue(sizes[i]);
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(size);
  return data;
}
} // namespace

TEST(VolGridTetrahedralizeQuality, DefaultsGiveGoodTetsAndTheExactBoundary)
{
  vtkNew<vtkPolyData> input = sphereInSphere(0.15);
  vtkNew<vtkVolGridTetrahedralize> f;
  EXPECT_TRUE(f->GetFieldPoints());
  EXPECT_TRUE(f->GetOptimize());
  EXPECT_DOUBLE_EQ(f->GetAlpha(), volgrid::ImprovementOptions().fieldPointOptions.alpha);
  EXPECT_DOUBLE_EQ(f->GetTargetMinDihedral(), volgrid::option::targetAngle.defaultValue);
  f->SetInputData(input);
  f->CheckOutputOn(); // the mesher verifies boundary == input and the volume exactly
  f->Update();
  const Summary s = summarize(f);
  ASSERT_GT(s.tets, 0);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.boundaryTriangles, input->GetNumberOfPolys());
  EXPECT_GE(s.dihedral.minDihedral, 15.0);
  EXPECT_LE(s.dihedral.maxDihedral, 165.0);
  // Input point i is output point i.
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); i += 97)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    f->GetOutput(0)->GetPoint(i, b);
    EXPECT_EQ(a[0], b[0]);
    EXPECT_EQ(a[1], b[1]);
    EXPECT_EQ(a[2], b[2]);
  }
}

TEST(VolGridTetrahedralizeQuality, AlphaAndFieldPointsControlTheDensity)
{
  vtkNew<vtkPolyData> input = sphereInSphere(0.2);
  vtkIdType previous = 0;
  for (double alpha : { 1.2, 0.75, 0.5 })
  {
    vtkNew<vtkVolGridTetrahedralize> f;
    f->SetInputData(input);
    f->SetAlpha(alpha);
    f->Update();
    const Summary s = summarize(f);
    EXPECT_GT(s.tets, previous) << "alpha " << alpha;
    EXPECT_TRUE(s.valid);
    previous = s.tets;
  }
  vtkNew<vtkVolGridTetrahedralize> off;
  off->SetInputData(input);
  off->FieldPointsOff();
  off->OptimizeOff();
  off->Update();
  EXPECT_LT(summarize(off).tets, previous);
  vtkNew<vtkVolGridTetrahedralize> capped;
  capped->SetInputData(input);
  capped->SetMaxEdgeLength(0.5);
  capped->Update();
  EXPECT_GT(summarize(capped).points, summarize(off).points * 2);
}

TEST(VolGridTetrahedralizeQuality, SourcesClusterAndSize)
{
  vtkNew<vtkPolyData> input = sphereInSphere(0.2);
  vtkNew<vtkVolGridTetrahedralize> plain;
  plain->SetInputData(input);
  plain->Update();
  const Summary base = summarize(plain);

  // Cluster: three points between the spheres (one outside the domain, inside the body), size 0.05.
  const std::vector<double> xyz = { 2.0, 0.0, 0.0, 0.0, -2.5, 0.5, 0.0, 0.0, 0.0 };
  vtkNew<vtkPolyData> sources = sourcePoints(xyz, { 0.05, 0.05, 0.05 });
  vtkNew<vtkVolGridTetrahedralize> cluster;
  cluster->SetInputData(0, input);
  cluster->SetInputData(1, sources);
  cluster->SetSourceSizeArray("TargetSize");
  cluster->Update();
  const Summary c = summarize(cluster);
  EXPECT_TRUE(c.valid);
  EXPECT_GT(c.tets, base.tets + 500);
  vtkUnstructuredGrid* grid = cluster->GetOutput(0);
  for (int k = 0; k < 2; ++k)
  {
    bool found = false;
    for (vtkIdType i = input->GetNumberOfPoints(); i < grid->GetNumberOfPoints() && !found; ++i)
    {
      double p[3];
      grid->GetPoint(i, p);
      found = p[0] == xyz[3 * k] && p[1] == xyz[3 * k + 1] && p[2] == xyz[3 * k + 2];
    }
    EXPECT_TRUE(found) << "cluster point " << k;
  }

  // Sizing: a cloud asking for 0.5 everywhere -> many more points than the boundary spacing alone.
  std::vector<double> cloud, sizes;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k)
      {
        cloud.insert(cloud.end(), { 2.0 * i, 2.0 * j, 2.0 * k });
        sizes.push_back(0.5);
      }
  vtkNew<vtkPolyData> background = sourcePoints(cloud, sizes);
  vtkNew<vtkVolGridTetrahedralize> sized;
  sized->SetInputData(0, input);
  sized->SetInputData(1, background);
  sized->SetSourceSizeArray("TargetSize");
  sized->ClusterSourcePointsOff();
  sized->SizingFromSourcesOn();
  sized->Update();
  const Summary z = summarize(sized);
  EXPECT_TRUE(z.valid);
  EXPECT_GT(z.points, 3 * base.points);

  // A missing array is an error with an empty output.
  vtkNew<vtkVolGridTetrahedralize> bad;
  bad->SetInputData(0, input);
  bad->SetInputData(1, background);
  bad->SetSourceSizeArray("NoSuchArray");
  bad->Update();
  EXPECT_EQ(bad->GetOutput(0)->GetNumberOfCells(), 0);
}

TEST(VolGridTetrahedralizeQuality, NumericOptionsAreClampedToTheOptionTable)
{
  // Every numeric property is clamped to its valid range in Core's OptionTable.h (an open end to the end
  // itself, which Core then refuses), and a valid value is kept.
  vtkNew<vtkVolGridTetrahedralize> f;
  struct Property
  {
    const volgrid::OptionSpec& spec;
    std::function<void(double)> set;
    std::function<double()> get;
  };
  vtkVolGridTetrahedralize* p = f;
  const Property properties[] = {
    { volgrid::option::alpha, [p](double x) { p->SetAlpha(x); }, [p] { return p->GetAlpha(); } },
    { volgrid::option::beta, [p](double x) { p->SetBeta(x); }, [p] { return p->GetBeta(); } },
    { volgrid::option::gradation, [p](double x) { p->SetGradation(x); }, [p] { return p->GetGradation(); } },
    { volgrid::option::sizeScale, [p](double x) { p->SetSizeScale(x); }, [p] { return p->GetSizeScale(); } },
    { volgrid::option::maxEdge, [p](double x) { p->SetMaxEdgeLength(x); }, [p] { return p->GetMaxEdgeLength(); } },
    { volgrid::option::maxVolume, [p](double x) { p->SetMaxVolume(x); }, [p] { return p->GetMaxVolume(); } },
    { volgrid::option::targetAngle, [p](double x) { p->SetTargetMinDihedral(x); },
      [p] { return p->GetTargetMinDihedral(); } },
    { volgrid::option::passes, [p](double x) { p->SetMaxPasses(static_cast<int>(x)); },
      [p] { return static_cast<double>(p->GetMaxPasses()); } },
    { volgrid::option::layers, [p](double x) { p->SetNumberOfLayers(static_cast<int>(x)); },
      [p] { return static_cast<double>(p->GetNumberOfLayers()); } },
    { volgrid::option::firstHeight, [p](double x) { p->SetFirstLayerHeight(x); },
      [p] { return p->GetFirstLayerHeight(); } },
    { volgrid::option::growth, [p](double x) { p->SetLayerGrowthRatio(x); }, [p] { return p->GetLayerGrowthRatio(); } },
  };
  for (const Property& property : properties)
  {
    const volgrid::OptionSpec& spec = property.spec;
    EXPECT_EQ(property.get(), spec.defaultValue) << spec.property;
    property.set(spec.minimum - 3);
    EXPECT_EQ(property.get(), spec.minimum) << spec.property;
    if (std::isfinite(spec.maximum))
    {
      property.set(spec.maximum + 30);
      EXPECT_EQ(property.get(), spec.maximum) << spec.property;
    }
    property.set(spec.sliderMin + 1);
    EXPECT_EQ(property.get(), spec.sliderMin + 1) << spec.property;
  }
}

TEST(VolGridTetrahedralizeQuality, OptimisationRaisesTheMinimumAngle)
{
  vtkNew<vtkPolyData> input = sphereInSphere(0.2);
  vtkNew<vtkVolGridTetrahedralize> raw;
  raw->SetInputData(input);
  raw->OptimizeOff();
  raw->Update();
  vtkNew<vtkVolGridTetrahedralize> opt;
  opt->SetInputData(input);
  opt->Update();
  const Summary a = summarize(raw), b = summarize(opt);
  EXPECT_TRUE(a.valid && b.valid);
  EXPECT_EQ(a.points, b.points); // optimisation adds no point
  EXPECT_GT(b.dihedral.minDihedral, a.dihedral.minDihedral);
  EXPECT_EQ(a.boundaryTriangles, b.boundaryTriangles);
}

// OrthogonalityFirst (off by default) reaches Core: on a plate whose edges force bad tets, the mesh has fewer
// faces a finite-volume solver finds severely non-orthogonal, with the boundary kept exactly.
TEST(VolGridTetrahedralizeQuality, OrthogonalityFirstGivesFewerSevereFaces)
{
  vtkNew<vtkPolyData> input = plateInSphere();
  vtkNew<vtkVolGridTetrahedralize> plain;
  EXPECT_FALSE(plain->GetOrthogonalityFirst());
  plain->SetInputData(input);
  plain->CheckOutputOn();
  plain->Update();
  vtkNew<vtkVolGridTetrahedralize> orthogonal;
  orthogonal->SetInputData(input);
  orthogonal->CheckOutputOn();
  orthogonal->OrthogonalityFirstOn();
  orthogonal->Update();
  const Summary a = summarize(plain), b = summarize(orthogonal);
  EXPECT_TRUE(a.valid && b.valid);
  EXPECT_EQ(a.boundaryTriangles, input->GetNumberOfPolys());
  EXPECT_EQ(b.boundaryTriangles, input->GetNumberOfPolys());
  std::printf("severe faces: %lld default, %lld orthogonality first\n", static_cast<long long>(a.severeFaces),
              static_cast<long long>(b.severeFaces));
  EXPECT_GT(a.severeFaces, 0);
  EXPECT_LT(b.severeFaces, a.severeFaces);
}
