// volgrid refine MESH OUT --size-array NAME: adaptivity (paper section 4). An existing tet mesh and
// a target edge length per point (e.g. from a solver's error estimate) -> field points where the target
// is smaller than the current spacing, then optimisation. The boundary (and the faces between regions of
// the cell array Region, if present) is kept exactly. MESH and OUT may also be solver meshes (.exo with the
// target as a nodal variable, .msh .su2 .mesh .cgns .node, an OpenFOAM case): the patches are kept.
#include "CliSupport.h"
#include "Commands.h"
#include "FlagParser.h"
#include "MeshExport.h"
#include "OutputPaths.h"
#include "PointFiles.h"
#include "SizeLimit.h"
#include "SurfaceFile.h"
#include "VolGridConversion.h"
#include "VolGridSolverMeshFromGrid.h"
#include "XmlDataFiles.h"

#include "MeshImprovement.h"
#include "OptionValues.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace option = volgrid::option;
const char* kHeader =
  "usage: volgrid refine MESH OUT --size-array NAME [--alpha A] [--beta B] [--gradation G]\n"
  "                      [--no-optimize] [--target-angle DEG] [--passes N] [--json] [--format NAME]\n"
  "  MESH: .vtu/.vtk, or a solver mesh (.exo/.e with NAME a nodal variable, its last time step; .msh .su2\n"
  "  .mesh .cgns .node or an OpenFOAM case carry no point fields). OUT: .vtu or any solver format of\n"
  "  `volgrid mesh` (--format NAME where the extension does not say it); the boundary patches of MESH\n"
  "  (PatchNames and BoundaryFacePatch of a VolGrid .vtu, or the solver file's) are kept by name.\n"
  "  Refines a tetrahedral mesh where the point array NAME (target edge length per point, e.g. from a\n"
  "  solver's error estimate) is smaller than the current spacing (paper section 4). Points keep their\n"
  "  ids, new points follow; the boundary faces and the faces between Region values are kept exactly.\n"
  "  Non-finite or non-positive targets mean 'no target here'. Exit 1 on bad input.\n"
  "  --gradation G        > 1 grades the targets over the mesh edges first (default 0: no grading)\n";
const char* kFooter = "  OUT.vtu is replaced atomically, only when it was written whole.\n";

struct Arguments
{
  std::string mesh, out; // MESH and OUT
  std::string arrayName;
  bool json = false;
  long long maxTets = 0;
  volgrid::RefineOptions options; // alpha, beta, target angle, passes: OptionTable.h's defaults, as for meshing
};

// 2 (after the message) when the arguments are bad, 0 after --help, -1 to go on refining.
int parseArguments(int argc, char** argv, Arguments& args)
{
  volgrid::RefineOptions& options = args.options;
  options.optimization = volgrid::ImprovementOptions().optimization;
  volgrid::cli::FlagParser p("refine", kHeader, kFooter);
  p.add("--json", args.json, true);
  p.add("--no-optimize", options.optimize, false);
  p.add("--size-array", args.arrayName);
  p.add("--gradation", options.gradation).accept = [&p, &options](const char* v)
  { return options.gradation >= 1 || p.fail(std::string("--gradation is out of range: ") + v); };
  const auto set = [&options](const volgrid::OptionSpec& spec, double x) { volgrid::setOption(options, spec, x); };
  p.add(option::alpha, "A", set);
  p.add(option::beta, "B", set);
  p.add(option::targetAngle, "DEG", set);
  p.add(option::passes, "N", set);
  p.add("--max-tets", args.maxTets,
        "  --max-tets N    refuse before any work when the result is estimated to exceed N tets (default: what\n"
        "                  the available memory holds)\n")
    .accept = [&args](const char* v) { return volgrid::cli::parseMaxTets("refine", v, args.maxTets); };
  std::vector<std::string> positional;
  if (const int code = p.scan(argc, argv, positional); code >= 0)
    return code;
  if (positional.size() != 2 || args.arrayName.empty())
  {
    p.fail("expected MESH OUT --size-array NAME", true);
    return 2;
  }
  args.mesh = positional[0];
  args.out = positional[1];
  return -1;
}

