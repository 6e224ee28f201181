// Point clouds and data sets from the files the CLI takes: `volgrid mesh --sizing/--cluster` and
// `volgrid refine`'s mesh.
#pragma once

#include "vtkDataSet.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace volgrid
{
namespace cli
{

// A solver mesh (Core/IO/MeshReader.h: .exo .cgns .msh ...; its point fields as point arrays), a .vtk
// (legacy) or VTK XML data set, or nullptr.
vtkSmartPointer<vtkDataSet> readDataSet(const std::string& path);

// Points (x,y,z each) and one value per point: text files (.txt .xyz .csv: 'x y z [value]' lines) or any
// data set with the point array `arrayName` (needArray: the values are required). Messages go to stderr.
bool readPointsWithArray(const char* command, const std::string& path, const std::string& arrayName, bool needArray,
                         std::vector<double>& xyz, std::vector<double>& values);

} // namespace cli
} // namespace volgrid
