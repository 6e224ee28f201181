// volgrid mesh --layers: options, the layered mesh, its VTK and solver outputs and the report.
#include "MeshLayers.h"

#include "CliSupport.h"
#include "XmlDataFiles.h"

#include "VolGridLayeredConversion.h"

#include "LayeredMesher.h"
#include "Predicates.h"

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridWriter.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace volgrid
{
namespace cli
{
const std::string kLayerUsage =
  std::string("Boundary layers (prisms on the wall patches, conformal with the tets):\n") +
  optionUsage(option::layers, "N") + optionUsage(option::firstHeight, "H") +
  "  --y-plus Y --reynolds RE --reference-length L\n"
  "                       instead of --first-height: the height of y+ = Y on a flat plate of length L at\n"
  "                       Reynolds number RE (Cf = 0.026 / RE^(1/7))\n" +
  optionUsage(option::growth, "R") + optionUsage(option::layerThickness, "T") +
  "  --layer-patches A,B  layered patches by name or id (default: named patches whose OpenFOAM type is wall,\n"
  "                       unnamed ones that neither span the domain's box nor enclose another surface)\n"
  "  --split-prisms       each prism as 3 tets, each pyramid as 2 (for tet-only solvers; needed for TetGen,\n"
  "                       the one format without prisms and pyramids)\n"
  "  --keep-wall-triangles  keep the wall's triangles even around edges whose prism side faces checkMesh\n"
  "                       would find highly skewed (by default those triangles are split first)\n";

int parseLayerOption(int argc, char** argv, int& i, LayerOptions& options)
{
  const std::string a = argv[i];
  if (a == "--split-prisms")
  {
    options.splitPrisms = true;
    return 1;
  }
  if (a == "--keep-wall-triangles")
  {
    options.keepWallTriangles = true;
    return 1;
  }
  if (a != "--layers" && a != "--first-height" && a != "--growth" && a != "--layer-patches" && a != "--y-plus" &&
      a != "--reynolds" && a != "--reference-length" && a != "--layer-thickness")
    return 0;
  if (a == "--growth" || a == "--layer-thickness")
  {
    // Two of first height, growth and thickness decide the third: all three would contradict each other.
    bool first = false, growth = false, thickness = false;
    for (int k = 1; k < argc; ++k)
    {
      const std::string b = argv[k];
      first = first || b == "--first-height" || b == "--y-plus";
      growth = growth || b == "--growth";
      thickness = thickness || b == "--layer-thickness";
    }
    if (first && growth && thickness)
    {
      std::fprintf(stderr,
                   "volgrid mesh: give two of --first-height (or --y-plus), --growth and --layer-thickness; "
                   "the third follows from them\n");
      return -1;
    }
  }
  if (i + 1 >= argc)
  {
    volgrid::cli::reportMissingValue("mesh", a);
    return -1;
  }
  const char* v = argv[++i];
  if (a == "--layer-patches")
  {
    addLayerPatches(v, options);
    return 1;
  }
  double x = 0;
  const OptionSpec* spec = nullptr; // layers, first-height, growth: the table's ranges and messages
  for (const OptionSpec* row : option::layerTable)
    spec = a.substr(2) == row->name ? row : spec;
  if (spec ? !parseOption("mesh", *spec, v, x) : !parseDouble("mesh", a.c_str(), v, x))
    return -1;
  if (a == "--layers")
  {
    options.layers = static_cast<int>(x);
    return 1;
  }
  (a == "--growth"               ? options.growth
     : a == "--y-plus"           ? options.yPlus
     : a == "--reynolds"         ? options.reynolds
     : a == "--reference-length" ? options.referenceLength
     : a == "--layer-thickness"  ? options.thickness
                                 : options.firstHeight) = x;
  return 1;
}

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> toVtk(const LayeredMeshResult& r)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  VolGridFillFromLayeredResult(r, grid, nullptr);
  return grid;
}

// Cells with a non-positive volume, counted exactly (orient3d; every decomposition of a prism).
int64_t invertedCells(const LayeredMeshResult& r)
{
  const auto at = [&](int32_t id) { return r.points.data() + 3 * size_t(id); };
  int64_t bad = 0;
  for (size_t t = 0; t < r.tets.size(); t += 4)
    bad += predicates::orient3d(at(r.tets[t]), at(r.tets[t + 1]), at(r.tets[t + 2]), at(r.tets[t + 3])) > 0 ? 0 : 1;
  for (size_t p = 0; p < r.pyramids.size(); p += 5)
  {
    int32_t split[8];
    splitPyramid(r.pyramids.data() + p, split);
    for (int t = 0; t < 8; t += 4)
      bad += predicates::orient3d(at(split[t]), at(split[t + 1]), at(split[t + 2]), at(split[t + 3])) > 0 ? 0 : 1;
  }
  for (size_t w = 0; w < r.wedges.size(); w += 6)
    bad += prismIsValid(at(r.wedges[w]), at(r.wedges[w + 1]), at(r.wedges[w + 2]), at(r.wedges[w + 3]),
                        at(r.wedges[w + 4]), at(r.wedges[w + 5]))
      ? 0
      : 1;
  return bad;
}

bool writeVtk(const std::string& out, vtkUnstructuredGrid* grid)
{
  if (out.size() > 4 && out.compare(out.size() - 4, 4, ".vtk") == 0)
  {
    vtkNew<vtkUnstructuredGridWriter> writer;
    writer->SetFileName(out.c_str());
    writer->SetInputData(grid);
    writer->SetFileTypeToBinary();
    if (writer->Write() == 1)
      return true;
    std::fprintf(stderr, "volgrid mesh: cannot write '%s'\n", out.c_str());
    return false;
  }
  std::string error;
  if (writeXmlDataSet(out, grid, error))
    return true;
  std::fprintf(stderr, "volgrid mesh: %s\n", error.c_str());
  return false;
}
} // namespace