// The boundary faces (faces of one tet only) as sorted triples.
std::set<std::array<int32_t, 3>> boundaryFaces(const volgrid::TetMesh& mesh)
{
  std::set<std::array<int32_t, 3>> faces;
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        if (mesh.neighbor(t, i) < 0)
        {
          int32_t f[3];
          mesh.faceVertices(t, i, f);
          std::sort(f, f + 3);
          faces.insert({ f[0], f[1], f[2] });
        }
    });
  return faces;
}
// The smallest valid target, as text ("none" when there is none).
std::string smallestTarget(const std::vector<double>& target)
{
  double smallest = std::numeric_limits<double>::infinity();
  for (const double t : target)
    if (t > 0 && std::isfinite(t))
      smallest = std::min(smallest, t);
  if (!std::isfinite(smallest))
    return "none";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", smallest);
  return buffer;
}
// The input's boundary triangles (unchanged by refinement, same point ids) with their patches and names
// on the refined grid: BoundaryFacePatch, PatchNames and RegionNames.
void attachPatches(const volgrid::SolverMesh& patches, vtkUnstructuredGrid* out)
{
  std::vector<int32_t> tets;
  tets.reserve(static_cast<size_t>(4 * out->GetNumberOfCells()));
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    out->GetCellPoints(c, npts, ids);
    for (int k = 0; k < 4; ++k)
      tets.push_back(static_cast<int32_t>(ids[k]));
  }
  out->GetCellData()->AddArray(VolGridBoundaryFacePatch(tets, patches.triangles, patches.trianglePatch));
  VolGridSetLabelNames(out, "PatchNames", patches.trianglePatch, patches.patchNames, "patch");
  std::vector<int32_t> regions;
  for (const auto& entry : patches.regionNames)
    regions.push_back(entry.first);
  if (!regions.empty())
    VolGridSetLabelNames(out, "RegionNames", regions, patches.regionNames, "region");
}
// MESH's points and tets as flat arrays; false (the message printed) when a cell is not a tetrahedron.
bool tetsOfGrid(vtkUnstructuredGrid* grid, std::vector<double>& points, std::vector<int32_t>& tets)
{
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  points.resize(3 * static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
    grid->GetPoint(i, points.data() + 3 * i);
  tets.reserve(4 * static_cast<size_t>(nc));
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
    {
      std::fprintf(stderr, "volgrid refine: cell %lld is not a tetrahedron (only tet meshes are refined)\n",
                   static_cast<long long>(c));
      return false;
    }
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, npts, ids);
    for (int k = 0; k < 4; ++k)
      tets.push_back(static_cast<int32_t>(ids[k]));
  }
  return true;
}

// The refined mesh as a grid: every input point keeps its id (point data copied), new points follow
// (null values); cell array Region from `regions` (per tet of the mesh).
void fillRefinedGrid(const volgrid::TetMesh& mesh, vtkUnstructuredGrid* input, const std::vector<int32_t>& regions,
                     vtkUnstructuredGrid* out)
{
  std::vector<int32_t> kept(static_cast<size_t>(mesh.numVertices()));
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    kept[v] = v;
  VolGridFillUnstructuredGrid(mesh, kept, out);
  vtkPointData* outPD = out->GetPointData();
  outPD->CopyAllocate(input->GetPointData(), mesh.numVertices());
  for (vtkIdType v = 0; v < mesh.numVertices(); ++v)
  {
    if (v < input->GetNumberOfPoints())
      outPD->CopyData(input->GetPointData(), v, v);
    else
      outPD->NullData(v);
  }
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->SetNumberOfValues(mesh.numFiniteTets());
  vtkIdType cell = 0;
  mesh.forEachFiniteTet([&](int32_t t) { region->SetValue(cell++, regions[t]); });
  out->GetCellData()->AddArray(region);
}
} // namespace

