// make bench, scale section (Testing/Benchmarks/bench_scale.sh): the figures of one tet mesh, whatever
// engine wrote it, as one JSON line:
//   tets, min and max dihedral angle, share of tets with a dihedral angle under 10 degrees;
//   the same for the interior tets (no vertex on the mesh boundary, i.e. on a face held by one tet only:
//   for a one-region domain the input boundary);
//   the size ratio between face-neighbouring tets (size = mean edge length; ratio = larger / smaller),
//   its 99th percentile and maximum over the interior faces (Core/SizeRatio.h, as volgrid mesh --json);
//   checkMesh's maximum non-orthogonality and its count of faces above 70 degrees (Core/CfdQuality.h).
// Reads VTK XML (.vtu) or legacy (.vtk) unstructured grids; cells that are not tets are ignored.
//
// usage: volgrid_bench_mesh_stats MESH.{vtu,vtk}
#include "CfdQuality.h"
#include "Quality.h"
#include "SizeRatio.h"

#include "vtkCellArray.h"
#include "vtkCellTypes.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Summary
{
  int64_t tets = 0, below10 = 0;
  int64_t outside15to165 = 0; // issue 16's interior bound: a dihedral angle under 15 or over 165 degrees
  double minDihedral = 180, maxDihedral = 0;
  void add(const double a[6])
  {
    const double lo = *std::min_element(a, a + 6), hi = *std::max_element(a, a + 6);
    ++tets;
    below10 += lo < 10;
    outside15to165 += lo < 15 || hi > 165;
    minDihedral = std::min(minDihedral, lo);
    maxDihedral = std::max(maxDihedral, hi);
  }
};

// One face of one tet: its sorted vertex ids and the tet.
struct Face
{
  int32_t v[3];
  int32_t tet;
  bool operator<(const Face& o) const
  {
    return v[0] != o.v[0] ? v[0] < o.v[0]
      : v[1] != o.v[1]    ? v[1] < o.v[1]
      : v[2] != o.v[2]    ? v[2] < o.v[2]
                          : tet < o.tet;
  }
  bool sameFace(const Face& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};

vtkSmartPointer<vtkUnstructuredGrid> read(const std::string& path)
{
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".vtu") == 0)
  {
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(path.c_str());
    r->Update();
    return r->GetOutput();
  }
  vtkNew<vtkUnstructuredGridReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  return r->GetOutput();
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: volgrid_bench_mesh_stats MESH.{vtu,vtk}\n");
    return 2;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = read(argv[1]);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "volgrid_bench_mesh_stats: no cells in %s\n", argv[1]);
    return 1;
  }
  const vtkIdType np = grid->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
    grid->GetPoint(i, &xyz[3 * static_cast<size_t>(i)]);
  std::vector<std::array<int32_t, 4>> tets;
  tets.reserve(static_cast<size_t>(grid->GetNumberOfCells()));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    if (grid->GetCellType(c) == VTK_TETRA)
    {
      grid->GetCellPoints(c, ids);
      tets.push_back({ static_cast<int32_t>(ids->GetId(0)), static_cast<int32_t>(ids->GetId(1)),
                       static_cast<int32_t>(ids->GetId(2)), static_cast<int32_t>(ids->GetId(3)) });
    }
  grid = nullptr;
  const int32_t nt = static_cast<int32_t>(tets.size());
  auto P = [&](int32_t v) { return &xyz[3 * static_cast<size_t>(v)]; };

  // Faces, sorted: a face held once is on the boundary; a face held twice links two neighbours.
  std::vector<Face> faces;
  faces.reserve(4 * static_cast<size_t>(nt));
  for (int32_t t = 0; t < nt; ++t)
    for (int i = 0; i < 4; ++i)
    {
      Face f;
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != i)
          f.v[m++] = tets[t][k];
      std::sort(f.v, f.v + 3);
      f.tet = t;
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::vector<uint8_t> onBoundary(static_cast<size_t>(np), 0);
  for (size_t k = 0; k < faces.size();)
  {
    size_t e = k + 1;
    while (e < faces.size() && faces[e].sameFace(faces[k]))
      ++e;
    if (e - k == 1)
      for (int32_t v : faces[k].v)
        onBoundary[v] = 1;
    k = e;
  }
  faces.clear();
  faces.shrink_to_fit();

  Summary all, interior;
  for (int32_t t = 0; t < nt; ++t)
  {
    const auto& q = tets[t];
    double a[6];
    volgrid::quality::tetDihedralAngles(P(q[0]), P(q[1]), P(q[2]), P(q[3]), a);
    all.add(a);
    if (!onBoundary[q[0]] && !onBoundary[q[1]] && !onBoundary[q[2]] && !onBoundary[q[3]])
      interior.add(a);
  }
  // Size ratio between face neighbours (Core/SizeRatio.h) and checkMesh's non-orthogonality (Core/CfdQuality.h).
  std::vector<int32_t> flat;
  flat.reserve(4 * static_cast<size_t>(nt));
  for (const auto& q : tets)
    flat.insert(flat.end(), q.begin(), q.end());
  const volgrid::SizeRatioSummary ratio = volgrid::summarizeSizeRatios(xyz.data(), flat.data(), tets.size());
  const volgrid::quality::CfdSummary cfd = volgrid::quality::cfdMetrics(xyz, flat, nullptr);
  std::printf(
    "{\"tets\": %lld, \"min_dihedral\": %.4f, \"max_dihedral\": %.4f, \"share_below_10\": %.6g, "
    "\"interior_tets\": %lld, \"interior_min_dihedral\": %.4f, \"interior_max_dihedral\": %.4f, "
    "\"interior_share_below_10\": %.6g, \"interior_outside_15_165\": %lld, \"size_ratio_p99\": %.4f, "
    "\"size_ratio_max\": %.4f, "
    "\"max_non_orthogonality\": %.4f, \"severe_non_orthogonal_faces\": %lld}\n",
    static_cast<long long>(all.tets), all.minDihedral, all.maxDihedral, all.tets ? double(all.below10) / all.tets : 0.0,
    static_cast<long long>(interior.tets), interior.minDihedral, interior.maxDihedral,
    interior.tets ? double(interior.below10) / interior.tets : 0.0, static_cast<long long>(interior.outside15to165),
    ratio.p99, ratio.max, cfd.maxNonOrthogonality, static_cast<long long>(cfd.severelyNonOrthogonalFaces));
  return 0;
}
