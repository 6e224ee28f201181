// volgrid quality MESH [--json] [--bins N] [--metric NAME] [--threads N]
// Runs vtkVolGridQuality on a volume grid (.vtu, .vtk) or a surface (.vtp, .vtk, or any surface file that
// `volgrid mesh` reads, through the same Core readers) and
// prints a summary table, or with --json one JSON line. Errors go to stderr with a non-zero exit code:
// 2 for bad arguments, 1 for unreadable input.
#include "Commands.h"
#include "FlagParser.h"
#include "MeshReader.h"
#include "SurfaceFile.h"
#include "VolGridConversion.h"
#include "XmlDataFiles.h"

#include "VolGridSurfaceConversion.h"

#include "vtkVolGridQuality.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetReader.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace
{
const char* kUsage =
  "usage: volgrid quality MESH.{vtu,vtk,vtp} | SURFACE [--json] [--bins N] [--metric NAME] [--threads N]\n"
  "  SURFACE: any file `volgrid mesh` reads (.stl .obj .ply .off .mesh .poly .smesh .msh, also .gz)\n"
  "  --bins N      histogram bins per metric (1..10000, default 20)\n"
  "  --metric NAME metric copied to the Quality array (AspectRatio, MinDihedralAngle, ...)\n"
  "  --threads N   threads (default 0: all cores)\n";

// A legacy .vtk data set (VTK's reader, after checking that the path is a regular file).
vtkSmartPointer<vtkDataSet> readLegacy(const std::string& path)
{
  struct stat st
  {
  };
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
  {
    std::fprintf(stderr, "volgrid quality: '%s' is not a readable file\n", path.c_str());
    return nullptr;
  }
  vtkNew<vtkDataSetReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  return vtkDataSet::SafeDownCast(r->GetOutput());
}

// A surface through the hardened Core readers that `volgrid mesh` uses (strict numbers, bounded counts,
// bounded gzip), as poly data with its PatchId.
vtkSmartPointer<vtkDataSet> readSurfaceFile(const std::string& path)
{
  volgrid::SurfaceMesh surface;
  std::string info;
  const volgrid::Status status = volgrid::readAnySurface(path, surface, info, true);
  if (!status.ok())
  {
    std::fprintf(stderr, "volgrid quality: %s\n", status.message.c_str());
    return nullptr;
  }
  vtkNew<vtkPolyData> poly;
  VolGridSurfaceMeshToPolyData(surface, poly, "PatchId");
  return poly.Get();
}

// Reads the file into a vtkUnstructuredGrid or vtkPolyData; nullptr (with a message) on failure.
vtkSmartPointer<vtkDataSet> readMesh(const std::string& path)
{
  const std::string ext = volgrid::surfaceFileExtension(path);
  vtkSmartPointer<vtkDataSet> data;
  if (volgrid::solverMeshReaderSupports(path)) // a solver's tet mesh (.mesh): Core's reader
  {
    volgrid::SolverMesh solverMesh;
    const volgrid::Status s = volgrid::readSolverMesh(path, solverMesh);
    if (!s.ok())
    {
      std::fprintf(stderr, "volgrid quality: %s\n", s.message.c_str());
      return nullptr;
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    VolGridFillFromSolverMesh(solverMesh, grid, nullptr);
    return grid;
  }
  if (volgrid::cli::isXmlDataExtension(ext))
  {
    std::string error;
    data = volgrid::cli::readXmlDataSet(path, error);
    if (!data)
    {
      std::fprintf(stderr, "volgrid quality: %s\n", error.c_str());
      return nullptr;
    }
  }
  else if (ext == "vtk")
    data = readLegacy(path);
  else if (volgrid::surfaceFileSupported(path))
    data = readSurfaceFile(path);
  else
  {
    std::fprintf(stderr,
                 "volgrid quality: '%s': unknown file type '.%s' (expected .vtu, .vtk, .vtp or a surface: "
                 ".stl .obj .ply .off .mesh .poly .smesh .msh, each also as .gz)\n",
                 path.c_str(), ext.c_str());
    return nullptr;
  }
  if (!data)
    return nullptr;
  if (!vtkUnstructuredGrid::SafeDownCast(data) && !vtkPolyData::SafeDownCast(data))
  {
    std::fprintf(stderr, "volgrid quality: '%s' is neither an unstructured grid nor a surface\n", path.c_str());
    return nullptr;
  }
  if (data->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "volgrid quality: '%s' has no cells (unreadable or empty)\n", path.c_str());
    return nullptr;
  }
  return data;
}

double scalar(vtkFieldData* fd, const char* name)
{
  vtkDataArray* a = fd->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetComponent(0, 0) : std::nan("");
}

// JSON number: null for NaN/infinity, integers without exponent when exact.
std::string num(double v)
{
  if (!std::isfinite(v))
    return "null";
  char buf[40];
  if (v == std::floor(v) && std::fabs(v) < 9.0e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    }
    else
      out += c;
  }
  return out + "\"";
}

