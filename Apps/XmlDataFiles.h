// VTK XML files (.vtu, .vtp) as the CLI reads and writes them.
//
// Written: inline binary (base64, zlib-compressed), never raw appended data, so that VTK 9.2 readers on
// any expat (Debian 12's current libexpat1 included) open them. Read: through VolGrid's XML readers,
// which also read raw appended files written by other tools (vtkVolGridXMLPolyDataReader.h).
#ifndef volgrid_cli_XmlDataFiles_h
#define volgrid_cli_XmlDataFiles_h

#include "vtkSmartPointer.h"

#include <string>

class vtkDataSet;

namespace volgrid
{
namespace cli
{
// True for the extensions these functions handle ("vtu", "vtp"; lower case, no dot).
bool isXmlDataExtension(const std::string& ext);

// Reads a .vtu or .vtp file; nullptr with `error` set when it cannot be read.
vtkSmartPointer<vtkDataSet> readXmlDataSet(const std::string& path, std::string& error);

// Writes a vtkUnstructuredGrid to .vtu or a vtkPolyData to .vtp; false with `error` set on failure.
bool writeXmlDataSet(const std::string& path, vtkDataSet* data, std::string& error);
} // namespace cli
} // namespace volgrid

#endif
