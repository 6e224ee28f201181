#include "PointFiles.h"

#include "VolGridConversion.h"
#include "XmlDataFiles.h"

#include "MeshReader.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace volgrid
{
namespace cli
{

namespace
{
bool endsWith(const std::string& s, const std::string& e)
{
  return s.size() >= e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
}
} // namespace

vtkSmartPointer<vtkDataSet> readDataSet(const std::string& path)
{
  vtkSmartPointer<vtkDataObject> data;
  if (volgrid::solverMeshReaderSupports(path))
  {
    volgrid::SolverMesh mesh;
    const volgrid::Status s = volgrid::readSolverMesh(path, mesh);
    if (!s.ok())
    {
      std::fprintf(stderr, "volgrid: %s\n", s.message.c_str());
      return nullptr;
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    VolGridFillFromSolverMesh(mesh, grid, nullptr);
    return grid;
  }
  if (endsWith(path, ".vtk"))
  {
    vtkNew<vtkGenericDataObjectReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    data = reader->GetOutput();
  }
  else
  {
    std::string ignored; // the caller names the file in its own message
    return volgrid::cli::readXmlDataSet(path, ignored);
  }
  return vtkDataSet::SafeDownCast(data);
}

bool readPointsWithArray(const char* command, const std::string& path, const std::string& arrayName, bool needArray,
                         std::vector<double>& xyz, std::vector<double>& values)
{
  xyz.clear();
  values.clear();
  if (endsWith(path, ".txt") || endsWith(path, ".xyz") || endsWith(path, ".csv"))
  {
    std::ifstream in(path);
    if (!in)
    {
      std::fprintf(stderr, "volgrid %s: cannot read '%s'\n", command, path.c_str());
      return false;
    }
    std::string line;
    size_t lineNo = 0;
    bool anyValue = false, allValues = true;
    while (std::getline(in, line))
    {
      ++lineNo;
      std::replace(line.begin(), line.end(), ',', ' ');
      if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t\r")] == '#')
        continue;
      std::istringstream ls(line);
      double p[4];
      int n = 0;
      while (n < 4 && ls >> p[n])
        ++n;
      if (n < 3 || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        std::fprintf(stderr, "volgrid %s: %s line %zu: expected 'x y z [value]'\n", command, path.c_str(), lineNo);
        return false;
      }
      xyz.insert(xyz.end(), p, p + 3);
      values.push_back(n == 4 ? p[3] : 0.0);
      anyValue |= n == 4;
      allValues &= n == 4;
    }
    if (needArray && !allValues)
    {
      std::fprintf(stderr, "volgrid %s: %s: every line needs a fourth column (the size)\n", command, path.c_str());
      return false;
    }
    if (!anyValue)
      values.clear();
    return true;
  }
  vtkSmartPointer<vtkDataSet> data = readDataSet(path);
  if (!data || data->GetNumberOfPoints() == 0)
  {
    std::fprintf(stderr, "volgrid %s: cannot read points from '%s'\n", command, path.c_str());
    return false;
  }
  const vtkIdType n = data->GetNumberOfPoints();
  xyz.resize(3 * static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
    data->GetPoint(i, xyz.data() + 3 * i);
  vtkDataArray* array = arrayName.empty() ? nullptr : data->GetPointData()->GetArray(arrayName.c_str());
  if (!array && needArray)
  {
    std::fprintf(stderr, "volgrid %s: '%s' has no point array '%s'\n", command, path.c_str(), arrayName.c_str());
    return false;
  }
  if (array)
  {
    values.resize(static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      values[i] = array->GetComponent(i, 0);
  }
  return true;
}

} // namespace cli
} // namespace volgrid
