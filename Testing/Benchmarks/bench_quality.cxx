// make bench: vtkVolGridQuality (all metrics, statistics and histograms) against vtkMeshQuality computing
// one metric (tet minimum dihedral angle) on the same ~5M-tet mesh, each with 1 and 2 STDThread threads.
// The mesh: a jittered structured grid of voxels split into tets by vtkDataSetTriangleFilter.
// Prints one JSON line per measurement (best of --repeat runs).
//
// usage: volgrid_bench_quality [--tets N] [--repeat R] [--seed S]
#include "vtkVolGridQuality.h"

#include "vtkCellData.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkImageData.h"
#include "vtkMeshQuality.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> buildMesh(long long targetTets, unsigned seed)
{
  // vtkDataSetTriangleFilter splits each voxel into 5 tets.
  const int n = std::max(2, static_cast<int>(std::lround(std::cbrt(static_cast<double>(targetTets) / 5.0))));
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(image);
  split->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = split->GetOutput();
  // Jitter the points by up to 20% of the spacing: varied shapes, still valid (positive) tets.
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.2 / n, 0.2 / n);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    points->SetPoint(i, p[0] + u(rng), p[1] + u(rng), p[2] + u(rng));
  }
  grid->SetPoints(points);
  return grid;
}

struct Timing
{
  double seconds = std::numeric_limits<double>::infinity(); // best wall-clock time
  double cpuSeconds = 0.0;                                  // process CPU time (all threads) of that run
};

// Best of `repeat` runs; the CPU time tells how much of the machine the run really had (shared machines).
Timing best(int repeat, int threads, const std::function<void()>& run)
{
  Timing t;
  for (int r = 0; r < repeat; ++r)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false },
                            [&]()
                            {
                              const std::clock_t c0 = std::clock();
                              const auto t0 = std::chrono::steady_clock::now();
                              run();
                              const auto t1 = std::chrono::steady_clock::now();
                              const std::clock_t c1 = std::clock();
                              const double wall = std::chrono::duration<double>(t1 - t0).count();
                              if (wall < t.seconds)
                              {
                                t.seconds = wall;
                                t.cpuSeconds = static_cast<double>(c1 - c0) / CLOCKS_PER_SEC;
                              }
                            });
  }
  return t;
}

void report(const char* engine, const char* metrics, int threads, vtkIdType tets, const Timing& t)
{
  std::printf("{\"bench\":\"quality\",\"engine\":\"%s\",\"metrics\":\"%s\",\"threads\":%d,\"tets\":%lld,"
              "\"seconds\":%.4f,\"cpu_seconds\":%.4f,\"mtets_per_s\":%.3f}\n",
              engine, metrics, threads, static_cast<long long>(tets), t.seconds, t.cpuSeconds, tets / t.seconds / 1e6);
  std::fflush(stdout);
}
} // namespace

int main(int argc, char** argv)
{
  long long targetTets = 5000000;
  int repeat = 3;
  unsigned seed = 1;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--tets") && i + 1 < argc)
      targetTets = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
      seed = static_cast<unsigned>(std::atoi(argv[++i]));
    else
    {
      std::fprintf(stderr, "usage: %s [--tets N] [--repeat R] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  if (!vtkSMPTools::SetBackend("STDThread"))
  {
    std::fprintf(stderr, "bench_quality: the STDThread SMP backend is not available\n");
    return 1;
  }
  vtkSmartPointer<vtkUnstructuredGrid> mesh = buildMesh(targetTets, seed);
  const vtkIdType tets = mesh->GetNumberOfCells();

  for (int threads : { 1, 2 })
  {
    vtkNew<vtkVolGridQuality> quality;
    quality->SetInputData(mesh);
    const Timing t = best(repeat, threads,
                          [&]()
                          {
                            quality->Modified();
                            quality->Update();
                          });
    report("vtkVolGridQuality", "all (8 per-tet arrays, statistics, histograms)", threads, tets, t);
  }
  for (int threads : { 1, 2 })
  {
    vtkNew<vtkMeshQuality> meshQuality;
    meshQuality->SetInputData(mesh);
    meshQuality->SetTetQualityMeasureToMinAngle();
    const Timing t = best(repeat, threads,
                          [&]()
                          {
                            meshQuality->Modified();
                            meshQuality->Update();
                          });
    report("vtkMeshQuality", "tet min dihedral angle", threads, tets, t);
  }
  return 0;
}