const char* kVolumeMetrics[] = { "AspectRatio",        "MinDihedralAngle", "MaxDihedralAngle",
                                 "MinSolidAngle",      "Volume",           "VolumeGradient",
                                 "RadiusEdgeRatio",    "RadiusRatio",      "NonOrthogonality",
                                 "Skewness",           "VolumeRatio",      "WedgeVolume",
                                 "WedgeScaledJacobian" };
const char* kSurfaceMetrics[] = { "AspectRatio", "Area", "MinAngle", "MaxAngle" };
const char* kVolumeFigures[] = {
  "NumberOfTetrahedra",       "SkippedCells",     "TotalVolume",     "MaxNonOrthogonality", "AverageNonOrthogonality",
  "SevereNonOrthogonalFaces", "MaxSkewness",      "HighlySkewFaces", "MaxVolumeRatio",      "NumberOfWedges",
  "InvertedWedges",           "NumberOfPyramids", "PyramidVolume"
};
const char* kSurfaceFigures[] = { "NumberOfElements", "SurfaceArea",      "EnclosedVolume", "BoundaryEdges",
                                  "BoundaryLoops",    "NonManifoldEdges", "Shells",         "SkippedCells" };
} // namespace

int runQualityCommand(int argc, char** argv)
{
  bool json = false;
  long long bins = 20, threads = 0;
  int metric = vtkVolGridQuality::MIN_DIHEDRAL_ANGLE;
  std::string metricName;
  volgrid::cli::FlagParser p("quality", kUsage);
  p.add("--json", json, true);
  p.add("--bins", bins).accept = [&p, &bins](const char*)
  { return (bins >= 1 && bins <= 10000) || p.fail("--bins needs an integer in 1..10000", true); };
  p.add("--threads", threads).accept = [&p, &threads](const char*)
  { return (threads >= 0 && threads <= 10000) || p.fail("--threads needs an integer >= 0", true); };
  p.add("--metric", metricName).accept = [&p, &metric](const char* v)
  {
    metric = -1;
    for (int m = vtkVolGridQuality::ASPECT_RATIO; m <= vtkVolGridQuality::WEDGE_SCALED_JACOBIAN; ++m)
      if (std::strcmp(v, vtkVolGridQuality::GetMetricName(m)) == 0)
        metric = m;
    return metric >= 0 || p.fail(std::string("unknown metric '") + v + "'", true);
  };
  std::string path;
  if (const int code = p.scan(argc, argv, path, "no input file", "more than one input file"); code >= 0)
    return code;
  vtkSmartPointer<vtkDataSet> mesh = readMesh(path);
  if (!mesh)
    return 1;

  vtkNew<vtkVolGridQuality> quality;
  quality->SetInputData(mesh);
  quality->SetBinCount(static_cast<int>(bins));
  quality->SetMetric(metric);
  if (threads > 0)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ static_cast<int>(threads), "STDThread", false },
                            [&]() { quality->Update(); });
  }
  else
  {
    quality->Update();
  }
  auto* out = vtkDataSet::SafeDownCast(quality->GetOutputDataObject(0));
  auto* table = vtkTable::SafeDownCast(quality->GetOutputDataObject(1));
  if (!out || !table || table->GetNumberOfColumns() == 0)
  {
    std::fprintf(stderr, "volgrid quality: the analysis of '%s' failed\n", path.c_str());
    return 1;
  }
  const bool volume = vtkUnstructuredGrid::SafeDownCast(mesh) != nullptr;
  vtkFieldData* fd = out->GetFieldData();
  std::vector<const char*> metrics = volume
    ? std::vector<const char*>(std::begin(kVolumeMetrics), std::end(kVolumeMetrics))
    : std::vector<const char*>(std::begin(kSurfaceMetrics), std::end(kSurfaceMetrics));
  std::vector<const char*> figures = volume
    ? std::vector<const char*>(std::begin(kVolumeFigures), std::end(kVolumeFigures))
    : std::vector<const char*>(std::begin(kSurfaceFigures), std::end(kSurfaceFigures));

  if (json)
  {
    std::string s = "{\"file\":" + jsonString(path) + ",\"kind\":\"" + (volume ? "volume" : "surface") +
      "\",\"cells\":" + num(static_cast<double>(mesh->GetNumberOfCells()));
    for (const char* f : figures)
      s += std::string(",\"") + f + "\":" + num(scalar(fd, f));
    s += ",\"metrics\":{";
    for (size_t m = 0; m < metrics.size(); ++m)
    {
      vtkDataArray* st = fd->GetArray((std::string(metrics[m]) + "Statistics").c_str());
      s += std::string(m ? "," : "") + "\"" + metrics[m] + "\":{";
      const char* keys[6] = { "count", "min", "max", "mean", "stddev", "worst_cell" };
      for (int c = 0; c < 6; ++c)
        s += std::string(c ? "," : "") + "\"" + keys[c] + "\":" + num(st ? st->GetComponent(0, c) : std::nan(""));
      vtkDataArray* lo =
        vtkDataArray::SafeDownCast(table->GetColumnByName((std::string(metrics[m]) + "_BinStart").c_str()));
      vtkDataArray* hi =
        vtkDataArray::SafeDownCast(table->GetColumnByName((std::string(metrics[m]) + "_BinEnd").c_str()));
      vtkDataArray* count =
        vtkDataArray::SafeDownCast(table->GetColumnByName((std::string(metrics[m]) + "_Count").c_str()));
      std::string edges, counts;
      for (vtkIdType b = 0; lo && hi && count && b < count->GetNumberOfTuples(); ++b)
      {
        edges += (b ? "," : "") + num(lo->GetTuple1(b));
        counts += (b ? "," : "") + num(count->GetTuple1(b));
        if (b + 1 == count->GetNumberOfTuples())
          edges += "," + num(hi->GetTuple1(b));
      }
      s += ",\"bin_edges\":[" + edges + "],\"bin_counts\":[" + counts + "]}";
    }
    s += "}}";
    std::printf("%s\n", s.c_str());
    return 0;
  }

  std::printf("VolGrid quality of %s (%s grid, %lld cells)\n", path.c_str(), volume ? "volume" : "surface",
              static_cast<long long>(mesh->GetNumberOfCells()));
  for (const char* f : figures)
    std::printf("  %-20s %.10g\n", f, scalar(fd, f));
  std::printf("\n  %-18s %12s %14s %14s %14s %14s %12s\n", "metric", "count", "min", "max", "mean", "stddev",
              "worst cell");
  for (const char* m : metrics)
  {
    vtkDataArray* st = fd->GetArray((std::string(m) + "Statistics").c_str());
    if (!st)
      continue;
    std::printf("  %-18s %12.0f %14.6g %14.6g %14.6g %14.6g %12.0f\n", m, st->GetComponent(0, 0),
                st->GetComponent(0, 1), st->GetComponent(0, 2), st->GetComponent(0, 3), st->GetComponent(0, 4),
                st->GetComponent(0, 5));
  }
  return 0;
}
