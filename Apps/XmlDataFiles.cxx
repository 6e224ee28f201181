#include "XmlDataFiles.h"

#include "vtkVolGridXMLPolyDataReader.h"
#include "vtkVolGridXMLUnstructuredGridReader.h"

#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm>
#include <cctype>

namespace volgrid
{
namespace cli
{
namespace
{
std::string lowerExtension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

template <class Reader>
vtkSmartPointer<vtkDataSet> readWith(const std::string& path)
{
  vtkNew<Reader> reader;
  if (!reader->CanReadFile(path.c_str()))
    return nullptr;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0)
    return nullptr;
  return reader->GetOutput();
}

// Inline binary: every DataArray carries its own base64 text, so no <AppendedData> block exists.
template <class Writer>
bool writeWith(const std::string& path, vtkDataSet* data)
{
  vtkNew<Writer> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  return writer->Write() == 1;
}
} // namespace

bool isXmlDataExtension(const std::string& ext)
{
  return ext == "vtu" || ext == "vtp";
}

vtkSmartPointer<vtkDataSet> readXmlDataSet(const std::string& path, std::string& error)
{
  const std::string ext = lowerExtension(path);
  vtkSmartPointer<vtkDataSet> data;
  if (ext == "vtu")
    data = readWith<vtkVolGridXMLUnstructuredGridReader>(path);
  else if (ext == "vtp")
    data = readWith<vtkVolGridXMLPolyDataReader>(path);
  else
  {
    error = path + ": not a VTK XML unstructured grid (.vtu) or poly data (.vtp) file";
    return nullptr;
  }
  if (!data)
    error = path + ": not a readable VTK XML " + (ext == "vtu" ? "unstructured grid" : "poly data") + " file";
  return data;
}

bool writeXmlDataSet(const std::string& path, vtkDataSet* data, std::string& error)
{
  const std::string ext = lowerExtension(path);
  bool written = false;
  if (ext == "vtu" && vtkUnstructuredGrid::SafeDownCast(data))
    written = writeWith<vtkXMLUnstructuredGridWriter>(path, data);
  else if (ext == "vtp" && vtkPolyData::SafeDownCast(data))
    written = writeWith<vtkXMLPolyDataWriter>(path, data);
  else
  {
    error = path + ": a " + (vtkPolyData::SafeDownCast(data) ? "surface is written as .vtp" : "volume mesh is written as .vtu");
    return false;
  }
  if (!written)
    error = "cannot write '" + path + "'";
  return written;
}
} // namespace cli
} // namespace volgrid