int runLayeredMesh(const SurfaceMesh& surface, const std::string& surfaceName, const std::string& out,
                   MeshFormat format, bool vtkOutput, const ExportRequest& request, const MesherOptions& options,
                   const LayerOptions& layers, bool json)
{
  if (!vtkOutput && !writesPrisms(format) && !layers.splitPrisms)
  {
    std::fprintf(stderr, "volgrid mesh: prism layers are not written to %s; add --split-prisms to write them as tets\n",
                 meshFormatName(format));
    return 2;
  }
  if (!request.patches.empty())
  {
    std::fprintf(stderr, "volgrid mesh: --patch is not supported together with --layers yet\n");
    return 2;
  }
  const Status valid = validateLayerOptions(layers);
  if (!valid.ok())
  {
    std::fprintf(stderr, "volgrid mesh: %s\n", valid.message.c_str());
    return 2;
  }
  LayeredMeshResult r;
  const Stopwatch watch;
  const Status status = meshSurfaceWithLayers(surface, options, layers, r);
  const double seconds = watch.seconds();
  if (!status.ok())
  {
    std::fprintf(stderr, "volgrid mesh: %s: %s\n", surfaceName.c_str(), status.message.c_str());
    return 1;
  }
  for (const std::string& warning : r.warnings)
    std::fprintf(stderr, "volgrid mesh: warning: %s\n", warning.c_str());
  const int64_t inverted = invertedCells(r);
  if (inverted > 0)
  {
    std::fprintf(stderr, "volgrid mesh: %lld inverted cells: a bug, nothing written\n", (long long)inverted);
    return 1;
  }
  if (vtkOutput && !writeVtk(out, toVtk(r).Get()))
    return 1;
  if (!vtkOutput)
  {
    if (!writeSolverOutput("mesh", out, format, layeredSolverMesh(r), request, json))
      return 1;
  }
  const LayerStatistics& l = r.layerStats;
  const long long wedges = (long long)(r.wedges.size() / 6), tets = (long long)(r.tets.size() / 4);
  if (json)
    std::printf(
      "{\"input\": %s, \"points\": %lld, \"wedges\": %lld, \"pyramids\": %lld, \"tets\": %lld, \"layers\": %d, "
      "\"first_height\": %.6g, \"growth\": %.9g, \"total_thickness\": %.9g, "
      "\"layered_faces\": %lld, \"full_faces\": %lld, \"coverage\": %.6f, \"all_layers\": %.6f, "
      "\"thinned_columns\": %lld, "
      "\"thinned_inversion\": %lld, \"thinned_collision\": %lld, \"thinned_neighbour\": %lld, \"collapsed_columns\": "
      "%lld, "
      "\"min_column_scale\": %.6g, \"inverted_cells\": %lld, \"interface_faces_shared\": %lld, "
      "\"wall_skew_edges_input\": %lld, \"wall_split_edges\": %lld, "
      "\"wall_skew_edges\": %lld, \"wall_skewness_max\": %.6g, \"wall_nonortho_edges\": %lld, "
      "\"wall_nonortho_max\": %.6g, \"transition_faces\": %lld, \"transition_ratio_median\": %.6g, "
      "\"transition_ratio_p90\": %.6g, \"transition_ratio_max\": %.6g, \"seconds_layers\": %.6f, \"seconds\": %.6f}\n",
      jsonString(surfaceName).c_str(), (long long)(r.points.size() / 3), wedges, (long long)(r.pyramids.size() / 5),
      tets, layers.layers, layers.resolved().firstHeight, layers.resolved().growth, layers.resolved().totalThickness(),
      (long long)l.layeredTriangles, (long long)l.fullTriangles, l.coverage(), l.allLayersShare(),
      (long long)l.thinnedColumns, (long long)l.thinnedBy[1], (long long)l.thinnedBy[2], (long long)l.thinnedBy[3],
      (long long)l.thinnedBy[4], l.minScale, (long long)inverted, (long long)r.interfaceOnTets,
      (long long)l.wallRefinement.skewedEdgesBefore, (long long)l.wallRefinement.splitEdges,
      (long long)l.wallFaceQuality.skewness.edgesOverLimit, l.wallFaceQuality.skewness.worst,
      (long long)l.wallFaceQuality.nonOrthogonality.edgesOverLimit, l.wallFaceQuality.nonOrthogonality.worst,
      (long long)r.transition.faces, r.transition.medianRatio, r.transition.p90Ratio, r.transition.maxRatio, l.seconds,
      seconds);
  else
    std::printf(
      "%s: %d layers on %lld faces (full height on %.2f%%, every layer on %.2f%%, %lld thinned and %lld "
      "collapsed columns) -> %lld wedges, %lld pyramids, %lld tets on %lld points, %lld inverted, in %.3f s\n",
      surfaceName.c_str(), layers.layers, (long long)l.layeredTriangles, 100.0 * l.coverage(),
      100.0 * l.allLayersShare(), (long long)l.thinnedColumns, (long long)l.thinnedBy[4], wedges,
      (long long)(r.pyramids.size() / 5), tets, (long long)(r.points.size() / 3), (long long)inverted, seconds);
  return 0;
}

} // namespace cli
} // namespace volgrid