int runRefineCommand(int argc, char** argv)
{
  volgrid::cli::ExportRequest exportRequest; // --format, --patch-type (MeshExport.h)
  if (!volgrid::cli::takeExportOptions("refine", argc, argv, exportRequest))
    return 2;
  Arguments args;
  if (const int code = parseArguments(argc, argv, args); code >= 0)
    return code;

  volgrid::MeshFormat format = volgrid::MeshFormat::Unknown;
  bool vtkOutput = true;
  if (!volgrid::cli::chooseFormat("refine", args.out, exportRequest, format, vtkOutput))
    return 2;
  // An OpenFOAM case is a directory, checked by its writer.
  if (format != volgrid::MeshFormat::OpenFOAM)
    if (const int code = volgrid::cli::checkOutputPath(
          "refine", "OUT", args.out, { vtkOutput ? std::string("vtu") : volgrid::surfaceFileExtension(args.out) },
          { args.mesh }))
      return code;
  vtkSmartPointer<vtkDataSet> data = volgrid::cli::readDataSet(args.mesh);
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "volgrid refine: '%s' is not an unstructured grid with cells\n", args.mesh.c_str());
    return 1;
  }
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  std::vector<double> points;
  std::vector<int32_t> tets;
  if (!tetsOfGrid(grid, points, tets))
    return 1;
  // The boundary patches, when MESH has them (kept exactly, so they carry over to the output).
  volgrid::SolverMesh patches;
  std::string patchError;
  const bool hasPatches = VolGridSolverMeshFromGrid(grid, patches, patchError);
  if (!hasPatches && !vtkOutput)
  {
    std::fprintf(stderr, "volgrid refine: cannot write a solver mesh from '%s': %s\n", args.mesh.c_str(),
                 patchError.c_str());
    return 1;
  }
  vtkDataArray* sizeArray = grid->GetPointData()->GetArray(args.arrayName.c_str());
  if (!sizeArray)
  {
    std::fprintf(stderr, "volgrid refine: '%s' has no point array '%s'\n", args.mesh.c_str(), args.arrayName.c_str());
    return 1;
  }
  std::vector<double> target(static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
    target[i] = sizeArray->GetComponent(i, 0);
  vtkDataArray* regionArray = grid->GetCellData()->GetArray("Region");
  std::vector<int32_t> regions(static_cast<size_t>(nc), 0);
  if (regionArray)
    for (vtkIdType c = 0; c < nc; ++c)
      regions[c] = static_cast<int32_t>(regionArray->GetComponent(c, 0));

  const volgrid::SizeEstimate estimate =
    volgrid::estimateRefineSize(points, tets, target, args.options.fieldPointOptions.alpha);
  if (volgrid::cli::refuseIfTooLarge("refine", estimate, args.maxTets,
                                     "the target sizes of point array '" + args.arrayName + "' (smallest " +
                                       smallestTarget(target) + ")"))
    return 1;

  volgrid::TetMesh mesh;
  volgrid::Status s = volgrid::tetMeshFromTets(points, tets, mesh);
  if (!s.ok())
  {
    std::fprintf(stderr, "volgrid refine: %s: %s\n", args.mesh.c_str(), s.message.c_str());
    return 1;
  }
  const auto facesBefore = boundaryFaces(mesh);
  volgrid::RefineReport report;
  const volgrid::cli::Stopwatch watch;
  s = volgrid::refineTetMesh(mesh, target, &regions, args.options, nullptr, &report);
  const double seconds = watch.seconds();
  if (!s.ok())
  {
    std::fprintf(stderr, "volgrid refine: %s\n", s.message.c_str());
    return 1;
  }
  const bool boundaryIdentical = boundaryFaces(mesh) == facesBefore;

  vtkNew<vtkUnstructuredGrid> out;
  fillRefinedGrid(mesh, grid, regions, out);
  if (hasPatches && boundaryIdentical)
    attachPatches(patches, out);
  std::string writeError;
  if (!boundaryIdentical)
    std::fprintf(stderr, "volgrid refine: the boundary changed (a bug: please report it); '%s' not written\n",
                 args.out.c_str());
  else if (!vtkOutput)
  {
    volgrid::SolverMesh refined;
    if (!VolGridSolverMeshFromGrid(out, refined, writeError) ||
        !volgrid::cli::writeSolverOutput("refine", args.out, format, std::move(refined), exportRequest, args.json))
    {
      if (!writeError.empty())
        std::fprintf(stderr, "volgrid refine: %s\n", writeError.c_str());
      return 1;
    }
  }
  else if (!volgrid::cli::writeXmlDataSet(args.out, out, writeError))
  {
    std::fprintf(stderr, "volgrid refine: %s\n", writeError.c_str());
    return 1;
  }
  if (args.json)
    std::printf("{\"input\": %s, \"points_before\": %lld, \"tets_before\": %lld, \"points\": %d, \"tets\": %d, "
                "\"inserted\": %lld, \"passes\": %d, \"boundary_identical\": %s, \"min_dihedral\": %s, "
                "\"max_dihedral\": %s, \"share_below_10\": %s, \"seconds\": %.6f}\n",
                volgrid::cli::jsonString(args.mesh).c_str(), static_cast<long long>(np), static_cast<long long>(nc),
                mesh.numVertices(), mesh.numFiniteTets(), static_cast<long long>(report.inserted), report.passes,
                boundaryIdentical ? "true" : "false",
                volgrid::cli::jsonNumber(report.after.minDihedral, "%.4f").c_str(),
                volgrid::cli::jsonNumber(report.after.maxDihedral, "%.4f").c_str(),
                volgrid::cli::jsonNumber(report.after.shareBelow10(), "%.6g").c_str(), seconds);
  else
    std::printf("%s: %lld points, %lld tets -> %d points, %d tets (%lld inserted) in %.3f s; dihedral angles "
                "%.2f..%.2f deg; boundary %s\n",
                args.mesh.c_str(), static_cast<long long>(np), static_cast<long long>(nc), mesh.numVertices(),
                mesh.numFiniteTets(), static_cast<long long>(report.inserted), seconds, report.after.minDihedral,
                report.after.maxDihedral, boundaryIdentical ? "identical" : "CHANGED");
  return boundaryIdentical ? 0 : 1;
}
